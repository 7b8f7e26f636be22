#!/usr/bin/env python3
"""Draws the documentation's measured figures from their committed CSV files, with gnuplot.

    scripts/doc_figures.py [--check] [--only NAME] [--csv FILE] [--page FILE] [--out DIR]
    scripts/doc_figures.py --from-report DIR

Each figure is a CSV of measured numbers (its first comment lines say where each number comes from and the command
that measured it), an SVG drawn from it, and the page whose table shows the same numbers:

- engine-cost-error: docs/data/engine-comparison.csv -> docs/img/engine-cost-error.svg, the table of docs/engines.md;
- work-precision: docs/data/work-precision.csv -> docs/img/work-precision.svg, the "Measured" table of
  docs/measurements/work-precision.md;
- suite-time: docs/data/suite-time.csv -> docs/img/suite-time.svg, the table of "Where the suite's time goes" on
  docs/measurements/speed.md.

Without --check it re-draws every SVG into docs/img/ (or --out). With --check it writes nothing there: it draws each
figure into a temporary folder and exits 1 naming every SVG that differs from the committed one and every number
(and verdict) of the CSV missing from its row of the page's table, so the figure cannot drift from the table it illustrates (the CTest
vssw_doc_figures). --from-report prints the engine comparison's measured columns from a `vssw report --out DIR`
folder's results.json (how the CSV's errors and verdicts were taken). --csv and --page replace the committed files
(--only names the figure), for the test that feeds the check a CSV the page does not show. Needs gnuplot (Debian gnuplot-nox, installed by
scripts/setup.sh).
"""
import argparse
import csv
import io
import json
import os
import pathlib
import re
import subprocess
import sys
import tempfile

REPO = pathlib.Path(__file__).resolve().parents[1]

# The plots' font, the one the program's own plots use (io/gnuplot.cpp, kPlotFont).
FONT = "sans,11"


def gp_string(text):
    """text as a gnuplot single-quoted string, as io::gp_string writes it (io/gnuplot.cpp): a quote doubled, a
    control character a space (gnuplot would end the string or the command there)."""
    return "'" + "".join(" " if ord(c) < 0x20 or c == "\x7f" else "''" if c == "'" else c for c in text) + "'"


def gp_data_string(text):
    """text as a double-quoted string of an inline data block, as io::gp_data_string writes it: gnuplot's data reader
    knows no escapes, so a double quote becomes a single one and a backslash a slash; a control character a space."""
    return '"' + "".join(" " if ord(c) < 0x20 or c == "\x7f" else "'" if c == '"' else "/" if c == "\\" else c
                         for c in text) + '"'


def read_csv(path):
    """The CSV's rows as dicts; lines starting with '#' are its notes on sources."""
    text = "".join(line for line in path.read_text(encoding="utf-8").splitlines(keepends=True)
                   if not line.startswith("#"))
    return list(csv.DictReader(io.StringIO(text)))


def engine_styles():
    """Each backend's colour and filled/open gnuplot point types, as its multibody/*/engine.cmake declares them."""
    styles = {}
    for cmake in sorted(REPO.glob("multibody/*/engine.cmake")):
        text = cmake.read_text(encoding="utf-8")
        for block in re.findall(r"vssw_engine(?:_backend)?\((.*?)\)\s*(?:\n\S|\Z)", text, re.S):
            name = re.search(r"NAME (\S+)", block)
            colour = re.search(r'COLOUR "(#[0-9A-Fa-f]{6})"', block)
            marker = re.search(r"MARKER (\d+) (\d+)", block)
            if name and colour and marker:
                styles[name.group(1)] = (colour.group(1), int(marker.group(1)), int(marker.group(2)))
    return styles


def log_log_preamble(svg_name, x_range, y_range, x_label, y_label, sample_length, targets):
    """The start of a log-log figure's gnuplot program: the SVG, its axes, the key right of the plot, and each target
    (value in %, its label, gnuplot's dash type, the label's place across the plot) as a grey horizontal line."""
    lines = [
        "set encoding utf8",
        f"set terminal svg size 760,460 noenhanced font '{FONT}' background rgb 'white'",
        f"set output '{svg_name}'",
        "set grid lc rgb '#dddddd'",
        "set logscale xy",
        f"set xrange [{x_range[0]}:{x_range[1]}]",
        f"set yrange [{y_range[0]}:{y_range[1]}]",
        "set format y '%g'",
        f"set xlabel '{x_label}'",
        f"set ylabel '{y_label}'",
        f"set key outside right top Left reverse box lc rgb '#cccccc' samplen {sample_length} spacing 1.1",
    ]
    for value, label, dash, across in targets:
        lines.append(f"set arrow from graph 0, first {value} to graph 1, first {value} nohead dt {dash} "
                     "lc rgb '#555555'")
        lines.append(f"set label '{label}' at graph {across}, first {value * 1.2:g} textcolor rgb '#555555'")
    return lines


