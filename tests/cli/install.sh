#!/usr/bin/env bash
# `cmake --install` staged into a temporary folder (DESTDIR), then the installed program run from there: it must find
# the installed data and plugins, not the source tree's or the build tree's (docs/guide/install.md).
# Usage: install.sh BUILD_DIR
set -euo pipefail
build="$1"
stage="$(mktemp -d)"
trap 'rm -rf "$stage"' EXIT
DESTDIR="$stage" cmake --install "$build" --prefix /opt/vssw >/dev/null
prefix="$stage/opt/vssw"
vssw="$prefix/bin/vssw"
for f in bin/vssw share/vssw/data/table1.csv share/vssw/data/NGA_no_1063_RRS228.AT2 share/vssw/bounds/ci.toml \
         share/vssw/studies/validation-default.toml share/doc/vssw/LICENSE share/doc/vssw/CITATION.cff; do
  [ -e "$prefix/$f" ] || { echo "install.sh: $f was not installed" >&2; exit 1; }
done
cd /  # nothing relative to the source tree
unset VSSW_DATA_DIR
"$vssw" --version | grep -q '^vssw ' || { echo "install.sh: --version printed no version" >&2; exit 1; }
"$vssw" summary >/dev/null
# Which data it read: with the installed record removed, the summary must fail naming the installed path.
mv "$prefix/share/vssw/data/NGA_no_1063_RRS228.AT2" "$stage/moved.AT2"
if out="$("$vssw" summary 2>&1)"; then echo "install.sh: summary ran without the installed record" >&2; exit 1; fi
echo "$out" | grep -q "$prefix/share/vssw/data/NGA_no_1063_RRS228.AT2" ||
  { echo "install.sh: the installed vssw did not read the installed data: $out" >&2; exit 1; }
mv "$stage/moved.AT2" "$prefix/share/vssw/data/NGA_no_1063_RRS228.AT2"
# The environment variable comes first.
if out="$(VSSW_DATA_DIR="$stage/nowhere" "$vssw" summary 2>&1)"; then
  echo "install.sh: VSSW_DATA_DIR was not used" >&2; exit 1
fi
echo "$out" | grep -q "$stage/nowhere" || { echo "install.sh: VSSW_DATA_DIR was not used: $out" >&2; exit 1; }
"$vssw" check --bounds "$prefix/share/vssw/bounds/ci.toml" >/dev/null
# Which suite it read: with the installed default suite broken, the check must fail naming the installed file.
suite="$prefix/share/vssw/studies/validation-default.toml"
echo 'this line is not TOML' >>"$suite"
if out="$("$vssw" check --bounds "$prefix/share/vssw/bounds/ci.toml" 2>&1)"; then
  echo "install.sh: check ran on a broken installed suite (it read another one)" >&2; exit 1
fi
echo "$out" | grep -q "$suite" || { echo "install.sh: the installed vssw did not read the installed suite: $out" >&2; exit 1; }
# The installed plugins (docs/architecture.md, "Plugins"): found beside the installed program, named by --version; a
# missing one is bad input (exit 2) naming the engine and the installed folder; VSSW_PLUGIN_PATH is searched first.
if "$vssw" --version | grep -q '^  ode '; then
  plugin="$(find "$prefix" -name vssw_engine_ode.so)"
  [ -n "$plugin" ] || { echo "install.sh: vssw_engine_ode.so was not installed" >&2; exit 1; }
  "$vssw" --version | grep -q "$plugin" || { echo "install.sh: --version does not name $plugin" >&2; exit 1; }
  wall=(--height 4 --thickness 0.4 --hinge 0.7)
  "$vssw" compare --engine ode "${wall[@]}" >/dev/null
  mkdir "$stage/moved-plugins"
  mv "$plugin" "$stage/moved-plugins/"
  rc=0
  out="$("$vssw" compare --engine ode "${wall[@]}" 2>&1)" || rc=$?
  [ "$rc" = 2 ] || { echo "install.sh: a missing plugin gave exit $rc, not 2: $out" >&2; exit 1; }
  echo "$out" | grep -q "engine 'ode'.*vssw_engine_ode.so.*$(dirname "$plugin")" ||
    { echo "install.sh: a missing plugin's message does not name the engine and the folder: $out" >&2; exit 1; }
  VSSW_PLUGIN_PATH="$stage/moved-plugins" "$vssw" compare --engine ode "${wall[@]}" >/dev/null ||
    { echo "install.sh: the plugin was not found through VSSW_PLUGIN_PATH" >&2; exit 1; }
  mv "$stage/moved-plugins/vssw_engine_ode.so" "$plugin"
fi
echo "install.sh: installed vssw ran on its installed data and plugins"
