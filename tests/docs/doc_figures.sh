#!/usr/bin/env bash
# The documentation's measured figures (scripts/doc_figures.py): each committed SVG is what its committed CSV draws,
# and every number of the CSV is in its page's table, so a figure cannot drift from the table beside it. Then the
# check is fed a CSV whose one number the page does not show, and must fail naming both the SVG and the number; a
# text with quotes must draw, a failing gnuplot must leave the SVG there was, and --from-report must read the
# results.json the program writes today. Skipped (exit 77) only without gnuplot: scripts/setup.sh installs
# gnuplot-nox, so CI has it.
#   tests/docs/doc_figures.sh SOURCE_DIR VSSW
set -euo pipefail
src="$1"
vssw="$2"
if ! command -v gnuplot >/dev/null; then
  echo "SKIPPED: gnuplot is not installed (Debian gnuplot-nox; bash scripts/setup.sh test installs it)"
  exit 77
fi
/usr/bin/python3 "$src/scripts/doc_figures.py" --check
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
# ODE's restitution error -0.594 made -0.694: a number the page's table does not show, and another figure.
sed 's/^ode,\(.*\),-0\.594,/ode,\1,-0.694,/' "$src/docs/data/engine-comparison.csv" >"$out/changed.csv"
if cmp -s "$out/changed.csv" "$src/docs/data/engine-comparison.csv"; then
  echo "FAIL: the test's change to the CSV did not apply (ODE's restitution is no longer -0.594?)"; exit 1
fi
if /usr/bin/python3 "$src/scripts/doc_figures.py" --check --only engine-cost-error --csv "$out/changed.csv" \
    >"$out/changed.txt"; then
  echo "FAIL: doc_figures.py --check passed a CSV that neither the figure nor the page shows"; exit 1
fi
for expected in "docs/img/engine-cost-error.svg: differs" "the row of ODE does not show restitution_pct = -0.694"; do
  if ! grep -qF "$expected" "$out/changed.txt"; then
    echo "FAIL: the check did not say \"$expected\":"; cat "$out/changed.txt"; exit 1
  fi
done
# The work-precision table's check too: ODE's CPU at 1 ms, 0.127 s, made 0.128 s.
sed 's/^ode,dt 1 ms,0\.127,/ode,dt 1 ms,0.128,/' "$src/docs/data/work-precision.csv" >"$out/wp.csv"
if /usr/bin/python3 "$src/scripts/doc_figures.py" --check --only work-precision --csv "$out/wp.csv" >"$out/wp.txt" ||
    ! grep -qF "the row of ode dt 1 ms does not show cpu_s = 0.128" "$out/wp.txt"; then
  echo "FAIL: the work-precision check did not refuse a CPU time its table does not show:"; cat "$out/wp.txt"; exit 1
fi
# And the suite split's: Simbody's free-vibration CPU, 7.48 s, made 7.49 s.
sed 's/^free (15 cases),0\.19,0\.15,7\.48,/free (15 cases),0.19,0.15,7.49,/' "$src/docs/data/suite-time.csv" >"$out/st.csv"
if /usr/bin/python3 "$src/scripts/doc_figures.py" --check --only suite-time --csv "$out/st.csv" >"$out/st.txt" ||
    ! grep -qF "the row of free (15 cases) does not show simbody_s = 7.49" "$out/st.txt"; then
  echo "FAIL: the suite-time check did not refuse a CPU time its table does not show:"; cat "$out/st.txt"; exit 1
fi
# The records verdict is checked too: ODE's "pass" made "FAIL".
sed 's/^ode,\(.*\),pass,/ode,\1,FAIL,/' "$src/docs/data/engine-comparison.csv" >"$out/records.csv"
if /usr/bin/python3 "$src/scripts/doc_figures.py" --check --only engine-cost-error --csv "$out/records.csv" \
    >"$out/records.txt" || ! grep -qF "the row of ODE does not show records = FAIL" "$out/records.txt"; then
  echo "FAIL: the check did not refuse a records verdict its table does not show:"; cat "$out/records.txt"; exit 1
fi
# A display name with both quotes and a backslash is drawn (escaped as io::gp_string and io::gp_data_string escape).
sed 's/^ode,ODE,/ode,O'"'"'D"E\\,/' "$src/docs/data/engine-comparison.csv" >"$out/quoted.csv"
mkdir "$out/svg"
/usr/bin/python3 "$src/scripts/doc_figures.py" --only engine-cost-error --csv "$out/quoted.csv" --out "$out/svg" >/dev/null
grep -qF "O'D\"E\\: restitution" "$out/svg/engine-cost-error.svg" ||
  { echo "FAIL: the display name with quotes is not in the SVG"; exit 1; }
# A gnuplot that fails half-way through its output leaves the SVG there was.
mkdir "$out/bin"
cat >"$out/bin/gnuplot" <<'EOF'
#!/bin/sh
# Starts the SVG its program names, then fails.
echo '<svg partial' >"$(sed -n "s/^set output '\(.*\)'$/\1/p")"
exit 1
EOF
chmod +x "$out/bin/gnuplot"
cp "$out/svg/engine-cost-error.svg" "$out/before.svg"
if PATH="$out/bin:$PATH" /usr/bin/python3 "$src/scripts/doc_figures.py" --only engine-cost-error --out "$out/svg" \
    >/dev/null 2>&1 || ! cmp -s "$out/before.svg" "$out/svg/engine-cost-error.svg"; then
  echo "FAIL: a failing gnuplot did not fail the script, or changed the SVG there was"; exit 1
fi
# --from-report on a one-case report of today's program: the matrix's key read, ODE's threshold error printed.
"$vssw" report --suite default --engines ode --cases fig6-vssw --no-plots --out "$out/report" >/dev/null
/usr/bin/python3 "$src/scripts/doc_figures.py" --from-report "$out/report" >"$out/columns.txt" &&
  grep -qE '^ode,[0-9.e-]+,' "$out/columns.txt" ||
  { echo "FAIL: --from-report did not read the report's results.json:"; cat "$out/columns.txt"; exit 1; }
echo "doc figures: every SVG is its CSV's, every CSV number is in its page's table; a changed CSV is caught"