def cost_error_program(rows, svg_name):
    """gnuplot's program for cost against error per engine: each engine's worst restitution error (filled) and worst
    period error (open), joined by a dotted line, on the default suite against its CPU per simulated second, the
    targets dashed."""
    styles = engine_styles()
    analytic_cost = next(float(r["cost_vssw_ms"]) for r in rows if r["engine"] == "analytic")
    lines = log_log_preamble(svg_name, (0.05, 200), (0.01, 10),
                             "CPU time per simulated second, Fig. 6 VSSW free vibration [ms]",
                             "largest |relative error| on the default suite [%]", 1,
                             [(2, "restitution target 2 %", 2, 0.02),
                              (0.5, "threshold and period target 0.5 %", 3, 0.02)])
    lines += [
        f"set arrow from first {analytic_cost}, graph 0 to first {analytic_cost}, graph 1 nohead dt 4 lc rgb '#555555'",
        f"set label 'the analytic model' at first {analytic_cost * 1.15}, graph 0.06 textcolor rgb '#555555'",
    ]
    plots = []
    for r in (r for r in rows if r["engine"] != "analytic"):
        colour, filled, hollow = styles[r["engine"]]
        cost = float(r["cost_vssw_ms"])
        restitution, period = abs(float(r["restitution_pct"])), abs(float(r["period_pct"]))
        data = "$" + r["engine"].replace("-", "_")
        lines.append(f"{data} << EOD\n{cost} {restitution} {period}\nEOD")
        plots.append(f"{data} using 1:3:(0):($2-$3) with vectors nohead dt 3 lc rgb '{colour}' notitle")
        plots.append(f"{data} using 1:2 with points pt {filled} ps 1.6 lc rgb '{colour}' "
                     f"title {gp_string(r['display'] + ': restitution')}")
        plots.append(f"{data} using 1:3 with points pt {hollow} ps 1.6 lc rgb '{colour}' title 'period'")
        plots.append(f"{data} using 1:2:({gp_string(r['display'])}) with labels offset char 0.8, char 0.7 left "
                     "textcolor rgb '#333333' notitle")
    lines.append("plot " + ", \\\n     ".join(plots))
    return "\n".join(lines) + "\n"


def work_precision_program(rows, svg_name):
    """gnuplot's program for vssw bench's sweep: each engine's largest period error (filled, solid) and restitution
    error (open, dashed) through its settings against the CPU time summed over the bench's four problems."""
    styles = engine_styles()
    lines = log_log_preamble(svg_name, (0.08, 30), (0.005, 10),
                             "CPU time over the threshold and three free vibrations [s]",
                             "largest |relative error| [%]", 2,
                             [(2, "restitution target 2 %", 2, 0.55), (0.5, "period target 0.5 %", 3, 0.55)])
    plots = []
    for index, engine in enumerate(dict.fromkeys(r["engine"] for r in rows if r["engine"] != "analytic")):
        colour, filled, hollow = styles[engine]
        points = sorted((float(r["cpu_s"]), r["period_pct"], r["restitution_pct"], r["setting"])
                        for r in rows if r["engine"] == engine)
        block = "$" + engine.replace("-", "_")
        data = "\n".join(f"{c} {p} {e} {gp_data_string(label)}" for c, p, e, label in points)
        lines.append(f"{block} << EOD\n{data}\nEOD")
        plots.append(f"{block} using 1:2 with linespoints pt {filled} ps 1.4 lw 1.5 lc rgb '{colour}' "
                     f"title {gp_string(engine + ': period')}")
        plots.append(f"{block} using 1:3 with linespoints pt {hollow} ps 1.4 dt 2 lc rgb '{colour}' "
                     "title 'restitution'")
        above = 0.9 if index % 2 else -0.8  # alternate engines' setting labels above and below their points
        plots.append(f"{block} using 1:2:4 with labels offset char 0.6, char {above} left font 'sans,9' "
                     "textcolor rgb '#555555' notitle")
    lines.append("plot " + ", \\\n     ".join(plots))
    return "\n".join(lines) + "\n"


