#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Every source file of the repository (C++, GLSL, Python, CMake, shell) names its licence in an
# SPDX line within its first three lines: LICENSE is BSD-3-Clause, and a file copied out of the
# repository keeps saying so. Run by ctest as `licence_headers`.
set -euo pipefail
cd "$1"
missing=0
while IFS= read -r f; do
  if ! head -3 "$f" | grep -q 'SPDX-License-Identifier: BSD-3-Clause'; then
    echo "licence_headers: no SPDX line in $f"
    missing=$((missing + 1))
  fi
done < <(find app bench cmake core examples filters python readers scripts tests views .ci -type f \
           \( -name '*.cpp' -o -name '*.hpp' -o -name '*.h' -o -name '*.cxx' -o -name '*.glsl' -o -name '*.py' \
              -o -name '*.sh' -o -name '*.cmake' -o -name 'CMakeLists.txt' \) \
           -not -path 'tests/data/*' -not -path 'tests/fuzz/corpus/*' | sort)
if [ "$missing" -gt 0 ]; then
  echo "licence_headers: $missing files lack '// SPDX-License-Identifier: BSD-3-Clause' (or '#' for scripts)"
  exit 1
fi
test -f LICENSE && grep -q 'BSD 3-Clause License' LICENSE
echo "licence_headers: every source file says BSD-3-Clause, as LICENSE does"
