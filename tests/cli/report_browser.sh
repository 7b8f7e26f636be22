#!/bin/bash
# The report and a study as a reader sees them: report.html and study.html rendered by headless Chromium (Debian package
# `chromium`), failing on a JavaScript error, an image that does not load, a figure without its plot drawn, a contents
# link without its anchor, or a plot point left with gnuplot's script hover handler (onmousemove calling a gnuplot_svg
# the pages do not load: an error on every hover). A copy of the page gets a small script at the top of its <head> that
# records every error event (scripts and resources alike, caught in the capture phase) and, once the page has loaded,
# writes what it found into the DOM, which Chromium dumps; it counts the plots and the points' native hover texts
# (<title> in a plot's group: io/gnuplot.hpp), of which each page must have some when gnuplot is installed. A
# deliberately broken copy (an <img> whose file is missing, a script calling an undefined function, a point with
# gnuplot's handler) must fail the same check naming all three, or the check could not fail at all. About 15 s, three
# renders.
# Usage: report_browser.sh path/to/vssw path/to/data work_dir        Exit 0 ok, 1 failed, 77 skipped (no chromium).
set -u
vssw=$1
data=$2
work=$3

chromium=$(command -v chromium || command -v chromium-browser || true)
if [ -z "$chromium" ]; then
    echo "SKIP: chromium is not installed (Debian package chromium; scripts/setup.sh test installs it)"
    exit 77
fi
rm -rf "$work"
mkdir -p "$work"

# A small report: the Fig. 6 VSSW released at 0.5 alpha (a trace with both analytic impact laws) and the PW's
# threshold, with ODE, and a small earthquake part (its verdict table and plots from ../earthquake/; a few seconds).
if ! "$vssw" report --engines ode --cases fig6-vssw/r0.5,fig6-pw --data "$data" --out "$work/report" \
        --earthquake "$(dirname "$0")/earthquake_small.toml" >"$work/report.log" 2>&1; then
    echo "FAIL: vssw report failed:"; cat "$work/report.log"; exit 1
fi

checker='<script>
window.vsswProblems = [];
window.addEventListener("error", function (e) {
  var t = e.target;
  window.vsswProblems.push(t && t !== window && (t.src || t.href) ? "did not load: " + (t.getAttribute("src") || t.href)
                                                                 : "script error: " + e.message);
}, true);
window.addEventListener("load", function () {
  var p = window.vsswProblems.slice();
  document.querySelectorAll("img").forEach(function (img) {
    if (!img.complete || img.naturalWidth === 0) p.push("image not shown: " + img.getAttribute("src"));
  });
  document.querySelectorAll("[onmousemove]").forEach(function (g) {
    p.push("script hover handler: " + g.getAttribute("onmousemove").slice(0, 60));
  });
  var hovers = 0;
  document.querySelectorAll("figure svg g > title").forEach(function (t) { if (t.textContent.trim()) hovers++; });
  var plots = 0;
  document.querySelectorAll("figure").forEach(function (f, i) {
    var svg = f.querySelector("svg"), r = svg ? svg.getBoundingClientRect() : null;
    if (!svg && !f.querySelector("img")) p.push("figure " + i + " holds no plot: " + f.textContent.slice(0, 80));
    else if (svg && (r.width < 300 || r.height < 100)) p.push("figure " + i + " drawn at " + r.width + " x " + r.height);
    else plots++;
  });
  document.querySelectorAll("a[href^=\"#\"]").forEach(function (a) {
    if (!document.getElementById(decodeURIComponent(a.getAttribute("href").slice(1))))
      p.push("link without its anchor: " + a.getAttribute("href"));
  });
  var out = document.createElement("pre");
  out.textContent = p.length ? "VSSW-CHECK FAIL\n" + p.join("\n")
                             : "VSSW-CHECK OK hovers=" + hovers + " plots=" + plots;
  document.body.appendChild(out);
});
</script>'

# instrument IN OUT [EXTRA]: the page with the checker first in its <head>, EXTRA (HTML) at the top of its <body>.
instrument() {
    CHECKER="$checker" EXTRA="${3:-}" awk '{ print } /^<head>$/ { print ENVIRON["CHECKER"] }
                                            /^<body>$/ { if (ENVIRON["EXTRA"] != "") print ENVIRON["EXTRA"] }' \
        "$1" >"$2"
}

# render PAGE: Chromium's DOM of the page after load, the checker's verdict in it.
render() {
    timeout 60 "$chromium" --headless --disable-gpu --no-sandbox --no-first-run --disable-extensions \
        --user-data-dir="$work/profile" --window-size=1280,1024 --virtual-time-budget=5000 \
        --dump-dom "file://$1" >"$1.dom" 2>"$1.log"
    # The checker's <pre> (not its own script's text, which names the same words).
    sed -n '/^<pre>VSSW-CHECK/,/<\/pre>/p' "$1.dom" | sed 's/^<pre>//; s/<\/pre>.*//'
}

failures=0
if ! grep -q 'id="under-earthquake-records"' "$work/report/report.html"; then
    echo "FAIL: report.html has no section \"Under earthquake records\""; failures=$((failures + 1))
fi

# A small study (study_small.toml: analytic runs only, under a second) for study.html: value plots and tornado charts.
if ! "$vssw" study "$(dirname "$0")/study_small.toml" --out "$work/study" >"$work/study.log" 2>&1; then
    echo "FAIL: vssw study failed:"; cat "$work/study.log"; exit 1
fi

# check PAGE: the checker's verdict on the page, which must be OK, with plots and hover texts when gnuplot is there.
check() {
    local page=$1 checked verdict
    checked="$(dirname "$page")/checked.html"
    instrument "$page" "$checked"
    verdict=$(render "$checked")
    case "$verdict" in
        "VSSW-CHECK OK"*)
            echo "$(basename "$page"): $verdict"
            if command -v gnuplot >/dev/null; then
                case "$verdict" in
                    *" plots=0"|*"hovers=0 "*)
                        echo "FAIL: gnuplot is installed but $(basename "$page") shows no plot or no hover text"
                        failures=$((failures + 1)) ;;
                esac
            fi ;;
        *)  echo "FAIL: $(basename "$page") in Chromium:"; echo "${verdict:-(no verdict: the checker did not run)}"
            tail -20 "$checked.log"; failures=$((failures + 1)) ;;
    esac
}
check "$work/report/report.html"
check "$work/study/study.html"

# The check must be able to fail: a copy with a missing image, a script error and a point with gnuplot's hover handler
# must fail it, naming all three.
instrument "$work/report/report.html" "$work/report/broken.html" \
    '<img src="plots/no_such_plot.svg" alt="missing"><script>vsswNoSuchFunction();</script>
<svg><g onmousemove="gnuplot_svg.showHypertext(evt,'"'x'"')"><circle r="3"/></g></svg>'
verdict=$(render "$work/report/broken.html")
for expected in "VSSW-CHECK FAIL" "did not load: plots/no_such_plot.svg" "script error: Uncaught ReferenceError" \
                "script hover handler: gnuplot_svg.showHypertext"; do
    case "$verdict" in
        *"$expected"*) ;;
        *) echo "FAIL: the broken copy's verdict lacks '$expected' (${verdict:-no verdict}): the check cannot fail"
           failures=$((failures + 1)) ;;
    esac
done
[ "$failures" -eq 0 ] && echo "broken.html fails as it must: $(echo "$verdict" | tail -n +2 | tr '\n' ';')"

[ "$failures" -eq 0 ] || exit 1
rm -rf "$work"
echo "ok"
