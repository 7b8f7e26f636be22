#!/usr/bin/env bash
# Shards run by the shipped scripts give the rows of one run: scripts/study_parallel.sh (GNU parallel, when installed)
# and scripts/study_slurm.sh in the modes a Slurm array job calls it in (no cluster needed), each merged and compared
# byte for byte with a single run of the same study.
# usage: study_shards.sh VSSW SOURCE_DIR WORK_DIR
set -euo pipefail
vssw="$1" src="$2" work="$3"
study="$src/tests/cli/study_small.toml"
rm -rf "$work" && mkdir -p "$work"
"$vssw" study "$study" --out "$work/single" --no-plots >/dev/null

if command -v parallel >/dev/null; then
  VSSW="$vssw" bash "$src/scripts/study_parallel.sh" "$study" "$work/parallel" 3 >/dev/null
  cmp "$work/single/results.csv" "$work/parallel/results.csv"
  echo "study_parallel.sh: 3 shards merged = one run"
else
  echo "study_parallel.sh: GNU parallel is not installed, not tested"
fi

for k in 1 2 3; do
  SLURM_ARRAY_TASK_ID=$k VSSW="$vssw" bash "$src/scripts/study_slurm.sh" shard "$study" "$work/slurm" 3 >/dev/null
done
VSSW="$vssw" bash "$src/scripts/study_slurm.sh" merge "$study" "$work/slurm" 3 >/dev/null
cmp "$work/single/results.csv" "$work/slurm/results.csv"
echo "study_slurm.sh: 3 shards merged = one run"
