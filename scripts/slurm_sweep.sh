#!/usr/bin/env bash
# An mdrsim sweep as a SLURM job array: array task I of N runs shard I/N of the sweep into
# OUT.shard-I-of-N.csv, and a job that depends on the array merges the shards into OUT,
# byte for byte the CSV of the sweep run in one piece (README "Sweeps").
#
# From the repository (or with MDRSIM=/path/to/mdrsim), submit both at once:
#   bash scripts/slurm_sweep.sh submit 16 OUT.csv SCENE.toml --vary KEY=... [sweep flags]...
# which runs
#   jobid=$(sbatch --parsable --array=0-15 scripts/slurm_sweep.sh shard OUT.csv SCENE.toml ...)
#   sbatch --dependency=afterok:$jobid scripts/slurm_sweep.sh merge OUT.csv
# A task runs its shard with --resume: a requeued task (node failure, preemption) or a
# resubmitted array keeps every row its shard had finished. At the time limit SLURM sends
# SIGTERM: mdrsim keeps the finished rows and exits 143; submit the same array again to
# finish. The two steps also run without SLURM, e.g. to try them:
#   SLURM_ARRAY_TASK_ID=0 SLURM_ARRAY_TASK_COUNT=2 bash scripts/slurm_sweep.sh shard OUT.csv ...
#   SLURM_ARRAY_TASK_ID=1 SLURM_ARRAY_TASK_COUNT=2 bash scripts/slurm_sweep.sh shard OUT.csv ...
#   bash scripts/slurm_sweep.sh merge OUT.csv
#
#SBATCH --job-name=mdrsim-sweep
#SBATCH --cpus-per-task=2
#SBATCH --time=02:00:00
#SBATCH --requeue
#SBATCH --output=mdrsim-sweep-%A_%a.log
set -euo pipefail

mdrsim=${MDRSIM:-build/apps/mdrsim}

usage() {
  echo "usage: $0 submit N OUT.csv SCENE.toml --vary ... | shard OUT.csv SCENE.toml --vary ... | merge OUT.csv" >&2
  exit 2
}

[[ $# -ge 2 ]] || usage
mode=$1
shift
case "$mode" in
  submit)
    [[ $# -ge 3 && $1 =~ ^[1-9][0-9]*$ ]] || usage
    count=$1
    shift
    # The jobs start in this folder; the binary is named by its absolute path.
    MDRSIM=$(realpath "$mdrsim")
    export MDRSIM
    jobid=$(sbatch --parsable --array=0-$((count - 1)) "$0" shard "$@")
    sbatch --dependency=afterok:"${jobid%%;*}" --job-name=mdrsim-merge --cpus-per-task=1 \
      "$0" merge "$1"
    ;;
  shard)
    out=$1
    shift
    [[ -n ${SLURM_ARRAY_TASK_ID:-} ]] || { echo "$0: shard runs as a SLURM array task (SLURM_ARRAY_TASK_ID)" >&2; exit 2; }
    index=$SLURM_ARRAY_TASK_ID
    count=${SLURM_ARRAY_TASK_COUNT:-$((SLURM_ARRAY_TASK_MAX - SLURM_ARRAY_TASK_MIN + 1))}
    # Shard I/N needs the tasks 0..N-1: --array=0-15, not 1-16 or 0-30:2.
    if [[ ${SLURM_ARRAY_TASK_MIN:-0} != 0 || ${SLURM_ARRAY_TASK_MAX:-$((count - 1))} != $((count - 1)) ]]; then
      echo "$0: the array must be --array=0-$((count - 1)) (tasks 0 to N-1, step 1)" >&2
      exit 2
    fi
    exec "$mdrsim" sweep "$@" --shard "$index/$count" --resume \
      --threads "${SLURM_CPUS_PER_TASK:-1}" --csv "${out%.csv}.shard-$index-of-$count.csv"
    ;;
  merge)
    out=$1
    shopt -s nullglob
    shards=("${out%.csv}".shard-*-of-*.csv)
    [[ ${#shards[@]} -gt 0 ]] || { echo "$0: no ${out%.csv}.shard-*-of-*.csv to merge" >&2; exit 2; }
    "$mdrsim" merge "$out" "${shards[@]}"
    ;;
  *)
    usage
    ;;
esac
