#!/usr/bin/env bash
# SIGINT and SIGTERM leave no temporary file, folder or lock file behind, and what the run would have replaced as it
# was; a --resume or another command on its --out while the study still runs is refused naming its process; the
# interrupted study resumes to the rows of an uninterrupted run. The real program, on jobs long enough to be caught
# mid-way: a history writing a 30 MB CSV, and a study held in its plot phase by a stand-in for gnuplot that sleeps
# (and ends with the study).
# usage: out_signals.sh VSSW SOURCE_DIR WORK_DIR
set -euo pipefail
set -m  # background jobs keep SIGINT (a script's background jobs otherwise ignore it)
vssw="$1" src="$2" work="$3"
rm -rf "$work" && mkdir -p "$work" && cd "$work"
fail() { echo "FAIL: $*" >&2; exit 1; }
no_leftovers() { if ls -a "$1" | grep -q 'vssw-tmp\|vssw-lock'; then ls -a "$1" >&2; fail "$2: a leftover in $1"; fi; }
# A process alive (not gone, not a zombie waiting to be reaped).
running() { local state; state=$(awk '{print $3}' "/proc/$1/stat" 2>/dev/null) && [ "$state" != Z ]; }
# Waits (up to 60 s) until a path matching the glob exists.
wait_for() { for _ in $(seq 6000); do compgen -G "$1" >/dev/null && return 0; sleep 0.01; done; fail "never saw $1"; }

# 1. history --csv: the signal arrives while the temporary CSV is being written.
wall=(--height 4 --thickness 0.4 --hinge 0.7)
long=(--pulse harmonic --amplitude 0.05 --pulse-period 0.5 --duration 100 --output-dt 1e-4 --t-end 100)
for sig in INT TERM; do
  echo "the old file" > big.csv
  "$vssw" history "${wall[@]}" "${long[@]}" --csv big.csv >/dev/null &
  pid=$!
  wait_for '.big.csv.vssw-tmp-*'
  kill -s "$sig" "$pid"
  rc=0; wait "$pid" || rc=$?
  want=$((128 + $(kill -l "$sig")))
  [ "$rc" = "$want" ] || fail "history SIG$sig: exit $rc, want $want"
  no_leftovers . "history SIG$sig"
  [ "$(cat big.csv)" = "the old file" ] || fail "history SIG$sig: big.csv changed"
  echo "history --csv, SIG$sig: exit $rc, no temporary file, the old file intact"
done

# 2. study: held in its plot phase by a gnuplot that sleeps; the results folder is then in its staging folder.
cat > slow-gnuplot <<'SH'
#!/bin/sh
echo $$ > "$VSSW_TEST_MARK"
exec sleep 60
SH
chmod +x slow-gnuplot
study="$src/tests/cli/study_small.toml"
"$vssw" study "$study" --out reference --no-plots >/dev/null
"$vssw" study "$study" --out s --no-plots >/dev/null
echo "a note of the user's" > s/notes.txt
(cd s && md5sum results.csv manifest.json results.json study.md notes.txt) > s.md5
resume=()
for sig in INT TERM; do
  rm -f mark
  VSSW_TEST_MARK="$work/mark" "$vssw" study "$study" --out s ${resume[@]+"${resume[@]}"} --gnuplot "$work/slow-gnuplot" \
    >/dev/null 2>err.txt &
  pid=$!
  wait_for mark
  # A second run or a --resume meanwhile: refused, naming the first.
  rc=0; "$vssw" study "$study" --out s --resume --no-plots >/dev/null 2>second.txt || rc=$?
  [ "$rc" = 2 ] || fail "a --resume while the study runs: exit $rc, want 2"
  grep -q "in use by another vssw command (process $pid)" second.txt || { cat second.txt >&2; fail "not named: $pid"; }
  # Another command on the same --out meanwhile (two commands started together once both succeeded, the folder mixing
  # their files): refused up front, naming the first; nothing of it in the folder.
  rc=0; "$vssw" motions generate --count 2 --seed 1 --out s >/dev/null 2>second.txt || rc=$?
  [ "$rc" = 2 ] || fail "motions generate into a study's folder in use: exit $rc, want 2"
  grep -q "in use by another vssw command (process $pid)" second.txt || { cat second.txt >&2; fail "motions: not named"; }
  if ls s | grep -q 'motion'; then ls s >&2; fail "motions generate wrote into the study's folder"; fi
  kill -s "$sig" "$pid"
  rc=0; wait "$pid" || rc=$?
  # The stand-in for gnuplot, a child of the study, ended with it (analytic/child_fork.hpp).
  for _ in $(seq 3000); do running "$(cat mark)" || break; sleep 0.01; done
  if running "$(cat mark)"; then kill "$(cat mark)"; fail "study SIG$sig: its gnuplot still runs"; fi
  want=$((128 + $(kill -l "$sig")))
  [ "$rc" = "$want" ] || fail "study SIG$sig: exit $rc, want $want"
  no_leftovers . "study SIG$sig"
  no_leftovers s "study SIG$sig"
  (cd s && md5sum -c --quiet ../s.md5) || fail "study SIG$sig: the old results changed"
  [ -f s/journal.csv ] || fail "study SIG$sig: no journal to resume"
  resume=(--resume)  # the next run continues the journal the signal left
  echo "study ${resume[*]-} in its plot phase, SIG$sig: exit $rc, no staging folder, the old results intact, --resume refused meanwhile"
done
"$vssw" study "$study" --out s --resume --no-plots >/dev/null
cmp reference/results.csv s/results.csv || fail "the resumed study differs from an uninterrupted run"
[ "$(cat s/notes.txt)" = "a note of the user's" ] || fail "the user's file was not carried over"
[ ! -e s/journal.csv ] || fail "the journal was left"
no_leftovers . "resume"
echo "--resume after the signals: results.csv byte-identical to an uninterrupted run; the user's file kept"
