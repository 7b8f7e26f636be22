#!/usr/bin/env bash
# Tags a release: `bash scripts/release.sh VERSION` (e.g. 0.3.0) checks that CMake's project() version, CITATION.cff,
# CHANGELOG.md's newest release heading (scripts/check_version.py) and, when build/vssw exists, `vssw --version` all
# say VERSION, that CHANGELOG.md has a section "## VERSION — date", and that the work tree is clean; then it makes the
# annotated tag vVERSION. It pushes nothing. Refuses with one line on stderr, exit 1 (2 for a malformed VERSION).
# usage: release.sh VERSION
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
refuse() { echo "release: $*" >&2; exit 1; }

[ $# -eq 1 ] || { echo "usage: bash scripts/release.sh VERSION" >&2; exit 2; }
version="$1"
[[ "$version" =~ ^[0-9]+\.[0-9]+\.[0-9]+$ ]] || { echo "release: error: VERSION '$version' is not X.Y.Z" >&2; exit 2; }

git -C "$here" rev-parse --is-inside-work-tree >/dev/null 2>&1 || refuse "$here is not a git work tree"
grep -qE "^## ${version//./\\.} — " "$here/CHANGELOG.md" || refuse "CHANGELOG.md has no section \"## $version — date\""
program=()
[ -x "$here/build/vssw" ] && program=(--vssw "$here/build/vssw")
if ! out="$(/usr/bin/python3 "$here/scripts/check_version.py" "$here" --expect "$version" "${program[@]}")"; then
  refuse "the versions disagree: $(printf '%s' "$out" | head -n 1 | sed 's/^version: //')"
fi
[ -z "$(git -C "$here" status --porcelain)" ] || refuse "the work tree has changes; commit or stash them first"
git -C "$here" rev-parse -q --verify "refs/tags/v$version" >/dev/null && refuse "the tag v$version exists already"
git -C "$here" tag -a "v$version" -m "vssw $version"
echo "release: tagged v$version at $(git -C "$here" rev-parse --short HEAD); push it with: git push origin v$version"
