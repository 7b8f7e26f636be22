#!/usr/bin/env bash
# A run that fails on a full disk leaves the results folder it would have replaced as it was (no mixture of old and
# new files, no staging folder), for study and report; bench --out on a read-only place is refused before the sweep.
# Needs a 1 MiB tmpfs and a read-only one: run as root; elsewhere it is skipped (exit 77) with the reason.
# usage: out_full_disk.sh VSSW SOURCE_DIR WORK_DIR
set -euo pipefail
vssw="$1" src="$2" work="$3"
rm -rf "$work" && mkdir -p "$work/full" "$work/ro" && cd "$work"
fail() { echo "FAIL: $*" >&2; exit 1; }
cleanup() { umount "$work/full" 2>/dev/null || true; umount "$work/ro" 2>/dev/null || true; }
trap cleanup EXIT
if ! mount -t tmpfs -o size=1m tmpfs "$work/full" 2>/dev/null; then
  echo "SKIP: cannot mount a tmpfs here (not root, or no permission): the full-disk cases need one"
  exit 77
fi
# A read-only place holding an existing folder: the folder exists, so only a check that it can be written catches it.
mount -t tmpfs -o size=1m tmpfs "$work/ro" && mkdir "$work/ro/b" && mount -o remount,ro "$work/ro" ||
  fail "mounted one tmpfs but could not make a read-only one"
no_leftovers() { if ls -a "$1" | grep -q 'vssw-tmp'; then ls -a "$1" >&2; fail "$2: a .vssw-tmp leftover in $1"; fi; }

# Study: a small study fits; one 7 times larger into the same folder does not, though its results.csv alone would
# (the case where an earlier vssw left the new results.csv beside the old results.json).
cat > big.toml <<TOML
name = "big"
metrics = ["peak_rotation", "peak_time", "overturned", "energy_balance_error"]
[wall]
alpha = [0.06, 0.07, 0.08, 0.09, 0.1, 0.11, 0.12, 0.13, 0.14, 0.15]
R = [1.0, 1.5, 2.0, 2.5]
hinge = 0.6
xi = 0.1
[assumptions]
set = "paper"  # its roller bilateral, so that every combination below is a model (the size the test needs)
kinematics = ["paper", "exact"]
impact = ["eq19", "whole-mechanism"]
[excitation]
kind = "record"
file = "$src/data/elcentro_chopra.txt"
pga = [0.2, 0.4]
TOML
"$vssw" study "$src/tests/cli/study_small.toml" --out full/s --no-plots >/dev/null
(cd full/s && md5sum results.csv results.json manifest.json study.md study.html) > s.md5
rc=0; "$vssw" study big.toml --out full/s --no-plots >/dev/null 2>err.txt || rc=$?
[ "$rc" = 2 ] || fail "study on a full disk: exit $rc, want 2"
grep -q "vssw: error: .*results" err.txt || { cat err.txt >&2; fail "study: no message naming the file"; }
(cd full/s && md5sum -c --quiet ../../s.md5) || fail "study: the old results changed"
no_leftovers full "study"
echo "study on a full disk: exit 2, the old results intact, no staging folder"

# Report: a one-case report fits; the default suite's (3.4 MB) into the same folder does not.
"$vssw" report --engines analytic --no-plots --cases fig6-vssw --out full/r >/dev/null
(cd full/r && md5sum report.md report.html results.json metrics.csv failures.csv traces.csv) > r.md5
rc=0; "$vssw" report --engines analytic --no-plots --out full/r >/dev/null 2>err.txt || rc=$?
[ "$rc" = 2 ] || fail "report on a full disk: exit $rc, want 2"
(cd full/r && md5sum -c --quiet ../../r.md5) || fail "report: the old report changed"
no_leftovers full "report"
echo "report on a full disk: exit 2, the old report intact, no staging folder"

# bench --out on a read-only place: refused before the sweep (which prints a line per point as it goes).
rc=0; "$vssw" bench --quick --engines analytic --no-plots --out ro/b >out.txt 2>err.txt || rc=$?
[ "$rc" = 2 ] || fail "bench on a read-only place: exit $rc, want 2"
grep -q "^vssw: error: --out 'ro/b'" err.txt || { cat err.txt >&2; fail "bench: the message does not name --out"; }
if grep -q "^vssw bench: " err.txt; then fail "bench: the sweep ran before --out was found unwritable"; fi
for cmd in "study $src/tests/cli/study_small.toml" "report --engines analytic" "stress --quick --engines analytic"; do
  rc=0; $vssw $cmd --out ro/b >/dev/null 2>err.txt || rc=$?
  [ "$rc" = 2 ] || fail "$cmd on a read-only place: exit $rc, want 2"
done
echo "bench, study, report, stress --out on a read-only place: exit 2 before running"
