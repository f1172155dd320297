#!/usr/bin/env bash
# A curvbench study over a Slurm cluster: one array task per shard, then a report job that runs
# once every shard has finished (afterok). The case store must be on a filesystem every node
# sees; every node must run the same curvbench build (the store is keyed by the code version).
#
#   bash tools/cluster/slurm_array.sh SHARDS STORE OUTPUT [EXPERIMENT... | --all]
#   e.g. bash tools/cluster/slurm_array.sh 32 /shared/cb-store /shared/cb-results --all
#
# Environment: CURVBENCH (default: build/curvbench of this checkout), SBATCH_ARGS (extra sbatch
# options, e.g. "--partition=short --time=02:00:00"), THREADS (per task, default 2).
# A shard that fails or is cancelled can be resubmitted alone (sbatch --array=K ...); finished
# cases are kept, so a rerun computes only what is missing.
set -euo pipefail
if [[ $# -lt 4 ]]; then
  sed -n '2,13p' "$0" >&2
  exit 2
fi
shards=$1 store=$2 output=$3
shift 3
curvbench=${CURVBENCH:-$(cd "$(dirname "$0")/../.." && pwd)/build/curvbench}
threads=${THREADS:-2}
mkdir -p "$store" "$output"

# Shard K of N for K = 1..N (SLURM_ARRAY_TASK_ID).
array_job=$(sbatch --parsable ${SBATCH_ARGS:-} --job-name=curvbench-shard \
  --array="1-$shards" --cpus-per-task="$threads" --output="$output/slurm-shard-%a.log" \
  --wrap="'$curvbench' run $* --cache '$store' --output '$output' \
          --shard \$SLURM_ARRAY_TASK_ID/$shards --threads $threads")
# The report (CSVs, rates, REPORT.md, plots, CLAIMS.md) from the complete store.
report_job=$(sbatch --parsable ${SBATCH_ARGS:-} --job-name=curvbench-report \
  --dependency="afterok:$array_job" --cpus-per-task="$threads" \
  --output="$output/slurm-report.log" \
  --wrap="'$curvbench' run $* --cache '$store' --output '$output' --report-only \
          --threads $threads")
echo "submitted shards $array_job (1-$shards) and report $report_job -> $output"
