#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# A user's install, run from the installed files only: `cmake --install` into a fresh prefix, the
# prefix moved elsewhere (relocatable), and then, with a bare environment (PATH=/usr/bin:/bin, no
# PYTHONPATH into the build tree, a working folder outside the checkout):
#   - no installed file names the build or source tree (strings, RPATHs, CMake files);
#   - lightcone --version, a render of the installed default scene by its bare name, a formula
#     metric scene (metrics/ found beside it) and `metric check` of an installed metric;
#   - the Python package imported from the prefix, running an installed example;
#   - the CMake package: the example consumer (examples/cmake) configured, built and run;
#   - the man pages (groff, warnings as errors), the bash completion, the desktop entry and the
#     AppStream metadata (validators where installed).
# usage: installed_tree.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$(cd "$1" && pwd) source=$(cd "$2" && pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/lightcone-install.XXXXXX")
trap 'rm -rf "$work"' EXIT
fail() { echo "installed_tree: $*" >&2; exit 1; }

cmake --install "$build" --prefix "$work/first" > "$work/install.log" || { cat "$work/install.log"; fail "cmake --install failed"; }
mv "$work/first" "$work/moved"  # relocated: nothing may depend on where it was installed
prefix="$work/moved"
for f in bin/lightcone bin/lightcone-gui lib/lightcone/liblightcone_oiio_codec.so share/lightcone/data/default.json \
         share/lightcone/data/metrics/kerr.json share/man/man1/lightcone.1 share/man/man1/lightcone-render.1 \
         share/bash-completion/completions/lightcone share/doc/lightcone/LICENSE lib/cmake/Lightcone/LightconeConfig.cmake \
         share/applications/io.github.lightcone.Workbench.desktop share/metainfo/io.github.lightcone.Workbench.metainfo.xml \
         share/icons/hicolor/scalable/apps/io.github.lightcone.Workbench.svg lib/python3/dist-packages/lightcone/__init__.py; do
  [ -e "$prefix/$f" ] || fail "not installed: $f"
done

# No path of the build or source tree (or of the first prefix) in any installed file.
if leaks=$(grep -rlF -e "$build" -e "$source/" -e "$work/first" "$prefix"); then
  fail "installed files name the build tree, the sources or the install folder:"$'\n'"$leaks"
fi
for program in "$prefix"/bin/* "$prefix"/lib/lightcone/*.so "$prefix"/lib/python3/dist-packages/lightcone/*.so; do
  if readelf -d "$program" | grep -qE "RPATH|RUNPATH"; then fail "$program carries an RPATH"; fi
done

bare() { env -i PATH=/usr/bin:/bin HOME="$work" LANG=C.UTF-8 "$@"; }
mkdir "$work/run" && cd "$work/run"
bare "$prefix/bin/lightcone" --version | grep -q "^lightcone [0-9]" || fail "--version"
bare "$prefix/bin/lightcone" render default.json -o default.png --width 64 --height 32 --quiet
bare "$prefix/bin/lightcone" render kerr_formula.json -o kerr.png --width 32 --height 16 --quiet
[ -s default.png ] && [ -s kerr.png ] || fail "the installed renders wrote no image"
bare "$prefix/bin/lightcone" metric check kerr.json --param a=0.5 > check.txt || fail "metric check kerr.json"
if bare "$prefix/bin/lightcone" render no_such_scene.json -o x.png 2> missing.txt; then fail "a missing scene was accepted"; fi
grep -q "share/lightcone/data" missing.txt || fail "a missing scene's message does not say where it looked: $(cat missing.txt)"
LIGHTCONE_DATA_PATH="$source/data" bare "$prefix/bin/lightcone" help > /dev/null

# Python: the package from the prefix, an installed example.
pydir="$prefix/lib/python3/dist-packages"
bare env PYTHONPATH="$pydir" /usr/bin/python3 -c "import lightcone, sys; sys.exit(not lightcone.__file__.startswith('$pydir'))" \
  || fail "Python did not import lightcone from the prefix"
bare env PYTHONPATH="$pydir" /usr/bin/python3 -c "import lightcone; lightcone.read_scene('kerr.json', edits={'metric.a': 0.5})" \
  || fail "Python did not find the installed scene kerr.json by name"
bare env PYTHONPATH="$pydir" /usr/bin/python3 "$prefix/share/doc/lightcone/examples/python/vtk_pipeline.py" "$work/run/py" > py.txt \
  || { cat py.txt; fail "the installed Python example failed"; }

# The CMake package: the example consumer against the moved prefix.
generator=(); command -v ninja > /dev/null && generator=(-G Ninja)
cmake -S "$prefix/share/doc/lightcone/examples/cmake" -B "$work/consumer" "${generator[@]}" \
  -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release > "$work/consumer.log" 2>&1 \
  || { cat "$work/consumer.log"; fail "the example consumer did not configure"; }
cmake --build "$work/consumer" > "$work/consumer.log" 2>&1 || { cat "$work/consumer.log"; fail "the example consumer did not build"; }
bare "$work/consumer/godel_horizon" || fail "the example consumer's check failed"

# Man pages without groff warnings, the completion, desktop entry and AppStream metadata.
for page in "$prefix"/share/man/man1/*.1; do
  warnings=$(groff -man -Tutf8 -ww -z "$page" 2>&1) || fail "groff failed on $page"
  [ -z "$warnings" ] || fail "$page: $warnings"
done
bare bash -c "source '$prefix/share/bash-completion/completions/lightcone' && complete -p lightcone" > /dev/null \
  || fail "the bash completion does not load"
if command -v desktop-file-validate > /dev/null; then
  desktop-file-validate "$prefix/share/applications/io.github.lightcone.Workbench.desktop"
fi
if command -v appstreamcli > /dev/null; then
  appstreamcli validate --no-net "$prefix/share/metainfo/io.github.lightcone.Workbench.metainfo.xml" > /dev/null
fi
echo "installed_tree: the moved install runs render, metric check, Python and the CMake consumer"
