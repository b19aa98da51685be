#!/usr/bin/env bash
# The cost of watching a run (issue 23, docs/live_view.md "Measured"): the
# default world explored N times without the live view and N times with
# --view and two clients subscribed to every channel; prints each run's wall
# time (run.json) and the clients' bytes, bytes per stop and map delays.
# Usage: bench/live_view/measure.sh [N] [WORLD]   (after scripts/build release)
set -euo pipefail
cd "$(dirname "$0")/../.."
n=${1:-5}
world=${2:-worlds/soccer_field.yaml}
bin=build/release/apps/pirouette/pirouette
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
port=18790
for i in $(seq 1 "$n"); do
  "$bin" explore --world "$world" --out "$work/plain$i" --quiet
  plain=$(python3 -c "import json;print(json.load(open('$work/plain$i/run.json'))['wall_time_s'])")
  "$bin" explore --world "$world" --out "$work/view$i" --quiet --view "$port" --view-linger 10 &
  pid=$!
  node bench/live_view/watch_client.mjs "ws://127.0.0.1:$port/" > "$work/c1.json" &
  c1=$!
  node bench/live_view/watch_client.mjs "ws://127.0.0.1:$port/" > "$work/c2.json" &
  c2=$!
  wait $c1 $c2 $pid
  viewed=$(python3 -c "import json;print(json.load(open('$work/view$i/run.json'))['wall_time_s'])")
  echo "run $i: wall $plain s without the view, $viewed s with it and two clients"
  echo "  client 1: $(cat "$work/c1.json")"
  echo "  client 2: $(cat "$work/c2.json")"
done
