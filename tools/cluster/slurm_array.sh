#!/usr/bin/env bash
# A curvbench study over a Slurm cluster: one array task per shard, then a report job that runs
# once every shard has finished (afterok). The case store must be on a filesystem every node
# sees; every node must run the same curvbench build (the store is keyed by the code version).
#
#   bash tools/cluster/slurm_array.sh [OPTIONS] SHARDS STORE OUTPUT EXPERIMENT...|--all [RUN...]
#   e.g. bash tools/cluster/slurm_array.sh -p short -t 02:00:00 32 /nfs/cb-store /nfs/cb-out --all
#
# Everything after OUTPUT goes to `curvbench run` as it is (experiment names or --all, and run
# options such as --experiments-dir DIR or --no-readings). Options (before SHARDS):
#   -p, --partition P     -t, --time T (per task)     -A, --account A
#   -c, --cpus-per-task C (also curvbench's --threads; default $THREADS or 2)
#   --logs DIR            the Slurm logs (default OUTPUT)
# Environment: CURVBENCH (default: build/curvbench of this checkout), THREADS, SBATCH_ARGS (any
# other sbatch options, e.g. "--mem-per-cpu=2G --qos=long"); sbatch's own SBATCH_PARTITION,
# SBATCH_TIMELIMIT and SBATCH_ACCOUNT work too. Prints the two job ids.
set -euo pipefail
usage() {
  sed -n '2,16p' "$0" >&2
  exit 2
}
threads=${THREADS:-2}
logs=
sbatch_args=()
while [[ $# -gt 0 && $1 == -* ]]; do
  [[ $# -ge 2 ]] || usage
  case "$1" in
    -p | --partition) sbatch_args+=("--partition=$2") ;;
    -t | --time) sbatch_args+=("--time=$2") ;;
    -A | --account) sbatch_args+=("--account=$2") ;;
    -c | --cpus-per-task) threads=$2 ;;
    --logs) logs=$2 ;;
    *) usage ;;
  esac
  shift 2
done
[[ $# -ge 4 ]] || usage
shards=$1 store=$2 output=$3
shift 3
if ! [[ $shards =~ ^[1-9][0-9]*$ ]]; then
  echo "slurm_array.sh: SHARDS: expected a positive integer, got '$shards'" >&2
  exit 2
fi
if ! [[ $threads =~ ^[1-9][0-9]*$ ]]; then
  echo "slurm_array.sh: --cpus-per-task: expected a positive integer, got '$threads'" >&2
  exit 2
fi
curvbench=${CURVBENCH:-$(cd "$(dirname "$0")/../.." && pwd)/build/curvbench}
if [[ ! -x $curvbench ]]; then
  echo "slurm_array.sh: no curvbench binary at '$curvbench' (build it, or set CURVBENCH)" >&2
  exit 2
fi
# Absolute paths: the jobs start in this folder (sbatch's default), but the logs and the job
# scripts should not depend on it.
curvbench=$(realpath "$curvbench")
store=$(realpath -m "$store")
output=$(realpath -m "$output")
logs=$(realpath -m "${logs:-$output}")
# Slurm does not create the folder of --output: a job whose log cannot be opened fails at once.
mkdir -p "$store" "$output" "$logs"
# shellcheck disable=SC2206  # SBATCH_ARGS is a list of words
sbatch_args+=(${SBATCH_ARGS:-} --cpus-per-task="$threads")

# The command line, quoted once here and run as a bash job script (no --wrap: /bin/sh would
# reparse it).
printf -v run '%q ' "$curvbench" run "$@" --cache "$store" --output "$output" --threads "$threads"

# Shard K of N for K = 1..N (SLURM_ARRAY_TASK_ID); a shard's exit status is curvbench's.
array_job=$(sbatch --parsable "${sbatch_args[@]}" --job-name=curvbench-shard \
  --array="1-$shards" --output="$logs/slurm-shard-%a.log" <<EOF
#!/bin/bash
exec ${run}--shard "\$SLURM_ARRAY_TASK_ID/$shards"
EOF
)
array_job=${array_job%%;*} # --parsable prints "id" or "id;cluster"
# The report (CSVs, rates, REPORT.md, plots, CLAIMS.md) from the complete store. afterok on an
# array waits for every task; if one fails, the report job is cancelled (kill-on-invalid-dep)
# instead of waiting forever.
report_job=$(sbatch --parsable "${sbatch_args[@]}" --job-name=curvbench-report \
  --dependency="afterok:$array_job" --kill-on-invalid-dep=yes \
  --output="$logs/slurm-report.log" <<EOF
#!/bin/bash
exec ${run}--report-only
EOF
)
report_job=${report_job%%;*}
echo "submitted shards $array_job (array 1-$shards) and report $report_job -> $output"
