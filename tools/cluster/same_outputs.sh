#!/usr/bin/env bash
# Whether two `curvbench run` output folders hold the same results: the same files (the case
# store .cache/ aside), byte for byte, except what holds measured seconds:
#   timings/                    the same number of rows
#   recommendations.csv         the columns before best_seconds (the cheapest case within 2x is
#                               chosen by time)
#   leaderboard.csv             every column but us_per_vertex
#   report/sweeps.md            byte for byte before its section "Choosing an estimator and a
#                               radius" (with those times), and the same number of lines
#   report/field-studies.md     the same headings (its times per vertex, the cheapest estimator
#                               to reach a target and the targets themselves come from seconds)
#   site/*.html                 the same numbers of sections, charts and tables (the pages render
#                               the CSVs compared above, times included; site/assets/ byte for
#                               byte)
# Prints each difference; exit 0 if none, 1 otherwise.
# Used by tests/cli/test_cli_shard.cpp (shard processes) and tools/cluster/test_slurm.sh (Slurm).
#
#   bash tools/cluster/same_outputs.sh WANT GOT
set -euo pipefail
if [[ $# -ne 2 || ! -d "$1" || ! -d "$2" ]]; then
  sed -n '2,10p' "$0" >&2
  exit 2
fi
want=$1 got=$2
files() { (cd "$1" && find . -path ./.cache -prune -o -type f -print | sed 's|^\./||' | LC_ALL=C sort); }
bad=0
while IFS= read -r f; do echo "missing from $got: $f"; bad=1; done \
  < <(LC_ALL=C comm -23 <(files "$want") <(files "$got"))
while IFS= read -r f; do echo "not in $want: $f"; bad=1; done \
  < <(LC_ALL=C comm -13 <(files "$want") <(files "$got"))
n=0
while IFS= read -r f; do
  n=$((n + 1))
  if [[ $f == timings/* ]]; then
    if [[ $(wc -l < "$want/$f") != $(wc -l < "$got/$f") ]]; then
      echo "differs (row count): $f"
      bad=1
    fi
  elif [[ $f == recommendations.csv ]]; then
    if ! cmp -s <(cut -d, -f1-17 "$want/$f") <(cut -d, -f1-17 "$got/$f"); then
      echo "differs (before best_seconds): $f"
      bad=1
    fi
  elif [[ $f == leaderboard.csv ]]; then
    if ! cmp -s <(cut -d, -f1-7,9- "$want/$f") <(cut -d, -f1-7,9- "$got/$f"); then
      echo "differs (but for us_per_vertex): $f"
      bad=1
    fi
  elif [[ $f == report/sweeps.md ]]; then
    choosing='^## Choosing an estimator and a radius$'
    if ! cmp -s <(sed "/$choosing/,\$d" "$want/$f") <(sed "/$choosing/,\$d" "$got/$f") ||
      [[ $(wc -l < "$want/$f") != $(wc -l < "$got/$f") ]]; then
      echo "differs (before its section Choosing an estimator, or in line count): $f"
      bad=1
    fi
  elif [[ $f == report/field-studies.md ]]; then
    if ! cmp -s <(grep '^#' "$want/$f") <(grep '^#' "$got/$f"); then
      echo "differs (in its headings): $f"
      bad=1
    fi
  elif [[ $f == site/*.html ]]; then
    for tag in '<section' '<canvas' '<table'; do
      if [[ $(grep -o "$tag" "$want/$f" | wc -l) != $(grep -o "$tag" "$got/$f" | wc -l) ]]; then
        echo "differs (number of $tag): $f"
        bad=1
      fi
    done
  elif ! cmp -s "$want/$f" "$got/$f"; then
    echo "differs: $f"
    bad=1
  fi
done < <(LC_ALL=C comm -12 <(files "$want") <(files "$got"))
if [[ $bad -ne 0 ]]; then
  exit 1
fi
echo "same outputs: $n files ($got = $want; timings/, recommendations.csv, leaderboard.csv, the
report's sweeps and field studies and the site's pages by their parts without times)"
