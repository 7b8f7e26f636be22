#!/usr/bin/env bash
# The engines' Debian packages, one a line: the words of the "  DEBIAN pkg..." lines of each engine folder's
# multibody/<engine>/engine.cmake (cmake/engines.cmake). Read as words, never run: a word that is not a Debian package
# name is refused (exit 2, naming it). scripts/setup.sh installs what this prints.
# usage: bash scripts/engine_packages.sh SOURCE_DIR
set -euo pipefail
[ $# -eq 1 ] || { echo "usage: bash scripts/engine_packages.sh SOURCE_DIR" >&2; exit 2; }

found=()
while read -r -a words; do
  for p in "${words[@]}"; do
    if [[ ! "$p" =~ ^[a-z0-9][a-z0-9.+-]+$ ]]; then
      echo "engine_packages: '$p' in a DEBIAN line of $1/multibody/*/engine.cmake is not a Debian package name" >&2
      exit 2
    fi
    found+=("$p")
  done
done < <(sed -n 's/^ *DEBIAN \([^#)]*\).*$/\1/p' "$1"/multibody/*/engine.cmake)
[ ${#found[@]} -gt 0 ] || { echo "engine_packages: no DEBIAN line in $1/multibody/*/engine.cmake" >&2; exit 2; }
printf '%s\n' "${found[@]}"