def suite_time_program(rows, svg_name):
    """gnuplot's program for where the default suite's CPU goes: one bar per case kind, stacked by engine."""
    styles = engine_styles()
    engines = [("bullet", "Bullet"), ("ode", "ODE"), ("simbody", "Simbody (compliant)")]
    lines = [
        "set encoding utf8",
        f"set terminal svg size 760,400 noenhanced font '{FONT}' background rgb 'white'",
        f"set output '{svg_name}'",
        "set grid ytics lc rgb '#dddddd'",
        "set style data histograms",
        "set style histogram rowstacked",
        "set style fill solid 0.85 border rgb '#333333'",
        "set boxwidth 0.6",
        "set yrange [0:*]",
        "set xrange [-0.6:3.6]",
        "set ylabel 'task CPU time [s]'",
        "set xlabel 'case kind of the default suite'",
        "set key outside right top Left reverse box lc rgb '#cccccc'",
        "$suite << EOD",
    ]
    # The bar's label is the kind's name without the page's count ("threshold (11 walls)": threshold).
    lines += [gp_data_string(r["kind"].split(" (")[0]) + " " + " ".join(r[f"{e}_s"] for e, _ in engines) for r in rows]
    lines.append("EOD")
    plots = [f"$suite using {i + 2}{':xtic(1)' if i == 0 else ''} lc rgb '{styles[e][0]}' title {gp_string(title)}"
             for i, (e, title) in enumerate(engines)]
    lines.append("plot " + ", \\\n     ".join(plots))
    return "\n".join(lines) + "\n"


def table_rows(page):
    """The cells of every table row of the page."""
    rows = []
    for line in page.read_text(encoding="utf-8").splitlines():
        if line.startswith("|"):
            rows.append([c.strip() for c in line.strip().strip("|").split("|")])
    return rows


def shown_as_in_table(value):
    """A CSV number as the page's tables write it: the minus as U+2212."""
    return value.replace("-", "\u2212") if value.startswith("-") else value


def rows_mismatch(rows, page, key, label, numbers):
    """Every number (or verdict) of the CSV that its row of the page's table does not show, named. A CSV row's table row is the
    one whose first cell is key(row)[0] and whose next cells start with the rest (bold marks ignored); numbers are
    the CSV columns that row must show."""
    problems = []
    table = table_rows(page)
    for r in rows:
        wanted = key(r)
        found = [cells for cells in table
                 if len(cells) >= len(wanted)
                 and cells[0].replace("**", "") == wanted[0]
                 and all(c.replace("**", "").startswith(w) for c, w in zip(cells[1:], wanted[1:]))]
        if not found:
            problems.append(f"{page.name}: no table row for {label(r)}")
            continue
        text = " | ".join(found[0])
        for column in numbers:
            shown = re.escape(shown_as_in_table(r[column]))
            if r[column] and not re.search(rf"(?<![\d.]){shown}(?![\d])", text):
                problems.append(f"{page.name}: the row of {label(r)} does not show {column} = {r[column]}")
    return problems


def cost_error_mismatches(rows, page):
    return rows_mismatch(rows, page, lambda r: [r["display"]], lambda r: r["display"],
                         ("threshold_pct", "period_pct", "restitution_pct", "cost_vssw_ms", "step_us", "peak_ratio",
                          "records"))


def work_precision_mismatches(rows, page):
    return rows_mismatch(rows, page, lambda r: [r["engine"], r["setting"]], lambda r: f"{r['engine']} {r['setting']}",
                         ("cpu_s", "threshold_pct", "period_pct", "restitution_pct"))


def suite_time_mismatches(rows, page):
    return rows_mismatch(rows, page, lambda r: [r["kind"]], lambda r: r["kind"],
                         ("bullet_s", "ode_s", "simbody_s", "all_s"))


