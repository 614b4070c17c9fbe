#!/usr/bin/env bash
# Installs what Matchcast needs and is missing: Debian packages, then the web
# page's npm packages. Safe to run again: it only installs what is absent.
#
#   scripts/install-deps.sh           what the demo needs (build + run)
#   scripts/install-deps.sh --test    also what the tests need (browser, fuzzers)
set -euo pipefail
cd "$(dirname "$0")/.."

# Why each package is here: README.md, "Dependencies".
runtime=(
  build-essential cmake ninja-build pkg-config   # compiler and build
  libboost-dev libboost-program-options-dev      # Asio + Beast (relay, live feed), options
  nlohmann-json3-dev                             # hello / control messages
  libfast-float-dev                              # decimal -> double, the same in both builds
  libglm-dev                                     # vector maths in anim/
  zlib1g-dev                                     # .rcg.gz logs, gzipped mocap clips
  libpng-dev                                     # PNG pictures of the tools and the viewer
  libssl-dev                                     # TLS for the relay (Boost.Asio SSL)
  libnats-dev                                    # origin/edge relays over NATS
  libglfw3-dev libgl-dev                         # native viewer (window + OpenGL)
  nodejs npm                                     # installs three.js for the page
  emscripten                                     # the page's log module (ingest+anim+proto in WebAssembly)
)
testing=(
  libgtest-dev libgmock-dev libbenchmark-dev     # C++ tests and benchmarks
  clang libclang-rt-dev                          # libFuzzer targets
  chromium                                       # browser test (headless)
  xvfb xauth libgl1-mesa-dri                     # native viewer test (Mesa under Xvfb)
  nats-server                                    # NATS origin/edge test
  openssl                                        # self-signed certificate for the TLS test
)
wanted=("${runtime[@]}")
if [[ "${1:-}" == "--test" ]]; then wanted+=("${testing[@]}"); fi

missing=()
for p in "${wanted[@]}"; do
  # nodejs may come from another Debian-format repository; any node will do.
  if [[ "$p" == nodejs && -x "$(command -v node || true)" ]]; then continue; fi
  if [[ "$p" == npm && -x "$(command -v npm || true)" ]]; then continue; fi
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if ((${#missing[@]})); then
  echo "Installing Debian packages: ${missing[*]}"
  sudo=()
  if [[ $(id -u) -ne 0 ]]; then sudo=(sudo); fi
  "${sudo[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# The page's packages (three.js; playwright-core for the browser test), pinned
# by package-lock.json. Reinstalled only when the lock file changed.
if [[ -f web/package-lock.json ]]; then
  stamp=web/node_modules/.matchcast-lock
  if [[ ! -f "$stamp" ]] || ! cmp -s web/package-lock.json "$stamp"; then
    echo "Installing npm packages for web/"
    (cd web && npm ci --no-audit --no-fund --loglevel=error)
    cp web/package-lock.json "$stamp"
  fi
fi
