#!/usr/bin/env bash
# Runs each mesh-reader fuzzer for a bounded time (make fuzz). Usage:
#   bash fuzz/run.sh BUILD_DIR SECONDS_PER_TARGET
# Environment: FUZZ_FORMATS (default "off obj ply"), FUZZ_MAX_LEN (bytes, default 4096).
#
# For each format it first replays tests/corpus/regressions/*.<format> (inputs that once found a
# bug), then fuzzes from a working corpus in BUILD_DIR/fuzz-corpus/<format> seeded with
# tests/corpus/<format> (the seeds are copied, never written; new inputs accumulate across runs;
# delete the folder to start over). Fails on any crash, sanitizer report, leak, timeout (> 10 s
# on one input) or out-of-memory (> 2 GB), printing the reproducer and how to replay it.
set -uo pipefail
cd "$(dirname "$0")/.."
build="${1:?usage: fuzz/run.sh BUILD_DIR SECONDS}"
seconds="${2:?usage: fuzz/run.sh BUILD_DIR SECONDS}"
formats="${FUZZ_FORMATS:-off obj ply}"
max_len="${FUZZ_MAX_LEN:-4096}"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1${UBSAN_OPTIONS:+:$UBSAN_OPTIONS}"
export ASAN_OPTIONS="detect_leaks=1${ASAN_OPTIONS:+:$ASAN_OPTIONS}"

failed=()
for fmt in $formats; do
  bin="$build/fuzz_read_$fmt"
  if [[ ! -x "$bin" ]]; then
    echo "fuzz: $bin not built" >&2
    exit 1
  fi
  log="$build/fuzz-$fmt.log"
  artifacts="$build/fuzz-artifacts/$fmt"
  rm -rf "$artifacts"
  mkdir -p "$artifacts" "$build/fuzz-corpus/$fmt"

  # 1. Regressions: each saved reproducer must now pass.
  shopt -s nullglob
  regressions=(tests/corpus/regressions/*."$fmt")
  shopt -u nullglob
  if [[ ${#regressions[@]} -gt 0 ]]; then
    if ! "$bin" -timeout=10 -rss_limit_mb=2048 -artifact_prefix="$artifacts/" \
      "${regressions[@]}" > "$log" 2>&1; then
      echo "fuzz[$fmt]: FAILED replaying tests/corpus/regressions (log: $log)" >&2
      tail -n 40 "$log" >&2
      failed+=("$fmt")
      continue
    fi
  fi

  # 2. Bounded fuzzing run.
  cp -n tests/corpus/"$fmt"/* "$build/fuzz-corpus/$fmt/"
  echo "fuzz[$fmt]: ${seconds}s, max_len $max_len, corpus $build/fuzz-corpus/$fmt"
  start=$(date +%s)
  "$bin" "$build/fuzz-corpus/$fmt" \
    -max_total_time="$seconds" -max_len="$max_len" -timeout=10 -rss_limit_mb=2048 \
    -dict="fuzz/$fmt.dict" -artifact_prefix="$artifacts/" -print_final_stats=1 \
    >> "$log" 2>&1
  rc=$?
  elapsed=$(($(date +%s) - start))
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -n 1)
  units=$(find "$build/fuzz-corpus/$fmt" -type f | wc -l)
  found=$(find "$artifacts" -type f | sort)
  if [[ $rc -ne 0 || -n "$found" ]]; then
    echo "fuzz[$fmt]: FAILED (exit $rc after ${elapsed}s; log: $log)" >&2
    grep -E '^(==[0-9]+==ERROR|SUMMARY|.*runtime error|fuzz_read_|ALARM|==[0-9]+== ERROR: libFuzzer)' \
      "$log" | head -n 20 >&2
    for a in $found; do
      echo "  reproducer: $a" >&2
      echo "  replay:     $bin $a" >&2
      echo "  minimize:   $bin -minimize_crash=1 -max_total_time=60 $a" >&2
    done
    failed+=("$fmt")
  else
    echo "fuzz[$fmt]: ok, ${execs:-?} inputs in ${elapsed}s (${rate:-?} exec/s), corpus $units files"
  fi
done

if [[ ${#failed[@]} -gt 0 ]]; then
  echo "fuzz: FAILED for ${failed[*]}" >&2
  exit 1
fi
echo "fuzz: no findings"
