#!/usr/bin/env bash
# vssw check against a deliberately broken core: the real program must pass the CI bounds (exit 0), the one with a
# wrong sign in the reference's whole-mechanism impact must fail them (exit 1, not 2 or a crash) and name the analytic restitution as out.
#   check_catches_mutant.sh VSSW MUTANT BOUNDS
set -uo pipefail
vssw="$1" mutant="$2" bounds="$3"
out="$(mktemp)"
trap 'rm -f "$out"' EXIT

"$vssw" check --bounds "$bounds" >"$out" 2>&1
code=$?
if [ "$code" -ne 0 ]; then
  echo "FAIL: vssw check --bounds $bounds exited $code, expected 0"; cat "$out"; exit 1
fi

"$mutant" check --bounds "$bounds" >"$out" 2>&1
code=$?
if [ "$code" -ne 1 ]; then
  echo "FAIL: the impact mutant exited $code, expected 1"; cat "$out"; exit 1
fi
if ! grep -Eq '^analytic +[^ ]+ +restitution .*OUT' "$out"; then
  echo "FAIL: the mutant's report does not name the analytic restitution as out of bounds"; cat "$out"; exit 1
fi
echo "ok: vssw holds the bounds; the impact mutant fails them:"
grep -E 'OUT|bounds' "$out"