def report_columns(folder):
    """The engine comparison's columns measured by `vssw report`: each engine's worst signed relative error in % on
    threshold, period and restitution (results.json `matrix`), and under records the median peak ratio and whether
    both verdicts pass (`earthquake.engines`)."""
    results = json.loads((pathlib.Path(folder) / "results.json").read_text(encoding="utf-8"))
    worst = {(m["engine"], m["metric"]): m for m in results["matrix"]}
    quake = {e["engine"]: e for e in (results.get("earthquake") or {}).get("engines", [])}
    print(f"# vssw {results['vssw']['commit']}, {results['date']}")
    print("engine,threshold_pct,period_pct,restitution_pct,peak_ratio,records")
    for engine in dict.fromkeys(m["engine"] for m in results["matrix"]):
        cells = []
        for metric in ("threshold_g", "period", "restitution"):
            m = worst.get((engine, metric))
            cells.append("" if m is None or m["worst_error"] is None else f"{100 * m['worst_error']:#.3g}")
        e = quake.get(engine, {})
        ratio = (e.get("peak_log_ratio") or {}).get("median_ratio")
        cells += ["" if ratio is None else f"{ratio:.3f}", {True: "pass", False: "FAIL"}.get(e.get("pass"), "")]
        print(",".join([engine] + cells))


FIGURES = {
    "engine-cost-error": {"csv": "docs/data/engine-comparison.csv", "svg": "docs/img/engine-cost-error.svg",
                          "page": "docs/engines.md", "program": cost_error_program,
                          "mismatches": cost_error_mismatches},
    "work-precision": {"csv": "docs/data/work-precision.csv", "svg": "docs/img/work-precision.svg",
                       "page": "docs/measurements/work-precision.md", "program": work_precision_program,
                       "mismatches": work_precision_mismatches},
    "suite-time": {"csv": "docs/data/suite-time.csv", "svg": "docs/img/suite-time.svg",
                   "page": "docs/measurements/speed.md", "program": suite_time_program,
                   "mismatches": suite_time_mismatches},
}


def draw(figure, rows, out_dir):
    """Runs gnuplot on the figure's program in a temporary folder inside out_dir and renames the SVG into out_dir, so
    a gnuplot that fails half-way leaves the SVG there was; returns the SVG's path."""
    svg = pathlib.Path(out_dir) / pathlib.Path(figure["svg"]).name
    with tempfile.TemporaryDirectory(dir=out_dir) as tmp:  # in out_dir: one file system, so the rename is whole
        subprocess.run(["gnuplot"], input=figure["program"](rows, svg.name), text=True, cwd=tmp, check=True)
        os.replace(pathlib.Path(tmp) / svg.name, svg)
    return svg


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--check", action="store_true", help="compare with the committed SVGs and pages; write nothing")
    parser.add_argument("--only", choices=sorted(FIGURES), help="one figure")
    parser.add_argument("--csv", type=pathlib.Path, help="this CSV instead of the committed one (with --only)")
    parser.add_argument("--page", type=pathlib.Path, help="this page instead of the committed one (with --only)")
    parser.add_argument("--out", type=pathlib.Path, help="write the SVGs here instead of docs/img/")
    parser.add_argument("--from-report", type=pathlib.Path, help="print the measured columns of a vssw report folder")
    args = parser.parse_args()
    if args.from_report:
        report_columns(args.from_report)
        return 0
    if (args.csv or args.page) and not args.only:
        parser.error("--csv and --page need --only")
    problems = []
    for name, figure in FIGURES.items():
        if args.only and name != args.only:
            continue
        csv_path = args.csv or REPO / figure["csv"]
        rows = read_csv(csv_path)
        page = args.page or REPO / figure["page"]
        committed = REPO / figure["svg"]
        if args.check:
            with tempfile.TemporaryDirectory() as tmp:
                if not committed.exists():
                    problems.append(f"{figure['svg']}: missing (run scripts/doc_figures.py and commit the SVG)")
                elif draw(figure, rows, tmp).read_bytes() != committed.read_bytes():
                    problems.append(f"{figure['svg']}: differs from what {csv_path} draws "
                                    "(run scripts/doc_figures.py and commit the SVG)")
            problems += figure["mismatches"](rows, page)
        else:
            out = args.out or committed.parent
            out.mkdir(parents=True, exist_ok=True)
            print(draw(figure, rows, out))
    for p in problems:
        print(p)
    if args.check:
        print(f"doc figures: {len(problems)} problem(s)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
