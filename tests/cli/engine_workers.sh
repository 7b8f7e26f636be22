#!/usr/bin/env bash
# Engine workers (multibody/host/child_process.hpp) never outlive the program, and their output never repeats the
# program's: a study whose runs take long (Simbody at a stiffness of 1e18, inside its range), its parent alone sent
# SIGTERM, SIGINT or SIGKILL (as `kill PID`, a batch system or the OOM killer would), leaves no worker alive; and
# `compare` of two engines written to a file gives one block per engine (each forked child once wrote a copy of the
# program's unwritten output).
# usage: engine_workers.sh VSSW WORK_DIR
set -euo pipefail
set -m  # background jobs keep SIGINT (a script's background jobs otherwise ignore it)
vssw="$1" work="$2"
rm -rf "$work" && mkdir -p "$work" && cd "$work"
fail() { echo "FAIL: $*" >&2; exit 1; }
for engine in ode simbody; do
  "$vssw" --version | grep -q "^  $engine " || { echo "SKIP: no $engine in this build"; exit 77; }
done
# A process gone, or a zombie (ended, waiting to be reaped by whoever adopted it).
ended() { local state; state=$(awk '{print $3}' "/proc/$1/stat" 2>/dev/null) || return 0; [ "$state" = Z ]; }
# Up to 30 s for a condition (a loaded machine starts the workers slowly); only a failure waits that long.
within_30s() { for _ in $(seq 3000); do "$@" && return 0; sleep 0.01; done; return 1; }

# 1. Output to a file: exactly one block per engine.
wall=(--height 4 --thickness 0.4 --hinge 0.7)
"$vssw" compare --engine ode,simbody "${wall[@]}" > compare.txt
blocks=$(grep -c 'against the analytic model' compare.txt)
[ "$blocks" = 2 ] || { cat compare.txt >&2; fail "compare of two engines to a file: $blocks blocks, want 2"; }
echo "compare --engine ode,simbody > file: 2 blocks"

# 2. A study's workers, its parent alone signalled.
cat > slow.toml <<'TOML'
name = "slow"
metrics = ["peak_rotation"]
engines = ["simbody"]
[wall]
height = 4
thickness = 0.4
hinge = [0.6, 0.7]
[excitation]
kind = "pulse"
shape = "sine"
amplitude = 0.5
pulse_period = 0.5
[settings.simbody]
stiffness = 1e18
TOML
two_workers() { [ "$(pgrep -P "$1" | wc -l)" -ge 2 ]; }
for sig in TERM INT KILL; do
  "$vssw" study slow.toml --out "slow-$sig" --threads 2 --no-plots >/dev/null 2>&1 &
  pid=$!
  within_30s two_workers "$pid" || fail "SIG$sig: the study never had two workers"
  workers=$(pgrep -P "$pid" | tr '\n' ' ')
  kill -s "$sig" "$pid"
  rc=0; wait "$pid" || rc=$?
  want=$((128 + $(kill -l "$sig")))
  [ "$rc" = "$want" ] || fail "study SIG$sig: exit $rc, want $want"
  for w in $workers; do
    within_30s ended "$w" || { kill -KILL $workers 2>/dev/null; fail "study SIG$sig: its worker $w still runs"; }
  done
  echo "study, SIG$sig to the parent alone: exit $rc, its workers ($workers) ended"
done
