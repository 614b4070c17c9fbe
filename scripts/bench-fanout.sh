#!/usr/bin/env bash
# Fan-out benchmark: the relay on one core, matchcast-loadgen on the other.
#
#   scripts/bench-fanout.sh [--sizes "1000 5000 9000"] [--duration 20] [--runs 2]
#                           [--anchor 'CMD {port}'] [--server-args '...'] [--both-cores]
#
# For each size it starts matchcast-server (--threads 1, no recording, the
# bundled game) pinned to core 0, runs matchcast-loadgen pinned to core 1
# (--header-only: it reads each frame's sequence number and the Unix-ms stamp
# at byte 18), and prints connected, delivered, delay p50/p99/max, server CPU
# per delivered message and user-space memory per spectator (RSS growth).
# With --anchor, the same load runs against that command too (its "{port}"
# is replaced by a free port), the two alternating run by run, and each size
# ends with the ratios Matchcast / anchor. --both-cores: nothing pinned, the
# relay with --threads 0 (a thread per core) and the load generator with two
# threads, sharing the machine: run it over growing --sizes to find the most
# spectators that still get every frame at p99 <= 100 ms.
# Figures: server/relay/README.md.
set -euo pipefail
cd "$(dirname "$0")/.."

sizes="1000 5000 9000"
duration=20
runs=1
anchor=""
server_args=""
ramp=1500
both=""
while [[ $# -gt 0 ]]; do
  case "$1" in
    --sizes) sizes="$2"; shift 2 ;;
    --duration) duration="$2"; shift 2 ;;
    --runs) runs="$2"; shift 2 ;;
    --anchor) anchor="$2"; shift 2 ;;
    --server-args) server_args="$2"; shift 2 ;;
    --ramp) ramp="$2"; shift 2 ;;
    --both-cores) both=1; shift ;;
    -h|--help) sed -n '2,19p' "$0"; exit 0 ;;
    *) echo "bench-fanout: unknown argument $1" >&2; exit 2 ;;
  esac
done

server=build/server/app/matchcast-server
loadgen=build/server/tools/loadgen/matchcast-loadgen
if [[ ! -x $server || ! -x $loadgen ]]; then scripts/build.sh --target matchcast-server matchcast-loadgen; fi
if [[ $(nproc) -lt 2 ]]; then echo "bench-fanout: needs two cores (one for the relay, one for the load)" >&2; exit 2; fi
# Both ends hold one socket per spectator.
ulimit -n 65536 2>/dev/null || ulimit -n "$(ulimit -Hn)"
out=$(mktemp -d)
trap 'kill $(jobs -p) 2>/dev/null || true; rm -rf "$out"' EXIT

