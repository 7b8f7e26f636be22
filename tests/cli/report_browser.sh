#!/bin/bash
# The report, a study and the documentation site as a reader sees them: report.html, study.html and every page of the
# MkDocs site rendered by headless Chromium (Debian package `chromium`). Each page gets tests/cli/page_checker.js first
# in its <head>: it records script and resource errors and console.error calls, and once the page has loaded writes
# its verdict into the DOM: an image or object not shown, a figure without its plot, a contents link without its
# anchor, a plot point with gnuplot's script hover handler (an error on every hover), a table wider than its container
# outside a scrolling box (cut at the page's edge), a number in a table cell broken over two lines. Chromium dumps the
# DOM; for the site, one harness page loads each page in turn in a frame of the page's width and gathers the verdicts
# (one browser start for 46 pages). The report and the study must show plots and hover texts when gnuplot is installed.
# A deliberately broken copy (a missing image and object, a script error, a console error, a point with gnuplot's
# handler, a wide table without a scrolling box, a number wrapped mid-exponent) must fail the check naming each, both
# alone and in the site's harness, or the check could not fail at all. About 20 s: four renders and a site build.
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

here=$(cd "$(dirname "$0")" && pwd)
src=$(cd "$here/../.." && pwd)
checker="<script>
$(cat "$here/page_checker.js")
</script>"

# instrument IN OUT [EXTRA]: the page with the checker first in its <head>, EXTRA (HTML) at the top of its <body>.
# (index(), not sub(): the script holds '&', which sub() would replace by the match.)
instrument() {
    CHECKER="$checker" EXTRA="${3:-}" awk '
        !head && (i = index($0, "<head>")) { print substr($0, 1, i + 5); print ENVIRON["CHECKER"];
                                              print substr($0, i + 6); head = 1; next }
        !body && (i = index($0, "<body")) { j = i + index(substr($0, i), ">") - 1; print substr($0, 1, j);
                                             if (ENVIRON["EXTRA"] != "") print ENVIRON["EXTRA"];
                                             print substr($0, j + 1); body = 1; next }
        { print }' "$1" >"$2"
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

# The check must be able to fail: a copy with each fault a reader would meet must fail it, naming each.
broken_html='<img src="plots/no_such_plot.svg" alt="missing"><object data="plots/no_such_object.svg"></object>
<script>vsswNoSuchFunction();</script><script>console.error("vssw broken on purpose");</script>
<svg><g onmousemove="gnuplot_svg.showHypertext(evt,'"'x'"')"><circle r="3"/></g></svg>
<div><table><tr><td>VSSW-WIDE-TABLE</td>'"$(for i in $(seq 40); do printf '<td>+1.234e-05 %%</td>'; done)"'</tr>
</table></div>
<table style="width: 4em"><tr><td style="width: 4em; white-space: normal">1.2345e-05</td></tr></table>'
broken_expected=("VSSW-CHECK FAIL" "did not load: plots/no_such_plot.svg" "object not shown: plots/no_such_object.svg"
                 "script error: Uncaught ReferenceError" "console error: vssw broken on purpose"
                 "script hover handler: gnuplot_svg.showHypertext" "not in a scrolling box: VSSW-WIDE-TABLE"
                 "number broken over lines in a table cell: 1.2345e-")
# expect_broken NAME VERDICT [SKIP]: the verdict names every fault of the broken copy (but SKIP).
expect_broken() {
    local expected
    for expected in "${broken_expected[@]}"; do
        [ "$expected" = "${3:-}" ] && continue
        case "$2" in
            *"$expected"*) ;;
            *) echo "FAIL: $1's verdict lacks '$expected' (${2:-no verdict}): the check cannot fail"
               failures=$((failures + 1)) ;;
        esac
    done
}
instrument "$work/report/report.html" "$work/report/broken.html" "$broken_html"
verdict=$(render "$work/report/broken.html")
before=$failures
expect_broken broken.html "$verdict"
[ "$failures" -eq "$before" ] && echo "broken.html fails as it must: $(echo "$verdict" | tail -n +2 | tr '\n' ';' | cut -c1-300)"

