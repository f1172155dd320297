#!/usr/bin/env bash
# `make bench`: runs the Google Benchmark suites built from bench/ (the build is done by
# `make bench` already) and regenerates the paper's Table 5:
#   results/table5_timing.csv   mesh,level,verts,tris,method,degree,threads,seconds,tris_per_second
#   results/table5_timing.md    Table 5 layout, paper times beside ours, ratios, machine, flags
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

# Build type and flags, quoted in table5_timing.md.
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
  [[ "$name" == bench_solvers || "$name" == bench_estimators ]] && continue
  echo "== $b"
  "$b" "${ARGS[@]}" --benchmark_out="$OUT/$name.json" --benchmark_out_format=json
done

# Peak memory of the command-line tool on a mesh of 1.44 million vertices (torus-structured level
# 6), LHF-2, one thread, binary PLY in and out; appended to table5_timing.md.
if [[ -x /usr/bin/time ]]; then
  echo "== peak memory: curvbench estimate, LHF-2, torus-structured level 6 (1.44M vertices)"
  mesh="$OUT/torus-structured-6.ply"
  [[ -f "$mesh" ]] || "$BUILD/curvbench" mesh --family torus-structured --level 6 --output "$mesh" > /dev/null
  /usr/bin/time -v "$BUILD/curvbench" estimate "$mesh" --method lhf-2 --threads 1 --timing \
    --output "$OUT/estimate-6.ply" 2> "$OUT/memory.log"
  rm -f "$OUT/estimate-6.ply"
  rss_kb=$(sed -n 's/.*Maximum resident set size (kbytes): *//p' "$OUT/memory.log")
  stages=$(sed -n 's/^timing: \(.*\) \([0-9.]*\) s$/\1 \2 s/p' "$OUT/memory.log" | paste -sd ';' | sed 's/;/, /g')
  echo "peak RSS $((rss_kb / 1024)) MB ($stages)"
  md="$RESULTS/table5_timing.md"
  {
    cat "$md"
    printf '\n## Memory: `curvbench estimate` on 1.44 million vertices\n\n'
    printf 'LHF-2, one thread, the torus-structured level-6 mesh (1441792 vertices, 2883584\n'
    printf 'triangles) read from and written to binary PLY: peak resident set size %d MB\n' \
      "$((rss_kb / 1024))"
    printf '(`/usr/bin/time -v`; target: under 600 MB for a million vertices). Stages: %s.\n' "$stages"
  } > "$md.tmp.$$"
  mv "$md.tmp.$$" "$md"
else
  echo "bench: /usr/bin/time not found (Debian package 'time'): peak memory not measured" >&2
fi

echo "bench: wrote results/table5_timing.csv and results/table5_timing.md in $(($(date +%s) - start)) s"