free_port() { python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1",0)); print(s.getsockname()[1])'; }
wait_port() {  # port, pid
  for _ in $(seq 100); do
    if (exec 3<>"/dev/tcp/127.0.0.1/$1") 2>/dev/null; then return 0; fi
    kill -0 "$2" 2>/dev/null || return 1
    sleep 0.1
  done
  return 1
}

# start NAME: starts the server NAME on core 0; sets pid and port.
start() {
  port=$(free_port)
  local pin=(taskset -c 0) threads=1
  if [[ -n $both ]]; then pin=(); threads=0; fi
  if [[ $1 == matchcast ]]; then
    # shellcheck disable=SC2086
    "${pin[@]}" "$server" --threads "$threads" --record-dir '' --port "$port" --max-connections-per-ip 0 \
      --max-clients 50000 $server_args >"$out/server.log" 2>&1 &
  else
    "${pin[@]}" bash -c "exec ${anchor//\{port\}/$port}" >"$out/server.log" 2>&1 &
  fi
  pid=$!
  wait_port "$port" "$pid" || { echo "bench-fanout: $1 did not start" >&2; cat "$out/server.log" >&2; exit 1; }
  sleep 1
}

# One run: prints "connected delivered_pct p50 p99 max cpu_us_per_msg cpu_us_per_frame kb_per_spectator gaps".
# Per message counts every WebSocket message delivered; per frame only the
# pose frames, so a server that sends extra messages (Matchcast's stamina,
# kick and director messages) is not flattered by them.
run() {  # name clients
  start "$1"
  local log="$out/$1-$2.log"
  local pin=(taskset -c 1) threads=1
  if [[ -n $both ]]; then pin=(); threads=2; fi
  "${pin[@]}" "$loadgen" --port "$port" -n "$2" --threads "$threads" --nice 0 --ramp "$ramp" \
    --duration "$duration" --header-only --server-pid "$pid" >"$log" 2>&1 || true
  kill -TERM "$pid" 2>/dev/null; wait "$pid" 2>/dev/null || true
  awk -v n="$2" -v d="$duration" '
    /^healthy  clients/ { gsub(",", ""); connected = $5 }
    /^ +frame delay/ && !got { p50 = $4; p99 = $7; max = $10; got = 1 }
    /^ +delivered/ && !gotd { msgs = $2; frames = $(NF-1); gotd = 1 }
    /^ +sequence:/ && !gots { gaps = $2; gots = 1 }
    /^server   cpu/ { cpu = $3; kb = $(NF-3); sub(/\(/, "", kb) }
    END {
      seconds = d; expected = n * 20 * seconds
      pct = expected > 0 ? 100 * frames / expected : 0
      us = msgs > 0 ? cpu * 1e6 / msgs : 0
      usf = frames > 0 ? cpu * 1e6 * seconds / frames : 0
      printf "%s %.1f %s %s %s %.2f %.2f %.2f %s\n", connected, pct, p50, p99, max, us, usf, kb, gaps
    }' "$log"
}

printf '%-10s %7s %9s %10s %8s %8s %8s %11s %12s %9s %5s\n' server clients connected "delivered%" p50_ms p99_ms max_ms \
  "cpu_us/msg" "cpu_us/frame" "KB/spect" gaps
for n in $sizes; do
  declare -A sum=()
  for r in $(seq "$runs"); do
    order=(matchcast)
    if [[ -n $anchor ]]; then
      # Alternate who goes first, so drift in the machine's load hits both.
      if (( r % 2 )); then order=(matchcast anchor); else order=(anchor matchcast); fi
    fi
    for name in "${order[@]}"; do
      read -r connected pct p50 p99 max us usf kb gaps < <(run "$name" "$n")
      printf '%-10s %7s %9s %10s %8s %8s %8s %11s %12s %9s %5s\n' "$name" "$n" "$connected" "$pct" "$p50" "$p99" "$max" \
        "$us" "$usf" "$kb" "$gaps"
      sum[$name.p99]=$(awk -v a="${sum[$name.p99]:-0}" -v b="$p99" 'BEGIN{print a+b}')
      sum[$name.us]=$(awk -v a="${sum[$name.us]:-0}" -v b="$us" 'BEGIN{print a+b}')
      sum[$name.usf]=$(awk -v a="${sum[$name.usf]:-0}" -v b="$usf" 'BEGIN{print a+b}')
      sum[$name.kb]=$(awk -v a="${sum[$name.kb]:-0}" -v b="$kb" 'BEGIN{print a+b}')
    done
  done
  if [[ -n $anchor ]]; then
    awk -v n="$n" -v p="${sum[matchcast.p99]}" -v pa="${sum[anchor.p99]}" -v u="${sum[matchcast.us]}" \
        -v ua="${sum[anchor.us]}" -v f="${sum[matchcast.usf]}" -v fa="${sum[anchor.usf]}" \
        -v k="${sum[matchcast.kb]}" -v ka="${sum[anchor.kb]}" 'BEGIN {
      printf "ratio      %7s  matchcast/anchor: p99 %.2f, cpu per message %.2f, per frame %.2f, memory per spectator %.2f\n",
        n, (pa > 0 ? p / pa : 0), (ua > 0 ? u / ua : 0), (fa > 0 ? f / fa : 0), (ka > 0 ? k / ka : 0) }'
  fi
  unset sum
done
