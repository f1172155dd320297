#!/usr/bin/env bash
# `make bench`: runs the Google Benchmark suites built from bench/ (the build is done by
# `make bench` already) and regenerates the paper's Table 5:
#   results/table5_timing.csv   mesh,level,verts,tris,method,degree,threads,seconds,tris_per_second
#                               (a "# machine: ..." comment line names CPU, compiler and flags)
#   results/table5_scaling.csv  the same columns, the scaling sweep's levels 5-6
#   results/end_to_end.csv      curvbench estimate on 1.44 million vertices, per stage
# (CSV only: `curvbench report` renders Table 5 from them, harness/report/table5.h)
#   results/limits.csv          per stage of `curvbench estimate` at 1.44M vertices: measured time
#                               and the bound the hardware sets (bench/bench_limits.cpp)
#   results/neighbourhoods.csv  k-NN and ball search at 1M points, and LHF-2 with rings against
#                               LHF-2 with k-NN on the same vertices (bench/bench_neighbourhoods.cpp)
# and, after `make experiments`, rewrites REPORT.md and CLAIMS.md from its case store so that the
# timing claims are judged on this run.
# Raw Google Benchmark JSON goes to BUILD/bench/*.json. The conversion is done by the bench
# binaries themselves (--table5_rows / --table5_dir; see bench/table5.h), files written atomically.
# Usage: tools/bench.sh [BUILD_DIR]   (extra Google Benchmark flags via BENCH_ARGS)
set -euo pipefail
BUILD=${1:-build}
ROOT=$(cd "$(dirname "$0")/.." && pwd)
RESULTS="$ROOT/results"
OUT="$BUILD/bench"
# Random interleaving spreads the 9 repetitions of every benchmark over the whole run, so a burst
# of load on a shared machine hits one of them, not all, and the median stays clean.
ARGS=(--benchmark_counters_tabular=true --benchmark_enable_random_interleaving=true ${BENCH_ARGS:-})
start=$(date +%s)

for b in bench_solvers bench_estimators; do
  if [[ ! -x "$BUILD/$b" ]]; then
    echo "bench: $BUILD/$b is not built (configure with -DCURVBENCH_BUILD_BENCH=ON)" >&2
    exit 1
  fi
done
mkdir -p "$OUT" "$RESULTS"

# Build type and flags, in table5_timing.csv's machine comment.
cache_value() { sed -n "s/^$1:[A-Z]*=//p" "$BUILD/CMakeCache.txt" 2>/dev/null | head -n1; }
type=$(cache_value CMAKE_BUILD_TYPE)
type_upper=$(echo "$type" | tr '[:lower:]' '[:upper:]')
flags="$(cache_value CMAKE_CXX_FLAGS) $(cache_value "CMAKE_CXX_FLAGS_${type_upper}")"
flags=$(echo "$flags" | xargs)
build_info="CMAKE_BUILD_TYPE=${type:-unknown}, CXX flags '${flags}' (+ OpenMP; no -march=native, no -ffast-math)"

echo "== $BUILD/bench_solvers (safeguarded QR vs SVD, neighbourhood gathering)"
"$BUILD/bench_solvers" "${ARGS[@]}" --benchmark_out="$OUT/bench_solvers.json" \
  --benchmark_out_format=json --table5_rows="$OUT/solver_rows.csv"

echo "== $BUILD/bench_estimators (Table 5 methods, levels 1-4)"
"$BUILD/bench_estimators" "${ARGS[@]}" --benchmark_out="$OUT/bench_estimators.json" \
  --benchmark_out_format=json --table5_dir="$RESULTS" --table5_extra="$OUT/solver_rows.csv" \
  --build_info="$build_info"

# Any further suites (bench/*.cpp added later).
shopt -s nullglob
for b in "$BUILD"/bench_*; do
  name=$(basename "$b")
  [[ -x "$b" && -f "$b" ]] || continue
  [[ "$name" == bench_solvers || "$name" == bench_estimators || "$name" == bench_limits ||
     "$name" == bench_neighbourhoods ]] && continue
  echo "== $b"
  "$b" "${ARGS[@]}" --benchmark_out="$OUT/$name.json" --benchmark_out_format=json
done

# End to end: `curvbench estimate` on a mesh of 1.44 million vertices (torus-structured level 6),
# LHF-2, binary PLY in, CSV out, on 1 and 2 threads: the stages it prints with --timing (read,
# orientation, neighbourhoods+fit, write; estimation and writing alternate block by block, each
# stage is the sum of its own parts), the wall time and the peak resident set size
# (/usr/bin/time -v), written to results/end_to_end.csv (the report renders it with Table 5:
# harness/report/table5.h):
#   threads,read_s,orientation_s,fit_s,write_s,wall_s,peak_rss_mb
mesh="$OUT/torus-structured-6.ply"
[[ -f "$mesh" ]] || "$BUILD/curvbench" mesh --family torus-structured --level 6 --output "$mesh" > /dev/null

