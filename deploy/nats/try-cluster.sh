#!/bin/sh
# Tries deploy/nats/nats-cluster.conf on one machine: three nats-server nodes
# on loopback (ports 14201-3, routes 16201-3, monitoring 18201-3) form a
# cluster with JetStream; then an origin on node 1 and an edge on node 3,
# each with its own user, and the edge must serve the origin's frames.
# Usage: deploy/nats/try-cluster.sh [path/to/matchcast-server]
# Prints "cluster: ok" and exits 0 on success. Stops everything it started.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
server=${1:-$here/../../build/server/app/matchcast-server}
nats=$(command -v nats-server || echo /usr/sbin/nats-server)
work=$(mktemp -d /tmp/matchcast-cluster.XXXXXX)
pids=""
cleanup() {
  for p in $pids; do kill "$p" 2>/dev/null || true; done
  sleep 1
  rm -rf "$work"
}
trap cleanup EXIT INT TERM

export NATS_HOST=127.0.0.1 NATS_ROUTE_1=nats-route://127.0.0.1:16201 \
  NATS_ROUTE_2=nats-route://127.0.0.1:16202 NATS_ROUTE_3=nats-route://127.0.0.1:16203 \
  MATCHCAST_ORIGIN_PASSWORD=origin-secret MATCHCAST_EDGE_PASSWORD=edge-secret
for i in 1 2 3; do
  NATS_NAME=nats-$i NATS_PORT=1420$i NATS_MONITOR_PORT=1820$i NATS_CLUSTER_PORT=1620$i \
    NATS_STORE=$work/store-$i "$nats" -c "$here/nats-cluster.conf" >"$work/nats-$i.log" 2>&1 &
  pids="$pids $!"
done

# Each node sees two routes (the other two), within 20 s.
for i in 1 2 3; do
  n=0
  until [ "$(curl -s http://127.0.0.1:1820$i/routez | grep -c '"remote_id"')" -ge 2 ]; do
    n=$((n + 1)); [ $n -lt 100 ] || { echo "cluster: node $i has no routes"; cat "$work/nats-$i.log"; exit 1; }
    sleep 0.2
  done
done
echo "cluster: three nodes, each with two routes"

"$server" --role origin --nats-url nats://origin:origin-secret@127.0.0.1:14201 --nats-replicas 3 \
  --port 0 --record-dir "" >"$work/origin.out" 2>"$work/origin.log" &
pids="$pids $!"
"$server" --role edge --nats-url nats://edge:edge-secret@127.0.0.1:14203,nats://edge:edge-secret@127.0.0.1:14202 \
  --port 0 --record-dir "" >"$work/edge.out" 2>"$work/edge.log" &
pids="$pids $!"

port=""
n=0
while [ -z "$port" ]; do
  n=$((n + 1)); [ $n -lt 150 ] || { echo "cluster: the edge did not start"; cat "$work/edge.log"; exit 1; }
  sleep 0.2
  port=$(sed -n 's|^Matchcast: open http://[0-9.]*:\([0-9]*\)/$|\1|p' "$work/edge.out")
done
# The edge's channel gains frames through the cluster (node 1 -> node 3).
frames() { curl -s "http://127.0.0.1:$port/channels" | sed -n 's/.*"frames":\([0-9]*\).*/\1/p'; }
n=0
until [ "$(frames)" ] && [ "$(frames)" -ge 40 ]; do
  n=$((n + 1)); [ $n -lt 150 ] || { echo "cluster: no frames at the edge"; tail -n 20 "$work/origin.log" "$work/edge.log" "$work/nats-3.log"; exit 1; }
  sleep 0.2
done
echo "cluster: the edge on node 3 serves the origin's frames from node 1 ($(frames) so far)"
# The keyframe stream has three replicas.
replicas=$(curl -s "http://127.0.0.1:18201/jsz?accounts=true&streams=true&config=true" | grep -o '"num_replicas": *[0-9]*' | head -n 1 | grep -o '[0-9]*$' || true)
echo "cluster: MATCHCAST_KEY replicas: ${replicas:-unknown}"
[ "${replicas:-0}" = 3 ] || { echo "cluster: the keyframe stream should have 3 replicas"; exit 1; }
grep -q nats_stream_ready "$work/origin.log" || { echo "cluster: the origin's stream is not ready"; cat "$work/origin.log"; exit 1; }
# Neither user was refused anything it needs (the edge's snapshot reads).
if grep -h Violation "$work"/nats-*.log; then echo "cluster: a node refused a request (above)"; exit 1; fi
echo "cluster: ok"
