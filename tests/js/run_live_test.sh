#!/usr/bin/env bash
# One live-view test, as ctest runs it: starts a run with --view, runs a node
# test against it, waits for the run, and exits with the test's code (0 pass,
# 1 fail, 77 skip when node, tests/js/node_modules or Chromium are absent).
#
#   run_live_test.sh PIROUETTE PORT client|browser WORK_DIR WORLD
#     client:  foxglove_client_test.mjs (the protocol through @foxglove/ws-protocol)
#     browser: browser_test.mjs (the page in headless Chromium; the screenshot
#              goes to WORK_DIR/live_view.png)
# PIROUETTE may be "mock": tests/js/mock_server.mjs stands in for the run (it
# ignores WORLD), to check the tests themselves.
set -uo pipefail
if [ $# -ne 5 ]; then
  echo "usage: $0 PIROUETTE PORT client|browser WORK_DIR WORLD" >&2
  exit 2
fi
pirouette=$1 port=$2 mode=$3 work=$4 world=$5
here=$(cd "$(dirname "$0")" && pwd)

case "$mode" in
  client) test=(foxglove_client_test.mjs) ;;
  browser) test=(browser_test.mjs) ;;
  *) echo "$0: mode $mode is neither client nor browser" >&2; exit 2 ;;
esac
if ! command -v node >/dev/null; then
  echo "SKIP: no node on PATH: run scripts/setup" >&2
  exit 77
fi
if [ "$(node -p 'process.versions.node.split(".")[0]')" -lt 20 ]; then
  echo "SKIP: node $(node --version) is older than the tests' packages need (20)" >&2
  exit 77
fi
if [ ! -d "$here/node_modules" ]; then
  echo "SKIP: $here/node_modules is missing: run scripts/setup (npm ci --prefix tests/js)" >&2
  exit 77
fi
if [ "$mode" = browser ] && [ ! -x "${CHROMIUM:-/usr/bin/chromium}" ]; then
  echo "SKIP: no Chromium at ${CHROMIUM:-/usr/bin/chromium}: run scripts/setup" >&2
  exit 77
fi

rm -rf "$work"
mkdir -p "$work"
out=$work/out
log=$work/run.log
if [ "$pirouette" = mock ]; then
  node "$here/mock_server.mjs" --port "$port" --out "$out" --linger 20 >"$log" 2>&1 &
else
  "$pirouette" explore --world "$world" --out "$out" --view "127.0.0.1:$port" --view-linger 20 \
    --quiet >"$log" 2>&1 &
fi
run_pid=$!

url=http://127.0.0.1:$port/
test+=("$url" "$out")
[ "$mode" = browser ] && test+=("$work/live_view.png")
node "$here/${test[0]}" "${test[@]:1}" &
test_pid=$!
# Stopped itself (ctest's timeout, Ctrl-C): the run and the test stop too.
trap 'kill "$run_pid" "$test_pid" 2>/dev/null; exit 1' INT TERM

# Waits for the test; when the run ends first, the test has 30 s more
# (5 s if the run failed) before it is stopped.
run_code=
killed=
while kill -0 "$test_pid" 2>/dev/null; do
  if [ -z "$run_code" ] && ! kill -0 "$run_pid" 2>/dev/null; then
    wait "$run_pid"
    run_code=$?
    [ "$run_code" -eq 0 ] && grace=300 || grace=50
    echo "the run exited with $run_code; the test has $((grace / 10)) s more" >&2
  fi
  if [ -n "$run_code" ]; then
    grace=$((grace - 1))
    if [ "$grace" -le 0 ]; then
      echo "FAIL: the test did not end after the run's end; stopping it" >&2
      kill "$test_pid" 2>/dev/null
      killed=1
      break
    fi
  fi
  sleep 0.1
done
wait "$test_pid"
code=$?
[ -n "$killed" ] && code=1
if [ -z "$run_code" ]; then
  # The run lingers until its clients have gone, at most --view-linger.
  for _ in $(seq 300); do kill -0 "$run_pid" 2>/dev/null || break; sleep 0.1; done
  if kill -0 "$run_pid" 2>/dev/null; then
    echo "FAIL: the run still serves 30 s after its last client left; stopping it" >&2
    kill "$run_pid" 2>/dev/null
    [ "$code" -eq 0 ] && code=1
  fi
  wait "$run_pid"
  run_code=$?
fi
if [ "$code" -ne 0 ] || [ "$run_code" -ne 0 ]; then
  echo "-- the run ($pirouette, exit $run_code), $log:" >&2
  tail -n 20 "$log" >&2
fi
if [ "$code" -eq 0 ] && [ "$run_code" -ne 0 ]; then
  echo "FAIL: the test passed but the run exited with $run_code" >&2
  code=1
fi
exit "$code"
