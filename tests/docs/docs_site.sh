#!/usr/bin/env bash
# The documentation site (docs/contributing/docs.md): the committed reference pages are what the program prints
# today (scripts/gen_reference.py --check), `mkdocs build --strict` builds the site without a warning (a broken
# link, a page missing from the navigation), every link's anchor exists (tests/docs/check_anchors.py) and the site
# needs no network: MathJax copied in for its equations (tests/docs/check_site_offline.py). Skipped (exit 77) only when mkdocs is not installed: scripts/setup.sh installs it, so CI has it.
#   tests/docs/docs_site.sh VSSW SOURCE_DIR
set -euo pipefail
vssw="$1"
src="$2"
/usr/bin/python3 "$src/scripts/gen_reference.py" --vssw "$vssw" --check
if ! command -v mkdocs >/dev/null; then
  echo "SKIPPED: mkdocs is not installed (Debian mkdocs and mkdocs-material; bash scripts/setup.sh test installs them)"
  exit 77
fi
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
cd "$src"
mkdocs build --strict --quiet -f "$src/mkdocs.yml" -d "$out/site"
test -s "$out/site/index.html"
test -s "$out/site/reference/commands.html"
# Anchors, which MkDocs 1.4 does not check: every page#part link of the site reaches an id.
/usr/bin/python3 "$src/tests/docs/check_anchors.py" "$out/site"
# ... and the check can fail: a two-page site whose link names an anchor its target lacks.
mkdir -p "$out/broken"
printf '<h1 id="top">A</h1><a href="b.html#gone">b</a> <a href="b.html#here">b</a>\n' >"$out/broken/a.html"
printf '<h2 id="here">B</h2>\n' >"$out/broken/b.html"
if /usr/bin/python3 "$src/tests/docs/check_anchors.py" "$out/broken" >"$out/broken.txt"; then
  echo "FAIL: check_anchors.py passed a link to a missing anchor"; exit 1
fi
if ! grep -q "a.html: b.html#gone" "$out/broken.txt"; then
  echo "FAIL: the broken anchor was not named:"; cat "$out/broken.txt"; exit 1
fi
# Offline equations: every script and stylesheet of every page is the site's own (MathJax copied in, no CDN, no web
# fonts), and the model's pages hold equations marked for MathJax.
/usr/bin/python3 "$src/tests/docs/check_site_offline.py" "$out/site" model/analytic-core.html model/top-support.html \
  model/paper.html glossary.html
# ... and the check can fail: a page loading a script from another host, one loading a file the site lacks, a page
# named as holding equations that has none, and MathJax itself missing.
mkdir -p "$out/online"
printf '<script src="https://cdn.example.org/mathjax/MathJax.js"></script>\n' >"$out/online/cdn.html"
printf '<script src="gone.js"></script><p>no equation</p>\n' >"$out/online/plain.html"
if /usr/bin/python3 "$src/tests/docs/check_site_offline.py" "$out/online" plain.html >"$out/online.txt"; then
  echo "FAIL: check_site_offline.py passed a site that needs the network"; exit 1
fi
for expected in "cdn.html: loads https://cdn.example.org" "plain.html: loads gone.js" \
                "plain.html: no equation" "javascripts/mathjax/MathJax.js: missing"; do
  if ! grep -qF "$expected" "$out/online.txt"; then
    echo "FAIL: check_site_offline.py did not name '$expected':"; cat "$out/online.txt"; exit 1
  fi
done
echo "docs: reference up to date, site built strictly, every anchor resolves, equations render offline"
