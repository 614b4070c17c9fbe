#!/usr/bin/env bash
# matchcast-loadgen against a real matchcast-server on loopback: 200
# spectators for 3 s, one of them stalled. The tool must report every
# healthy client connected, no gap, no error, and exit 0; the stalled one
# must not cost the others a frame.
#   loadgen_smoke.sh SERVER LOADGEN LOG
set -euo pipefail
server=$1 loadgen=$2 log=$3
out=$(mktemp -d)
"$server" --address 127.0.0.1 --port 0 --rcg "$log" --record-dir "" --max-connections-per-ip 0 \
  > "$out/server.txt" 2>&1 &
pid=$!
trap 'kill "$pid" 2>/dev/null || true; wait "$pid" 2>/dev/null || true; rm -rf "$out"' EXIT
port=""
for _ in $(seq 1 100); do  # at most 10 s for the server to listen
  port=$(sed -n 's|^Matchcast: open http://127.0.0.1:\([0-9]*\)/.*|\1|p' "$out/server.txt" | head -n 1)
  [ -n "$port" ] && break
  sleep 0.1
done
[ -n "$port" ] || { echo "server did not start:"; cat "$out/server.txt"; exit 1; }
timeout 60 "$loadgen" --port "$port" -n 200 --threads 2 --ramp 1000 --duration 3 --stalled 0.005 \
  --header-only --server-pid "$pid" | tee "$out/loadgen.txt"
grep -Eq '^healthy +clients +199: connected 199, failed 0, closed by server 0' "$out/loadgen.txt"
grep -Eq 'sequence: 0 gaps' "$out/loadgen.txt"
grep -q 'healthy clients: no drops, no gaps, no errors' "$out/loadgen.txt"
echo "loadgen smoke: ok"
