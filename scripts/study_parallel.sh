#!/usr/bin/env bash
# A study split into N shards run side by side by GNU parallel (Debian package `parallel`), on this machine or on
# several (-S host1,host2: the study file, its records and OUT must be on a shared file system, vssw at the same
# path), then merged into OUT:
#
#   bash scripts/study_parallel.sh STUDY.toml OUT N [parallel options...]
#
# It is the one line below; each shard runs with --threads 1 (GNU parallel runs one per core; -j to change that)
# and writes OUT/shards/K-of-N, so that a shard that fails can be run again alone (add --resume to finish it).
set -euo pipefail
if [ $# -lt 3 ]; then
  echo "usage: bash scripts/study_parallel.sh STUDY.toml OUT N [parallel options...]" >&2
  exit 2
fi
study="$1" out="$2" n="$3"
shift 3
vssw="${VSSW:-$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)/build/vssw}"
command -v parallel >/dev/null || { echo "study_parallel.sh: GNU parallel is not installed (apt-get install parallel)" >&2; exit 2; }
mkdir -p "$out/shards"

parallel --will-cite --halt now,fail=1 "$@" "$vssw" study "$study" --out "$out/shards/{}-of-$n" --shard "{}/$n" --threads 1 '>' "$out/shards/{}-of-$n.log" ::: $(seq 1 "$n")
shards=()
for k in $(seq 1 "$n"); do shards+=("$out/shards/$k-of-$n"); done
"$vssw" study merge "${shards[@]}" --out "$out"
