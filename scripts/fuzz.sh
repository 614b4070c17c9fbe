#!/usr/bin/env bash
# Every libFuzzer target for longer than CI's 20 s, with ASan and UBSan, one
# after another at nice 10 (a long run leaves the machine usable), then a
# table: executions, speed, coverage, corpus and crashes per target.
#
#   scripts/fuzz.sh --minutes 30                 each target for 30 minutes
#   scripts/fuzz.sh --runs 10000000              each target for 10 million inputs
#   scripts/fuzz.sh --seconds 10                 a quick look at every target's speed
#   scripts/fuzz.sh --minutes 5 replay_ proto_   only targets whose name starts so
#   scripts/fuzz.sh --minutes 5 --jobs 2         two targets at a time
#   BUILD_JOBS=1 scripts/fuzz.sh --seconds 10    build with one compiler job
#
# Targets are the ctest tests labelled "fuzz" of the fuzz build (BUILD_DIR,
# default build-fuzz, configured here like scripts/test.sh does), run with
# the same dictionary and seed corpus; each one's corpus grows in the build
# tree. A crash, leak or timeout leaves its input in
# BUILD_DIR/fuzz-artifacts/TARGET/ and makes the script exit 1: fix it, then
# keep the input as a regression seed in the target's seeds folder (the
# path is in the table's last column), so that every later run replays it.
set -euo pipefail
cd "$(dirname "$0")/.."

minutes=""
seconds=""
runs=""
jobs=1
build="${BUILD_DIR:-build-fuzz}"
filters=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    --minutes) minutes="$2"; shift 2 ;;
    --seconds) seconds="$2"; shift 2 ;;
    --runs) runs="$2"; shift 2 ;;
    --jobs) jobs="$2"; shift 2 ;;
    --build) build="$2"; shift 2 ;;
    -h|--help) sed -n '2,20p' "$0"; exit 0 ;;
    *) filters+=("$1"); shift ;;
  esac
done
if [[ -n $minutes ]]; then seconds=$((minutes * 60)); fi
if [[ -z $seconds && -z $runs ]]; then
  echo "fuzz.sh: give --minutes N, --seconds N or --runs N (see --help)" >&2
  exit 2
fi

if [[ ! -f $build/CMakeCache.txt ]]; then
  CXX=clang++ cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DMATCHCAST_FUZZ=ON \
    ${CMAKE_CXX_COMPILER_LAUNCHER:+-DCMAKE_CXX_COMPILER_LAUNCHER=$CMAKE_CXX_COMPILER_LAUNCHER} >/dev/null
fi
cmake --build "$build" -j "${BUILD_JOBS:-$(nproc 2>/dev/null || echo 2)}" --target fuzzers

# The libraries' UBSan checks are recoverable: make the first report fatal,
# so that undefined behaviour stops the run and leaves its input, like a crash.
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1}"
out="$build/fuzz-runs"
mkdir -p "$out"
# name<TAB>working dir<TAB>command (one argument a line, base64) from ctest.
(cd "$build" && ctest -L fuzz --show-only=json-v1) | python3 -c '
import base64, json, sys
for t in json.load(sys.stdin)["tests"]:
    wd = next((p["value"] for p in t.get("properties", []) if p["name"] == "WORKING_DIRECTORY"), ".")
    print(t["name"], wd, base64.b64encode("\n".join(t["command"]).encode()).decode(), sep="\t")
' > "$out/targets.tsv"

selected=()
while IFS=$'\t' read -r name wd cmd; do
  if [[ ${#filters[@]} -gt 0 ]]; then
    keep=no
    for f in "${filters[@]}"; do [[ $name == "$f"* ]] && keep=yes; done
    [[ $keep == yes ]] || continue
  fi
  selected+=("$name")
done < "$out/targets.tsv"
if [[ ${#selected[@]} -eq 0 ]]; then
  echo "fuzz.sh: no fuzz target matches" >&2
  exit 2
fi

run_one() {
  local name="$1" wd cmd
  IFS=$'\t' read -r _ wd cmd < <(grep -P "^\Q$name\E\t" "$out/targets.tsv")
  local -a args
  mapfile -t args < <(echo "$cmd" | base64 -d)
  local -a final=()
  for a in "${args[@]}"; do
    [[ $a == -max_total_time=* ]] && continue
    final+=("$a")
  done
  local artifacts="$PWD/$build/fuzz-artifacts/$name/"
  mkdir -p "$artifacts"
  local limit=()
  [[ -n $seconds ]] && limit+=("-max_total_time=$seconds")
  [[ -n $runs ]] && limit+=("-runs=$runs")
  # The corpus folders come last on the command line; options go first.
  local -a opts=() dirs=()
  for a in "${final[@]:1}"; do
    if [[ $a == -* ]]; then opts+=("$a"); else dirs+=("$a"); fi
  done
  (cd "$wd" && nice -n 10 "${final[0]}" "${opts[@]}" "${limit[@]}" -print_final_stats=1 \
      -artifact_prefix="$artifacts" "${dirs[@]}") > "$out/$name.log" 2>&1
  echo $? > "$out/$name.rc"
}

echo "fuzz.sh: ${#selected[@]} targets, ${seconds:+$seconds s}${runs:+ $runs runs} each, $jobs at a time; logs in $out/"
running=0
for name in "${selected[@]}"; do
  run_one "$name" &
  running=$((running + 1))
  if [[ $running -ge $jobs ]]; then
    wait -n || true
    running=$((running - 1))
  fi
done
wait || true

failed=0
printf '%-34s %14s %9s %8s %8s %8s %7s  %s\n' target executions exec/s cov ft corpus crashes seeds
for name in "${selected[@]}"; do
  log="$out/$name.log"
  rc=$(cat "$out/$name.rc" 2>/dev/null || echo 1)
  execs=$(grep -oP 'stat::number_of_executed_units:\s+\K[0-9]+' "$log" | tail -1 || true)
  speed=$(grep -oP 'stat::average_exec_per_sec:\s+\K[0-9]+' "$log" | tail -1 || true)
  last=$(grep -P '^#[0-9]+\s+(DONE|pulse|NEW|REDUCE|INITED)' "$log" | tail -1 || true)
  cov=$(echo "$last" | grep -oP 'cov: \K[0-9]+' || true)
  ft=$(echo "$last" | grep -oP 'ft: \K[0-9]+' || true)
  corp=$(echo "$last" | grep -oP 'corp: \K[0-9]+' || true)
  crashes=$(find "$build/fuzz-artifacts/$name" -type f 2>/dev/null | wc -l)
  seeds=$(IFS=$'\t' read -r _ _ cmd < <(grep -P "^\Q$name\E\t" "$out/targets.tsv"); echo "$cmd" | base64 -d | grep -v '^-' | tail -n +3 | head -1)
  printf '%-34s %14s %9s %8s %8s %8s %7s  %s\n' "$name" "${execs:-?}" "${speed:-?}" "${cov:-?}" "${ft:-?}" "${corp:-?}" \
    "$crashes" "${seeds:-(none)}"
  if [[ $rc -ne 0 || $crashes -ne 0 ]]; then
    failed=1
    echo "  !! $name: exit $rc; inputs in $build/fuzz-artifacts/$name/; log $log" >&2
  fi
done
exit $failed
