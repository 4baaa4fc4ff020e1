#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Runs one workbench test on an X server of its own, so that ctest can run them side by side:
# on one shared display two workbenches take the keyboard focus from each other. Xvfb picks a
# free display number itself (-displayfd), so parallel starts cannot race for the same one. The
# screen is xvfb-run's default (1280x1024x24), as for every other test.
# Listing the tests (gtest_discover_tests at build time) needs no display.
set -euo pipefail

for arg in "$@"; do
  [[ "$arg" == --gtest_list_tests ]] && exec "$@"
done

command -v Xvfb >/dev/null || { echo "on_own_display: Xvfb not found (Debian: xvfb)" >&2; exit 1; }
log=$(mktemp)
exec 3< <(exec Xvfb -displayfd 1 -screen 0 1280x1024x24 -nolisten tcp -noreset 2>"$log")
xvfb_pid=$!
trap 'kill "$xvfb_pid" 2>/dev/null; wait "$xvfb_pid" 2>/dev/null; rm -f "$log"' EXIT
if ! read -r -t 30 display <&3; then
  echo "on_own_display: Xvfb did not start within 30 s:" >&2
  cat "$log" >&2
  exit 1
fi
DISPLAY=":$display" "$@"