# The site: built as `vssw_docs` builds it, every page checked in a frame 1280 px wide by one harness page, and a
# broken page among them that must fail.
if command -v mkdocs >/dev/null; then
    (cd "$src" && mkdocs build --quiet -f "$src/mkdocs.yml" -d "$work/site") >"$work/site.log" 2>&1 ||
        { echo "FAIL: mkdocs build failed:"; cat "$work/site.log"; exit 1; }
    # The site's tables are prose: a number may break there as a word does (page_checker.js).
    site_checker="<script>window.vsswSkipNumbers = true;</script>
$checker"
    pages=()
    while IFS= read -r page; do
        [ "$page" = "404.html" ] && continue  # its links are the server's, absolute: not a page to open from disk
        checker="$site_checker" instrument "$work/site/$page" "$work/site/$page.checked.html"
        pages+=("$page.checked.html")
    done < <(cd "$work/site" && find . -name '*.html' ! -path './assets/*' | sed 's|^\./||' | sort)
    checker="$site_checker" instrument "$work/site/index.html" "$work/site/broken.checked.html" "$broken_html"
    pages+=("broken.checked.html")
    list=$(printf '"%s",' "${pages[@]}")
    cat >"$work/site/harness.html" <<HARNESS
<!DOCTYPE html><html><head><meta charset="utf-8"></head><body>
<iframe id="page" style="width: 1280px; height: 1024px; border: 0"></iframe>
<script>
var pages = [${list%,}], verdicts = [], at = 0, frame = document.getElementById("page");
function next() {
  if (at === pages.length) {
    var out = document.createElement("pre");
    out.textContent = "VSSW-SITE\n" + verdicts.join("\n") + "\nVSSW-SITE-END";
    document.body.appendChild(out);
    return;
  }
  var page = pages[at++];
  frame.onload = function () {
    setTimeout(function () {
      var v;
      try { v = frame.contentWindow.vsswVerdict || "no verdict: the checker did not run"; }
      catch (e) { v = "no verdict: " + e.message; }
      verdicts.push("PAGE " + page.replace(/\.checked\.html\$/, "") + ": " + v.replace(/\n/g, "\n  "));
      next();
    }, 50);
  };
  frame.src = page;
}
next();
</script></body></html>
HARNESS
    timeout 120 "$chromium" --headless --disable-gpu --no-sandbox --no-first-run --disable-extensions \
        --allow-file-access-from-files --user-data-dir="$work/profile" --window-size=1300,1100 \
        --virtual-time-budget=120000 --dump-dom "file://$work/site/harness.html" >"$work/site/harness.dom" \
        2>"$work/site/harness.log"
    verdicts=$(sed -n '/VSSW-SITE$/,/VSSW-SITE-END/p' "$work/site/harness.dom")
    checked=$(grep -c '^PAGE ' <<<"$verdicts")
    if [ "$checked" -ne "${#pages[@]}" ]; then
        echo "FAIL: the site's harness checked $checked of ${#pages[@]} pages"; tail -20 "$work/site/harness.log"
        failures=$((failures + 1))
    fi
    # Each page's verdict: OK, but the broken page's, which must name every fault.
    site_bad=$(grep '^PAGE ' <<<"$verdicts" | grep -v '^PAGE broken: ' | grep -v ': VSSW-CHECK OK' || true)
    if [ -n "$site_bad" ]; then
        echo "FAIL: pages of the site in Chromium:"
        awk '/^PAGE / { show = !/^PAGE broken: / && !/: VSSW-CHECK OK/ } show' <<<"$verdicts"
        failures=$((failures + 1))
    else
        echo "site: $((checked - 1)) pages: VSSW-CHECK OK"
    fi
    expect_broken "the site's broken page" "$(awk '/^PAGE / { show = /^PAGE broken: / } show' <<<"$verdicts")" \
        "${broken_expected[7]}"
else
    echo "site: not checked (mkdocs is not installed; scripts/setup.sh test installs it)"
fi

[ "$failures" -eq 0 ] || exit 1
rm -rf "$work"
echo "ok"
