#!/usr/bin/env bash
# Builds the page's log module, web/wasm/matchcast-log.{js,wasm}: the
# server's log readers, anim/ and the proto encoder in WebAssembly (Debian's
# emscripten), so that the page plays a dropped .rcg with no server. A second
# build tree (build-wasm/) of the same CMakeLists.txt; web/ is then a complete
# static site (README.md, "The page without a server").
set -euo pipefail
cd "$(dirname "$0")/.."
if ! command -v emcmake >/dev/null; then
  echo "build-wasm: emscripten is not installed (scripts/install-deps.sh); the page cannot open logs by itself" >&2
  exit 1
fi
# Debian's em++ runs its JavaScript tools with node; a node that is not
# Debian's own finds their modules (acorn) only through NODE_PATH.
export NODE_PATH="${NODE_PATH:+$NODE_PATH:}/usr/share/nodejs"
jobs=$(nproc 2>/dev/null || echo 2)
if [[ ! -f build-wasm/CMakeCache.txt ]]; then
  launcher=()
  if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
  emcmake cmake -S . -B build-wasm -G Ninja -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" >/dev/null
fi
cmake --build build-wasm -j "$jobs" "$@"
