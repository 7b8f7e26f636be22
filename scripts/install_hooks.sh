#!/usr/bin/env bash
# Installs scripts/commit-msg as the commit-msg hook of this clone (scripts/setup.sh runs it; nothing happens outside
# a git work tree). Idempotent: an installed copy that differs only by being older is replaced. A commit-msg hook of
# the clone's own is kept as commit-msg.local, which ours runs after its checks; when commit-msg.local exists already,
# nothing is touched and one line says so.
# usage: install_hooks.sh [SOURCE_DIR]
set -euo pipefail
here="${1:-$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)}"
ours="$here/scripts/commit-msg"
marker="scripts/setup.sh installs it into .git/hooks"

git -C "$here" rev-parse --is-inside-work-tree >/dev/null 2>&1 || exit 0
hooks="$(git -C "$here" rev-parse --path-format=absolute --git-path hooks)"
mkdir -p "$hooks"
hook="$hooks/commit-msg"

if [ -e "$hook" ] && ! grep -qF "$marker" "$hook"; then
  if [ -e "$hook.local" ]; then
    echo "install_hooks: $hook is not ours and $hook.local exists: left both as they are" >&2
    exit 0
  fi
  mv "$hook" "$hook.local"
  echo "install_hooks: kept your commit-msg hook as $hook.local (ours runs it after its checks)" >&2
fi
if ! cmp -s "$ours" "$hook"; then
  cp "$ours" "$hook"
  chmod +x "$hook"
  echo "install_hooks: installed $hook (commit subjects of at most 72 characters, a blank line before a body)" >&2
fi
