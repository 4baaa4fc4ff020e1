#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The Debian package as `apt install ./lightcone_*.deb` would get it: built by CPack into a
# temporary folder (nothing written into the build tree), its control data checked (name,
# version, the declared dependencies, and those dpkg-shlibdeps computes from its ELF files), its
# files unpacked into a temporary root and run from there: `lightcone render default.json` (the
# packaged scene, by name) and the Python package's import.
# CPack's own dpkg-shlibdeps step (CPACK_DEBIAN_PACKAGE_SHLIBDEPS, on in the project's
# configuration, checked below) first runs `file` through `cmake -E env` on each of the ~300
# packaged files to find the ELF ones: 25 of the test's 46 s. Here it is off, and dpkg-shlibdeps
# runs as CPack runs it, on the ELF files found with one `file` call.
# usage: debian_package.sh BUILD_DIR
set -euo pipefail
build=$(cd "$1" && pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/lightcone-deb.XXXXXX")
trap 'rm -rf "$work"' EXIT
fail() { echo "debian_package: $*" >&2; exit 1; }

grep -q 'set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS "ON")' "$build/CPackConfig.cmake" \
  || fail "the package's configuration does not compute its shared-library dependencies"
cpack -G DEB --config "$build/CPackConfig.cmake" -B "$work/package" -D CPACK_DEBIAN_PACKAGE_SHLIBDEPS=OFF \
  > "$work/cpack.log" 2>&1 || { cat "$work/cpack.log"; fail "cpack failed"; }
deb=$(ls "$work"/package/lightcone_*.deb 2> /dev/null | head -1)
[ -n "$deb" ] || fail "cpack made no lightcone_*.deb: $(ls "$work/package")"
dpkg-deb --extract "$deb" "$work/root"
# The dependencies dpkg-shlibdeps computes from the packaged ELF files, as CPack asks for them
# (an empty debian/control beside, --ignore-missing-info for the project's own libraries).
mapfile -t elves < <(find "$work/root" -type f -print0 | xargs -0 file -F '|' \
  | awk -F'|' '/ELF.*(dynamically linked|shared object)/ {print $1}')
[ "${#elves[@]}" -ge 3 ] || fail "fewer than 3 ELF files in the package: ${elves[*]}"
mkdir -p "$work/shlibs/debian" && : > "$work/shlibs/debian/control"
shlibs=$(cd "$work/shlibs" && dpkg-shlibdeps --ignore-missing-info -O "${elves[@]}" 2> "$work/shlibdeps.log") \
  || { cat "$work/shlibdeps.log"; fail "dpkg-shlibdeps failed"; }
info="$(dpkg-deb --field "$deb" Package Version Architecture Depends)"$'\n'"$shlibs"
for want in "Package: lightcone" "Architecture: amd64\|Architecture: arm64" "libvtk9.1" "libqt5widgets5" \
            "libjsoncpp25" "python3-numpy" "python3-vtk9"; do
  grep -q "$want" <<< "$info" || fail "the control data lacks '$want':"$'\n'"$info"
done
contents=$(dpkg-deb --contents "$deb")
for want in ./usr/bin/lightcone ./usr/bin/lightcone-gui ./usr/lib/lightcone/liblightcone_oiio_codec.so \
            ./usr/share/lightcone/data/default.json ./usr/share/man/man1/lightcone-render.1 \
            ./usr/lib/python3/dist-packages/lightcone/__init__.py ./usr/lib/cmake/Lightcone/LightconeConfig.cmake; do
  grep -q " $want\$" <<< "$contents" || fail "the package lacks $want"
done

mkdir "$work/run" && cd "$work/run"
env -i PATH=/usr/bin:/bin HOME="$work" "$work/root/usr/bin/lightcone" render default.json -o default.png \
  --width 64 --height 32 --quiet
[ -s default.png ] || fail "the packaged lightcone wrote no image"
env -i PATH=/usr/bin:/bin HOME="$work" PYTHONPATH="$work/root/usr/lib/python3/dist-packages" /usr/bin/python3 \
  -c "import lightcone; print(lightcone.__version__)" > version.txt || fail "the packaged Python module does not import"
echo "debian_package: $(basename "$deb") ($(du -h "$deb" | cut -f1)): $(grep "^Depends" <<< "$info" | cut -c1-60)...; ${#elves[@]} ELF files need $(cut -c1-80 <<< "$shlibs")..."
