#!/usr/bin/env bash
# `make experiments`: regenerates results/ with every experiment of experiments/*.exp (paper §5,
# Figs. 3-22), Tables 2 and 4, REPORT.md, the plots and CLAIMS.md. Progress goes to the terminal.
# Extra arguments are passed to `curvbench run` (e.g. THREADS: `make experiments RUN_ARGS="--threads 1"`).
set -euo pipefail
BUILD=${1:-build}
shift || true
start=$(date +%s)
# Where the safeguarded QR's condition test cuts a stencil (D5's and D6's Why lines read it; about
# 20 s of CPU), before the run that writes CLAIMS.md.
"$BUILD/curvbench" safeguard-fires --output results/diag-safeguard-fires.csv
"$BUILD/curvbench" run --all --output results "$@"
# README.md's headline block from the new results (tools/readme_headline.py).
/usr/bin/python3 "$(dirname "$0")/readme_headline.py" README.md results
echo "[experiments] done in $(( $(date +%s) - start )) s: see results/REPORT.md and results/CLAIMS.md"
