#!/usr/bin/env bash
# A study on a Slurm cluster: one array job whose task K runs shard K of N, and a merge job that waits for them all.
#
#   bash scripts/study_slurm.sh STUDY.toml OUT N [sbatch options...]     submits both jobs (prints their ids)
#
# The study file, its records, OUT and vssw must be on a file system every node sees. Each array task runs one shard
# on the CPUs Slurm gives it (--cpus-per-task, default 1 here: give more with e.g. `-c 8`); its log is
# OUT/shards/K-of-N.log. A task that fails can be run again with its shard alone (`--resume` finishes it); the merge
# job runs only once every shard has succeeded (afterok).
#
# Inside a job the same script is called with `shard` or `merge` as its first argument (by Slurm, not by you), and
# reads SLURM_ARRAY_TASK_ID; run it that way by hand to test it without a cluster:
#   SLURM_ARRAY_TASK_ID=K bash scripts/study_slurm.sh shard STUDY.toml OUT N
#   bash scripts/study_slurm.sh merge STUDY.toml OUT N
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
vssw="${VSSW:-$here/../build/vssw}"
usage() { echo "usage: bash scripts/study_slurm.sh [shard|merge] STUDY.toml OUT N [sbatch options...]" >&2; exit 2; }

mode=submit
case "${1:-}" in shard|merge) mode="$1"; shift ;; esac
[ $# -ge 3 ] || usage
study="$1" out="$2" n="$3"
shift 3

case "$mode" in
  shard)
    k="${SLURM_ARRAY_TASK_ID:?shard mode runs inside a Slurm array task (SLURM_ARRAY_TASK_ID)}"
    resume=()
    [ -f "$out/shards/$k-of-$n/journal.csv" ] && resume=(--resume)  # a requeued task finishes what it started
    exec "$vssw" study "$study" --out "$out/shards/$k-of-$n" --shard "$k/$n" --threads "${SLURM_CPUS_PER_TASK:-1}" \
      ${resume[@]+"${resume[@]}"}
    ;;
  merge)
    shards=()
    for k in $(seq 1 "$n"); do shards+=("$out/shards/$k-of-$n"); done
    exec "$vssw" study merge "${shards[@]}" --out "$out"
    ;;
  submit)
    command -v sbatch >/dev/null || { echo "study_slurm.sh: sbatch not found (not a Slurm login node?)" >&2; exit 2; }
    mkdir -p "$out/shards"
    array=$(sbatch --parsable --job-name=vssw-study --array="1-$n" --output="$out/shards/%a-of-$n.log" "$@" \
      "$here/study_slurm.sh" shard "$study" "$out" "$n")
    merge=$(sbatch --parsable --job-name=vssw-study-merge --dependency="afterok:$array" \
      --output="$out/merge.log" "$@" "$here/study_slurm.sh" merge "$study" "$out" "$n")
    echo "submitted: shards $array (array 1-$n), merge $merge (after all shards); results in $out"
    ;;
esac
