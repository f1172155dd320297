#!/usr/bin/env bash
# `make bench`: runs every Google Benchmark binary built from bench/ (issue 6 adds the Table 5
# suites and results/table5_timing.{csv,md}).
set -euo pipefail
BUILD=${1:-build}
shopt -s nullglob
ran=0
for b in "$BUILD"/bench_*; do
  [[ -x "$b" ]] || continue
  echo "== $b"
  "$b" --benchmark_counters_tabular=true
  ran=1
done
if [[ $ran -eq 0 ]]; then
  echo "bench: no benchmark suites are built yet (see issue 6)" >&2
  exit 1
fi
