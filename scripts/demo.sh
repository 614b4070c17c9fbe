#!/usr/bin/env bash
# The main job: install what is missing, build, and broadcast the bundled
# real game (HELIOS_A vs HELIOS_B, rcssserver 19) in a loop. No rcssserver
# is needed. Prints the URL to open; Ctrl-C stops it.
#
#   scripts/demo.sh                  on http://127.0.0.1:8080/
#   PORT=9000 scripts/demo.sh        another port
#   scripts/demo.sh --rcg other.rcg.gz --speed 2    any matchcast-server option
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh --target matchcast-server
scripts/build-wasm.sh   # the page opens dropped logs by itself (web/wasm/)
# Recordings (--record-dir recordings): one file per pass of the looping
# game, ~3 MB each. The demo keeps at most 300 MB and two days of them
# (the oldest deleted first), unless told otherwise.
limits=()
[[ " $* " == *" --record-max-bytes"* ]] || limits+=(--record-max-bytes 300M)
[[ " $* " == *" --record-max-age"* ]] || limits+=(--record-max-age 2d)
exec build/server/app/matchcast-server --port "${PORT:-8080}" "${limits[@]}" "$@"
