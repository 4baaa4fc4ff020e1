#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The Debian package as `apt install ./lightcone_*.deb` would get it: built by CPack into a
# temporary folder (nothing written into the build tree), its control data checked (name,
# version, dependencies computed by dpkg-shlibdeps plus the declared ones), its files unpacked
# into a temporary root and run from there: `lightcone render default.json` (the packaged scene,
# by name) and the Python package's import.
# usage: debian_package.sh BUILD_DIR
set -euo pipefail
build=$(cd "$1" && pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/lightcone-deb.XXXXXX")
trap 'rm -rf "$work"' EXIT
fail() { echo "debian_package: $*" >&2; exit 1; }

cpack -G DEB --config "$build/CPackConfig.cmake" -B "$work/package" > "$work/cpack.log" 2>&1 \
  || { cat "$work/cpack.log"; fail "cpack failed"; }
deb=$(ls "$work"/package/lightcone_*.deb 2> /dev/null | head -1)
[ -n "$deb" ] || fail "cpack made no lightcone_*.deb: $(ls "$work/package")"
info=$(dpkg-deb --field "$deb" Package Version Architecture Depends)
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

dpkg-deb --extract "$deb" "$work/root"
mkdir "$work/run" && cd "$work/run"
env -i PATH=/usr/bin:/bin HOME="$work" "$work/root/usr/bin/lightcone" render default.json -o default.png \
  --width 64 --height 32 --quiet
[ -s default.png ] || fail "the packaged lightcone wrote no image"
env -i PATH=/usr/bin:/bin HOME="$work" PYTHONPATH="$work/root/usr/lib/python3/dist-packages" /usr/bin/python3 \
  -c "import lightcone; print(lightcone.__version__)" > version.txt || fail "the packaged Python module does not import"
echo "debian_package: $(basename "$deb") ($(du -h "$deb" | cut -f1)): $(grep '^Depends' <<< "$info" | cut -c1-100)..."
