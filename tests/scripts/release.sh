#!/usr/bin/env bash
# scripts/release.sh on a scratch clone of the tree (never the tree itself): it refuses a VERSION the copies do not
# say, a version without a CHANGELOG section, a disagreeing copy and a dirty tree, each with one line and no tag; and
# tags a clean tree whose copies agree.
# Usage: release.sh SOURCE_DIR
set -euo pipefail
src="$1"
scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
fail() { echo "tests/scripts/release.sh: $*" >&2; exit 1; }
clone="$scratch/clone"
# The tree as it is now, committed into a fresh repository (the source's own uncommitted edits included).
mkdir -p "$clone/scripts"
cp "$src/CMakeLists.txt" "$src/CITATION.cff" "$src/CHANGELOG.md" "$clone/"
cp "$src/scripts/release.sh" "$src/scripts/check_version.py" "$clone/scripts/"
git -C "$clone" init -q
git -C "$clone" -c user.name=t -c user.email=t@t add -A
git -C "$clone" -c user.name=t -c user.email=t@t commit -qm "scratch"
version="$(/usr/bin/python3 "$clone/scripts/check_version.py" "$clone" | sed 's/^version: //')"

refuses() {  # refuses WHY VERSION: one line on stderr naming WHY, exit 1, no tag
  local why="$1" v="$2" err
  if err="$(bash "$clone/scripts/release.sh" "$v" 2>&1)"; then fail "tagged $v: $why"; fi
  [ "$(printf '%s\n' "$err" | wc -l)" -eq 1 ] || fail "more than one line for $why: $err"
  printf '%s' "$err" | grep -q "$3" || fail "the refusal does not say $3: $err"
  [ -z "$(git -C "$clone" tag)" ] || fail "a tag was made though $why"
}
refuses "a version the tree does not say" 9.9.9 "no section \"## 9.9.9"
printf '## 9.9.9 — 2026-12-01\n' >>"$clone/CHANGELOG.md"
git -C "$clone" -c user.name=t -c user.email=t@t commit -qam "a section for 9.9.9, the copies still at $version"
refuses "the copies say another version" 9.9.9 "not 9.9.9"
git -C "$clone" reset -q --hard HEAD~1
sed -i "s/^version: .*/version: 0.0.1/" "$clone/CITATION.cff"
git -C "$clone" -c user.name=t -c user.email=t@t commit -qam "CITATION.cff disagrees"
refuses "CITATION.cff disagrees" "$version" "CITATION.cff"
git -C "$clone" reset -q --hard HEAD~1
echo "# an edit" >>"$clone/CMakeLists.txt"
refuses "the tree is dirty" "$version" "changes"
git -C "$clone" checkout -q -- CMakeLists.txt
bash "$clone/scripts/release.sh" "$version" >/dev/null || fail "refused a clean tree whose copies say $version"
[ "$(git -C "$clone" tag)" = "v$version" ] || fail "no tag v$version"
echo "tests/scripts/release.sh: 4 refusals, one tag v$version (on a scratch clone)"
