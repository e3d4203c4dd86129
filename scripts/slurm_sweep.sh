#!/usr/bin/env bash
# An mdrsim sweep as a SLURM job array: array task I of N runs shard I/N of the sweep into
# OUT.shard-I-of-N.csv, and a job that runs after the array (however its tasks ended) merges
# the shards into OUT, byte for byte the CSV of the sweep run in one piece (docs/sweeps.md).
#
# From any folder, submit both at once (sbatch options, if any, before N):
#   bash path/to/slurm_sweep.sh submit [--account=A --partition=P --time=4:00:00 ...] \
#       16 OUT.csv SCENE.toml --vary KEY=... [sweep flags]...
# which runs
#   jobid=$(sbatch --parsable [options] --array=0-15 slurm_sweep.sh shard OUT.csv SCENE.toml ...)
#   sbatch [options] --dependency=afterany:$jobid --output=mdrsim-sweep-${jobid}_merge.log \
#       slurm_sweep.sh merge OUT.csv 16
# (the tasks log to mdrsim-sweep-JOB_I.log, the merge to mdrsim-sweep-JOB_merge.log).
# sbatch's own variables (SBATCH_ACCOUNT, SBATCH_PARTITION, SBATCH_TIMELIMIT) work too.
# The mdrsim run is $MDRSIM if set, else the `mdrsim` on PATH (an installed one), else the
# build next to this script (build/apps/mdrsim); submit passes it to the jobs by its
# absolute path.
# A task runs its shard with --resume: a requeued task (node failure, preemption) or a
# resubmitted array keeps every row its shard had finished. At the time limit SLURM sends
# SIGTERM: mdrsim keeps the finished rows and exits 143. The merge runs anyway; it names the
# shards that are missing (exit 1) or unfinished (exit 2, mdrsim merge's) without writing
# OUT. Submit the same
# array again to finish them, then merge by hand:
#   bash path/to/slurm_sweep.sh merge OUT.csv 16
# The two steps also run without SLURM, e.g. to try them:
#   SLURM_ARRAY_TASK_ID=0 SLURM_ARRAY_TASK_COUNT=2 bash scripts/slurm_sweep.sh shard OUT.csv ...
#   SLURM_ARRAY_TASK_ID=1 SLURM_ARRAY_TASK_COUNT=2 bash scripts/slurm_sweep.sh shard OUT.csv ...
#   bash scripts/slurm_sweep.sh merge OUT.csv 2
#
#SBATCH --job-name=mdrsim-sweep
#SBATCH --cpus-per-task=2
#SBATCH --time=02:00:00
#SBATCH --requeue
#SBATCH --output=mdrsim-sweep-%A_%a.log
set -euo pipefail

usage() {
  echo "usage: $0 submit [SBATCH OPTIONS...] N OUT.csv SCENE.toml --vary ... | shard OUT.csv SCENE.toml --vary ... | merge OUT.csv [N]" >&2
  exit 2
}

# The mdrsim to run: $MDRSIM, an installed mdrsim, or this checkout's build.
find_mdrsim() {
  if [[ -n ${MDRSIM:-} ]]; then
    echo "$MDRSIM"
  elif command -v mdrsim >/dev/null 2>&1; then
    command -v mdrsim
  else
    echo "$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/../build/apps/mdrsim"
  fi
}

[[ $# -ge 2 ]] || usage
mode=$1
shift
case "$mode" in
  submit)
    options=()
    while [[ $# -gt 0 && $1 == -* ]]; do
      options+=("$1")
      shift
    done
    [[ $# -ge 3 && $1 =~ ^[1-9][0-9]*$ ]] || usage
    count=$1
    shift
    mdrsim=$(find_mdrsim)
    [[ -x $mdrsim ]] || { echo "$0: no mdrsim at '$mdrsim' (set MDRSIM=/path/to/mdrsim)" >&2; exit 2; }
    # The jobs start in this folder, from a copy of this script: the binary goes by its
    # absolute path.
    MDRSIM=$(realpath "$mdrsim")
    export MDRSIM
    jobid=$(sbatch --parsable "${options[@]}" --array=0-$((count - 1)) "$0" shard "$@")
    # afterany: the merge runs however the tasks ended (a timed-out task must not leave it
    # pending for ever); it checks the shards itself. Its log sits beside the tasks' logs
    # (mdrsim-sweep-JOB_I.log): the directive's %a is no index for a job outside an array.
    sbatch "${options[@]}" --dependency=afterany:"${jobid%%;*}" --job-name=mdrsim-merge \
      --output="mdrsim-sweep-${jobid%%;*}_merge.log" --cpus-per-task=1 "$0" merge "$1" "$count"
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
    exec "$(find_mdrsim)" sweep "$@" --shard "$index/$count" --resume \
      --threads "${SLURM_CPUS_PER_TASK:-1}" --csv "${out%.csv}.shard-$index-of-$count.csv"
    ;;
  merge)
    out=$1
    count=${2:-}
    shopt -s nullglob
    if [[ -n $count ]]; then
      [[ $count =~ ^[1-9][0-9]*$ ]] || usage
      shards=()
      missing=()
      for ((i = 0; i < count; i++)); do
        shard="${out%.csv}.shard-$i-of-$count.csv"
        if [[ -f $shard ]]; then shards+=("$shard"); else missing+=("$i"); fi
      done
      if [[ ${#missing[@]} -gt 0 ]]; then
        echo "$0: ${#missing[@]} of $count shards have no CSV (${out%.csv}.shard-I-of-$count.csv for I = ${missing[*]}): their tasks never started or failed; submit the array again (--resume keeps the rows done), then: bash slurm_sweep.sh merge $out $count" >&2
        exit 1
      fi
    else
      shards=("${out%.csv}".shard-*-of-*.csv)
      [[ ${#shards[@]} -gt 0 ]] || { echo "$0: no ${out%.csv}.shard-*-of-*.csv to merge" >&2; exit 2; }
    fi
    # mdrsim merge names a shard that is unfinished (a task that timed out) and writes nothing.
    "$(find_mdrsim)" merge "$out" "${shards[@]}" || {
      status=$?
      echo "$0: not merged; submit the array again (--resume finishes the shards), then: bash slurm_sweep.sh merge $out ${count:-N}" >&2
      exit "$status"
    }
    ;;
  *)
    usage
    ;;
esac
