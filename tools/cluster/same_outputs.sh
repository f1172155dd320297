#!/usr/bin/env bash
# Whether two `curvbench run` output folders hold the same results: the same files (the case
# store .cache/ aside), byte for byte, except what holds measured seconds: timings/ (the same
# number of rows is enough), recommendations.csv (the columns before best_seconds; the cheapest
# case within 2x is chosen by time) and REPORT.md's section "Choosing an estimator and a radius"
# (its last, with those times: the same number of lines). Prints each difference; exit 0 if
# none, 1 otherwise.
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
  elif [[ $f == REPORT.md ]]; then
    choosing='^## Choosing an estimator and a radius$'
    if ! cmp -s <(sed "/$choosing/,\$d" "$want/$f") <(sed "/$choosing/,\$d" "$got/$f") ||
      [[ $(wc -l < "$want/$f") != $(wc -l < "$got/$f") ]]; then
      echo "differs (before its section Choosing an estimator, or in line count): $f"
      bad=1
    fi
  elif ! cmp -s "$want/$f" "$got/$f"; then
    echo "differs: $f"
    bad=1
  fi
done < <(LC_ALL=C comm -12 <(files "$want") <(files "$got"))
if [[ $bad -ne 0 ]]; then
  exit 1
fi
echo "same outputs: $n files ($got = $want; timings/, recommendations.csv and REPORT.md's
choice of estimator by their parts without times)"
