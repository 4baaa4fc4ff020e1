#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The bash completion `lightcone completion bash` prints, driven as bash drives it: commands,
# each command's options, an option's words, and file names after a file option.
# Usage: check_completion.sh path/to/lightcone
set -euo pipefail
source <("$1" completion bash)
complete_words() {  # the words offered after typing "$@" (the last one partial)
  COMP_WORDS=(lightcone "$@"); COMP_CWORD=$#; COMPREPLY=()
  _lightcone
  echo "${COMPREPLY[*]}"
}
expect() {  # expect "OFFERED" words...
  local got; got=$(complete_words "${@:2}")
  if [ "$got" != "$1" ]; then echo "after 'lightcone ${*:2}': offered '$got', expected '$1'"; exit 1; fi
}
expect "render" ren
expect "sweep shade" s
expect "--width --windings" render scene.json --wi
expect "closed_form" render scene.json --method clo
expect "kerr kerr-newman" trace --metric kerr
expect "--fps" animate --fp
expect "t-r" diagram s.json --kind t
expect "" render s.json --width 1     # a number: nothing offered
expect "bash" completion b
cd "$(dirname "$0")"
expect "check_completion.sh" render s.json -o check_comp   # a file option: the file names
echo "bash completion: ok"
