#!/usr/bin/env bash
# `mpirun -n 2 vssw study` writes the rows of a single-process run (the processes share the tasks; rank 0 writes),
# also when it was interrupted and resumed.
# As root (CI) OpenMPI needs --allow-run-as-root; --oversubscribe lets 2 processes start on a 1-core machine.
# usage: study_mpi.sh VSSW SOURCE_DIR WORK_DIR
set -euo pipefail
vssw="$1" src="$2" work="$3"
study="$src/tests/cli/study_small.toml"
rm -rf "$work" && mkdir -p "$work"
"$vssw" study "$study" --out "$work/single" --no-plots >/dev/null
mpirun --allow-run-as-root --oversubscribe -n 2 "$vssw" study "$study" --out "$work/mpi" --no-plots --json > "$work/mpi.json"
grep -q '"processes": 2' "$work/mpi.json"
cmp "$work/single/results.csv" "$work/mpi/results.csv"
echo "mpirun -n 2: the same rows as one process"

# Interrupted under MPI (SIGINT once a task is in the journal) and resumed under MPI: the rows of one uninterrupted
# process. (If the run ends before the signal, the resume finds it finished: the same rows.) The signal waits for the
# journal: a fixed second was, under load, sometimes before MPI's start-up had let any task finish, which left
# nothing to resume (--resume then refuses the folder).
slow="$src/tests/cli/study_engines.toml"
"$vssw" study "$slow" --out "$work/slow-single" --no-plots >/dev/null
mpirun --allow-run-as-root --oversubscribe -n 2 "$vssw" study "$slow" --out "$work/slow-mpi" --no-plots \
  >/dev/null 2>&1 &
run=$!
for _ in $(seq 1 600); do  # up to a minute
  grep -q '^#done' "$work/slow-mpi/journal.csv" 2>/dev/null && break
  kill -0 "$run" 2>/dev/null || break
  sleep 0.1
done
kill -INT "$run" 2>/dev/null || true
wait "$run" || true
[ -f "$work/slow-mpi/journal.csv" ] && echo "interrupted with $(grep -c '^#done' "$work/slow-mpi/journal.csv") tasks done"
mpirun --allow-run-as-root --oversubscribe -n 2 "$vssw" study "$slow" --out "$work/slow-mpi" --no-plots --resume \
  >/dev/null
cmp "$work/slow-single/results.csv" "$work/slow-mpi/results.csv"
echo "mpirun -n 2, interrupted and resumed: the same rows as one process"
