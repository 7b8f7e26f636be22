#!/usr/bin/env bash
# The documentation site (docs/contributing/docs.md): the committed reference pages are what the program prints
# today (scripts/gen_reference.py --check), `mkdocs build --strict` builds the site without a warning (a broken
# link, a page missing from the navigation), and every link's anchor exists (tests/docs/check_anchors.py). Skipped
# (exit 77) only when mkdocs is not installed: scripts/setup.sh installs it, so CI has it.
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
echo "docs: reference up to date, site built strictly, every anchor resolves"
