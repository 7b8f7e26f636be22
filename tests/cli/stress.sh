#!/usr/bin/env bash
# vssw stress --quick --json: every case ends (no hang, crash or NaN), the JSON has its documented shape, the files are
# written, and the verdicts docs/measurements/stress.md states hold; bad input exits 2 naming the value.
#   stress.sh VSSW WORKDIR
set -uo pipefail
vssw="$1" dir="$2"
rm -rf "$dir" && mkdir -p "$dir"

"$vssw" stress --quick --json --out "$dir/out" >"$dir/stdout.json" 2>"$dir/stderr.txt"
code=$?
if [ "$code" -ne 0 ]; then
  echo "FAIL: vssw stress --quick exited $code, expected 0"; cat "$dir/stderr.txt"; exit 1
fi
for f in stress.json stress.csv stress.md; do
  [ -s "$dir/out/$f" ] || { echo "FAIL: $dir/out/$f not written"; exit 1; }
done

python3 - "$dir/stdout.json" <<'PY' || exit 1
import json, sys
doc = json.load(open(sys.argv[1]))
for key in ("quick", "time_limit_s", "engines", "cases", "unsafe", "stable_steps", "case_list", "wall_time_s"):
    assert key in doc, f"missing key {key}"
assert doc["quick"] is True and doc["stable_steps"] == [], "the quick set has no step search"
quick_cases = [c["name"] for c in doc["case_list"] if c["quick"]]
assert len(doc["cases"]) == len(quick_cases) * len(doc["engines"]), "one verdict per quick case and engine"
verdict = {}
for c in doc["cases"]:
    assert set(c) >= {"name", "engine", "verdict", "reason", "time_s"}, c
    assert c["verdict"] in ("ok", "refused", "failed"), c
    assert isinstance(c["time_s"], (int, float)) and c["time_s"] >= 0, c
    # Never a hang, a crash, NaN or a wrong answer; a refusal or a failure always says why.
    assert c["failure"] not in ("timed_out", "crashed", "nan", "wrong"), c
    if c["verdict"] != "ok":
        assert c["reason"], c
    verdict[(c["name"], c["engine"])] = c["verdict"]
assert doc["unsafe"] == 0
# The verdicts docs/guide/stress.md states for the quick set.
for name in quick_cases:
    assert verdict[(name, "analytic")] == "ok", (name, verdict[(name, "analytic")])
for e in doc["engines"]:
    if e != "analytic":
        assert verdict[("chattering-e0.05", e)] == "refused", e
PY

"$vssw" stress --quick --time-limit -1 >"$dir/bad.txt" 2>&1
code=$?
if [ "$code" -ne 2 ] || ! grep -q -- "--time-limit.*-1" "$dir/bad.txt"; then
  echo "FAIL: --time-limit -1 exited $code (expected 2 naming the value)"; cat "$dir/bad.txt"; exit 1
fi
"$vssw" stress --quick --engines nosuch >"$dir/bad.txt" 2>&1
code=$?
if [ "$code" -ne 2 ] || ! grep -q "nosuch" "$dir/bad.txt"; then
  echo "FAIL: --engines nosuch exited $code (expected 2 naming the engine)"; cat "$dir/bad.txt"; exit 1
fi
# [[stress]] bounds in vssw check: a verdict held (0), one out (1), a malformed bound or an unknown case (2).
check_with() {  # ALLOWED CASE -> exit code of vssw check
  printf 'suite = "default"\n[[stress]]\ncases = ["%s"]\nengines = ["analytic"]\nallowed = [%s]\n' "$2" "$1" >"$dir/b.toml"
  "$vssw" check --bounds "$dir/b.toml" >"$dir/check.txt" 2>&1
}
check_with '"ok"' release-1e-6-alpha;      c0=$?
check_with '"refused"' release-1e-6-alpha; c1=$?
check_with '"maybe"' release-1e-6-alpha;   c2=$?
check_with '"ok"' no-such-case;            c3=$?
if [ "$c0 $c1 $c2 $c3" != "0 1 2 2" ]; then
  echo "FAIL: vssw check with [[stress]] bounds exited $c0 $c1 $c2 $c3, expected 0 1 2 2"; cat "$dir/check.txt"; exit 1
fi
echo "ok: vssw stress --quick: $(python3 -c "import json,sys; d=json.load(open(sys.argv[1])); print(len(d['cases']), 'runs,', round(d['wall_time_s'],1), 's')" "$dir/stdout.json")"
