#!/usr/bin/env bash
# The documentation site (docs/contributing/docs.md): the committed reference pages are what the program prints
# today (scripts/gen_reference.py --check), and `mkdocs build --strict` builds the site without a warning (a broken
# link, a page missing from the navigation). Skipped (exit 77) only when mkdocs is not installed: scripts/setup.sh
# installs it, so CI has it.
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
echo "docs: reference up to date, site built strictly"