# The limits table: each stage's measured time against the bound this machine's hardware sets
# (plain copies of the same bytes, peak vector rate, cache and memory bandwidth; docs/performance.md).
if [[ -x "$BUILD/bench_limits" ]]; then
  echo "== $BUILD/bench_limits (stages at 1.44M vertices against the hardware's bounds)"
  "$BUILD/bench_limits" --mesh "$mesh" --method lhf-2 --threads 1 --scratch "$OUT" \
    --output "$RESULTS/limits.csv"
fi

# Neighbourhoods without connectivity: the k-d tree's build and k-NN and ball rows at 1M points,
# and LHF-2 with its rings against knn=12 on the same vertices, as a mesh and as a point set
# (docs/performance.md "Neighbourhoods of point sets"; minimum of 3 runs each).
if [[ -x "$BUILD/bench_neighbourhoods" ]]; then
  echo "== $BUILD/bench_neighbourhoods (k-NN at 1M points; LHF-2 rings vs k-NN)"
  "$BUILD/bench_neighbourhoods" --repeat 3 --output "$RESULTS/neighbourhoods.csv"
fi

if [[ -x /usr/bin/time ]]; then
  echo "== end to end: curvbench estimate, LHF-2, torus-structured level 6 (1.44M vertices), PLY -> CSV"
  csv="# tools/bench.sh end to end (git $(git -C "$ROOT" rev-parse --short HEAD 2>/dev/null || echo unknown)), generated $(date -u +%Y-%m-%dT%H:%M:%SZ)"$'\n'
  csv+="threads,read_s,orientation_s,fit_s,write_s,wall_s,peak_rss_mb"$'\n'
  for threads in 1 2; do
    log="$OUT/estimate-6-t$threads.log"
    /usr/bin/time -v "$BUILD/curvbench" estimate "$mesh" --method lhf-2 --threads "$threads" \
      --timing --output "$OUT/estimate-6.csv" 2> "$log"
    rm -f "$OUT/estimate-6.csv"
    stage() { sed -n "s/^timing: $1 \([0-9.]*\) s$/\1/p" "$log"; }
    rss_kb=$(sed -n 's/.*Maximum resident set size (kbytes): *//p' "$log")
    wall=$(sed -n 's/.*Elapsed (wall clock) time (h:mm:ss or m:ss): *//p' "$log")
    # h:mm:ss or m:ss.ss -> seconds
    wall_s=$(echo "$wall" | awk -F: '{s = 0; for (i = 1; i <= NF; ++i) s = 60 * s + $i; printf "%.2f", s}')
    read_s=$(stage read); orient_s=$(stage orientation); fit_s=$(stage 'neighbourhoods+fit')
    write_s=$(stage write)
    echo "threads $threads: read $read_s s, orientation $orient_s s, fit $fit_s s, write $write_s s, wall $wall, peak RSS $((rss_kb / 1024)) MB"
    csv+=$(printf '%d,%.3f,%.3f,%.3f,%.3f,%s,%d' "$threads" "$read_s" "$orient_s" "$fit_s" \
      "$write_s" "$wall_s" "$((rss_kb / 1024))")$'\n'
  done
  printf '%s' "$csv" > "$RESULTS/end_to_end.csv.tmp.$$"
  mv "$RESULTS/end_to_end.csv.tmp.$$" "$RESULTS/end_to_end.csv"
else
  echo "bench: /usr/bin/time not found (Debian package 'time'): end-to-end rows not measured" >&2
  rm -f "$RESULTS/end_to_end.csv"  # not this run's
fi

# The timing claims of CLAIMS.md (F1-F9) are judged on table5_timing.csv: judge them again on this
# run's table when `make experiments` has left its case store, computing nothing
# (REPORT.md and CLAIMS.md rewritten from the stored cases).
if [[ -d "$RESULTS/.cache" && -x "$BUILD/curvbench" ]]; then
  echo "== CLAIMS.md: the timing claims on this run's table5_timing.csv (run --report-only)"
  "$BUILD/curvbench" run --all --output "$RESULTS" --report-only
fi

/usr/bin/python3 "$(dirname "$0")/readme_headline.py" README.md "$RESULTS"
echo "bench: wrote results/table5_timing.csv, table5_scaling.csv, end_to_end.csv, limits.csv and neighbourhoods.csv in $(($(date +%s) - start)) s"
