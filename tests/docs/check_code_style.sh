#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Every C++ file of the repository is formatted as its nearest .clang-format says (the root one,
# or VTK's style in filters/ and tests/vtk/). The style is defined for clang-format 14 (Debian
# 12's, installed by scripts/bootstrap); another version formats differently, so the check is
# skipped (exit 77) with the reason. Run by ctest as `code_style`.
set -euo pipefail
cd "$1"
formatter=$(command -v clang-format-14 || command -v clang-format || true)
if [ -z "$formatter" ]; then
  echo "code_style: clang-format not found (scripts/bootstrap installs Debian's clang-format)"
  exit 1
fi
version=$("$formatter" --version | sed -n 's/.*version \([0-9]*\)\..*/\1/p')
if [ "$version" != "14" ]; then
  echo "code_style: skipped: $formatter is version $version, the style is defined for clang-format 14"
  exit 77
fi
mapfile -t files < <(find app bench core filters readers tests views -type f \
  \( -name '*.cpp' -o -name '*.hpp' -o -name '*.cxx' -o -name '*.h' \) -not -path 'tests/data/*' | sort)
if ! "$formatter" --dry-run --Werror "${files[@]}" 2> /tmp/lightcone_code_style.$$; then
  grep -o '^[^:]*\.\(cpp\|hpp\|cxx\|h\)' /tmp/lightcone_code_style.$$ | sort -u | sed 's/^/code_style: not formatted: /'
  head -40 /tmp/lightcone_code_style.$$
  rm -f /tmp/lightcone_code_style.$$
  echo "code_style: run clang-format -i on the files above"
  exit 1
fi
rm -f /tmp/lightcone_code_style.$$
echo "code_style: ${#files[@]} files formatted as .clang-format says"
