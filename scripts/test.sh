#!/usr/bin/env bash
# Every test: install what is missing, build, run the C++ unit and loopback
# tests, the JavaScript decoder tests and the headless-browser test (all
# through ctest), then the libFuzzer targets for a bounded time each.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh --test
scripts/build.sh
scripts/build-wasm.sh   # the page's log module (web/wasm/), which wasm_frames and web_local_log test
jobs=$(nproc 2>/dev/null || echo 2)
mkdir -p test-output

set +e
(cd build && ctest -j "$jobs" --output-on-failure --timeout 600) | tee test-output/ctest.log
main_rc=${PIPESTATUS[0]}

# Fuzzers need clang's libFuzzer: a second, instrumented build of the libraries.
if [[ ! -f build-fuzz/CMakeCache.txt ]]; then
  CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DMATCHCAST_FUZZ=ON -DMATCHCAST_FUZZ_SECONDS="${FUZZ_SECONDS:-20}" >/dev/null
fi
cmake --build build-fuzz -j "$jobs" --target fuzzers &&
  (cd build-fuzz && ctest -L fuzz --output-on-failure) | tee test-output/fuzz.log
fuzz_rc=$?
set -e

passed=$(grep -hoE '^[[:space:]]*[0-9]+/[0-9]+ Test +#[0-9]+: .* Passed' test-output/ctest.log test-output/fuzz.log 2>/dev/null | wc -l)
failed=$(grep -hE '^[[:space:]]*[0-9]+/[0-9]+ Test +#[0-9]+: ' test-output/ctest.log test-output/fuzz.log 2>/dev/null | grep -vc ' Passed' || true)
echo
echo "matchcast: $passed passed, $failed failed"
if [[ $main_rc -ne 0 || $fuzz_rc -ne 0 ]]; then exit 1; fi
