#!/usr/bin/env bash
# The commit-msg hook (scripts/commit-msg) on good and bad messages, and its installation (scripts/install_hooks.sh)
# into a scratch git repository: idempotent, and a hook of the clone's own kept and still run.
# Usage: commit_msg_hook.sh SOURCE_DIR
set -euo pipefail
src="$1"
hook="$src/scripts/commit-msg"
scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
fail() { echo "commit_msg_hook.sh: $*" >&2; exit 1; }
accepts() { printf "$2" >"$scratch/msg"; "$hook" "$scratch/msg" 2>/dev/null || fail "refused $1"; }
refuses() { printf "$2" >"$scratch/msg"; ! "$hook" "$scratch/msg" 2>/dev/null || fail "accepted $1"; }

subject72="$(printf 'a%.0s' $(seq 71))—"   # 72 characters, 74 bytes: the limit counts characters
accepts "a subject of 72 characters with a body" "$subject72\n\nThe body.\n"
accepts "a subject alone" "Subject\n"
accepts "git's comment lines after the subject" "Subject\n# Please enter the commit message\n"
refuses "a subject of 73 characters" "${subject72}b\n"
refuses "a body without a blank line before it" "Subject\nThe body at once.\n"

# Installation: a clone with a commit-msg hook of its own.
repo="$scratch/clone"
git init -q "$repo"
mkdir -p "$repo/scripts"
cp "$hook" "$src/scripts/install_hooks.sh" "$repo/scripts/"
printf '#!/bin/sh\ntouch "%s/own-hook-ran"\n' "$scratch" >"$repo/.git/hooks/commit-msg"
chmod +x "$repo/.git/hooks/commit-msg"
"$repo/scripts/install_hooks.sh" "$repo" 2>/dev/null
cmp -s "$hook" "$repo/.git/hooks/commit-msg" || fail "the hook was not installed"
grep -q own-hook-ran "$repo/.git/hooks/commit-msg.local" || fail "the clone's own hook was not kept"
"$repo/scripts/install_hooks.sh" "$repo" 2>"$scratch/again"
[ ! -s "$scratch/again" ] || fail "a second installation changed something: $(cat "$scratch/again")"
printf 'Subject\n' >"$scratch/msg"
"$repo/.git/hooks/commit-msg" "$scratch/msg"
[ -e "$scratch/own-hook-ran" ] || fail "the clone's own hook did not run after ours"
# Outside a git work tree nothing happens.
mkdir -p "$scratch/plain/scripts" && cp "$hook" "$src/scripts/install_hooks.sh" "$scratch/plain/scripts/"
GIT_CEILING_DIRECTORIES="$scratch" "$scratch/plain/scripts/install_hooks.sh" "$scratch/plain"
[ ! -e "$scratch/plain/.git" ] || fail "install_hooks.sh made a .git outside a work tree"
echo "commit_msg_hook.sh: 5 messages judged, installed once, own hook kept and run"
