#!/usr/bin/env bash
# Places --out must not be (found by a review of the folder swap): a folder holding the current folder (the swap would
# leave the shell in a removed folder), a folder holding a mount point (the swap would carry that file system's files
# over and delete them from it); study merge into a folder holding an unfinished study (it destroyed the journal);
# a staging folder left by a run killed outright is removed by the next run into that --out.
# The mount-point case, last, needs root (a tmpfs); elsewhere the script skips (exit 77) after the others passed.
# usage: out_places.sh VSSW SOURCE_DIR WORK_DIR
set -euo pipefail
vssw="$1" src="$2" work="$3"
rm -rf "$work" && mkdir -p "$work" && cd "$work"
fail() { echo "FAIL: $*" >&2; exit 1; }
cleanup() { umount "$work/m/mnt" 2>/dev/null || true; }
trap cleanup EXIT
study="$src/tests/cli/study_small.toml"

# --out holding the current folder: refused, the folder as it was.
"$vssw" study "$study" --out here --no-plots >/dev/null
md5sum here/results.csv > here.md5
rc=0; (cd here && "$vssw" study "$study" --out . --no-plots >/dev/null 2>../err.txt) || rc=$?
[ "$rc" = 2 ] || fail "--out . : exit $rc, want 2"
grep -q "holds the current folder" err.txt || { cat err.txt >&2; fail "--out . : the message does not say why"; }
rc=0; (cd here && "$vssw" study "$study" --out .. --no-plots >/dev/null 2>../err.txt) || rc=$?
[ "$rc" = 2 ] || fail "--out .. : exit $rc, want 2"
md5sum -c --quiet here.md5 || fail "--out . : the results changed"
echo "--out holding the current folder: refused, nothing changed"

# A staging folder of a process that is gone (a run killed by SIGKILL): removed by the next run into that --out.
# Process id 2^22 + 1 is above Linux's largest (pid_max is at most 2^22).
mkdir -p .here.vssw-tmp-4194305/plots && touch .here.vssw-tmp-4194305/results.csv
"$vssw" study "$study" --out here --no-plots >/dev/null
[ ! -e .here.vssw-tmp-4194305 ] || fail "a dead run's staging folder was left beside --out"
echo "a dead run's staging folder: removed"

# study merge into a folder holding an unfinished study: refused, its journal kept.
"$vssw" study "$study" --out sh1 --shard 1/2 --no-plots >/dev/null
"$vssw" study "$study" --out sh2 --shard 2/2 --no-plots >/dev/null
mkdir unfinished && printf 'a journal\n' > unfinished/journal.csv
rc=0; "$vssw" study merge sh1 sh2 --out unfinished --no-plots >/dev/null 2>err.txt || rc=$?
[ "$rc" = 2 ] || fail "merge into an unfinished study: exit $rc, want 2"
grep -q "unfinished study" err.txt || { cat err.txt >&2; fail "merge: the message does not say why"; }
[ "$(cat unfinished/journal.csv)" = "a journal" ] || fail "merge: the journal changed"
echo "study merge into an unfinished study: refused, the journal kept"

# A mount point inside --out: refused, the mounted file system's files as they were.
mkdir -p m/mnt
"$vssw" study "$study" --out m --no-plots >/dev/null
if ! mount -t tmpfs -o size=1m tmpfs m/mnt 2>/dev/null; then
  echo "SKIP (the other cases passed): cannot mount a tmpfs here (not root): the mount-point case needs one"
  exit 77
fi
echo data > m/mnt/f
rc=0; "$vssw" study "$study" --out m --no-plots >/dev/null 2>err.txt || rc=$?
[ "$rc" = 2 ] || fail "a mount point inside --out: exit $rc, want 2"
grep -q "holds a mount point" err.txt || { cat err.txt >&2; fail "mount point: the message does not say why"; }
[ "$(cat m/mnt/f)" = data ] || fail "mount point: a file on the mounted file system changed"
mountpoint -q m/mnt || fail "mount point: the mount moved"
echo "a mount point inside --out: refused, its files intact"
