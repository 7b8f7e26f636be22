#!/bin/sh
# End-to-end check of the installed-style program (the GoogleTest suite runs the same code in-process): exit codes,
# which stream gets what, and that --json output is JSON. Usage: smoke.sh path/to/vssw path/to/data
set -u
vssw=$1
data=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0
wall="--height 4 --thickness 0.4 --hinge 0.7"

fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# expect CODE STDERR_LINES ARGS...: runs vssw with ARGS, checks the exit code and the number of lines on stderr.
expect() {
    code=$1; err_lines=$2; shift 2
    "$vssw" "$@" >"$tmp/out" 2>"$tmp/err"
    got=$?
    [ "$got" -eq "$code" ] || fail "vssw $*: exit $got, expected $code"
    lines=$(wc -l <"$tmp/err")
    [ "$lines" -eq "$err_lines" ] || fail "vssw $*: $lines line(s) on stderr, expected $err_lines: $(cat "$tmp/err")"
}

expect 0 0 --help
grep -q "Usage" "$tmp/out" || fail "--help prints no usage"
expect 2 1
grep -q "^vssw: error: " "$tmp/err" || fail "no command: message is not 'vssw: error: ...'"
expect 2 1 wall --height 4 --thickness -0.2 --hinge 0.7
grep -q -- "-0.2" "$tmp/err" || fail "negative thickness: the message does not name -0.2"
expect 2 1 free $wall --theta0 nan
expect 2 1 history $wall --record "$tmp/missing.AT2"

for command in "wall $wall" "free $wall --theta0 0.5" "history $wall --record $data/NGA_no_1063_RRS228.AT2" "summary"; do
    # shellcheck disable=SC2086  # word splitting of $command is intended
    expect 0 0 $command --json
    if command -v python3 >/dev/null 2>&1; then
        python3 -m json.tool "$tmp/out" >/dev/null || fail "vssw $command --json: output is not JSON"
    fi
done

expect 0 0 history $wall --record "$data/NGA_no_1063_RRS228.AT2" --csv "$tmp/out.csv"
[ "$(head -n 1 "$tmp/out.csv")" = "t,theta1_over_alpha1,theta_dot_over_ref,E_over_Vr,ED_over_Vr,ag_g" ] ||
    fail "CSV header: $(head -n 1 "$tmp/out.csv")"

# The report on one quick case (the analytic model only, no plots): files written, JSON valid; a file as --out is
# bad input.
expect 0 0 report --engines analytic --cases fig6-pw --no-plots --out "$tmp/report"
for f in report.md report.html results.json metrics.csv failures.csv traces.csv; do
    [ -s "$tmp/report/$f" ] || fail "vssw report: $f missing or empty"
done
if command -v python3 >/dev/null 2>&1; then
    python3 -m json.tool "$tmp/report/results.json" >/dev/null || fail "vssw report: results.json is not JSON"
fi
grep -q "$tmp/report/report.html" "$tmp/out" || fail "vssw report does not print where the report is"
expect 2 1 report --engines analytic --cases fig6-pw --out "$tmp/out.csv"

[ "$failures" -eq 0 ] && echo "vssw smoke test: all checks passed"
exit "$failures"
