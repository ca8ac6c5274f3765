#!/usr/bin/env bash
# The demo itself, on a built tree, inside a network namespace (scripts/demo.sh sets that up).
#   scripts/demo_run.sh [--short]
# Environment (for the tests): DEMO_OUT (default build/demo), CEREBELLUM_BIN, DEMO_TOUR_BIN,
# DEMO_RECORD_SIZE (default 1280x720; the video is 30 fps, rendered off-screen in software: the
# frames buffered during the run are rendered after it, which takes a while at 1280x720).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=${DEMO_OUT:-$root/build/demo}
cerebellum=${CEREBELLUM_BIN:-$root/build/src/cli/cerebellum}
tour=${DEMO_TOUR_BIN:-$root/build/examples/highlevel/cerebellum_demo_tour}
mkdir -p "$out"
sim=("$cerebellum" sim --config "$root/config/demo.yaml" --speed 1
     --record "$out/demo.mp4" --record-size "${DEMO_RECORD_SIZE:-1280x720}" --telemetry "$out/telemetry.csv")
# the sim's output goes to its log; the bar of the video's rendering after the run comes to this
# terminal (fd 3), and to nothing when the demo's own output is not a terminal
exec 3>&1
[[ -t 1 ]] && sim+=(--progress-to /dev/fd/3)
cd "$out"
echo "demo: starting the MC on the simulated robot (log: $out/sim.log)"
"${sim[@]}" > "$out/sim.log" 2>&1 &
sim_pid=$!
trap 'kill -INT $sim_pid 2>/dev/null || true' EXIT
# wait for the MC's ready line
for _ in $(seq 100); do
  grep -q "cerebellum ready" "$out/sim.log" && break
  kill -0 $sim_pid 2>/dev/null || { cat "$out/sim.log"; exit 1; }
  sleep 0.1
done
status=0
"$tour" "$@" || status=$?
kill -INT $sim_pid
echo "demo: the MC stopped; rendering the rest of the video"
wait $sim_pid || status=$?
trap - EXIT
/usr/bin/python3 "$root/scripts/plot_telemetry.py" "$out/telemetry.csv" --out "$out" > "$out/plots.log" 2>&1 || status=$?
echo
grep -E "^cerebellum stopped|^highlevel:" "$out/sim.log" || true
echo "video:     $out/demo.mp4"
echo "telemetry: $out/telemetry.csv"
echo "plots:     $(ls "$out"/*.png 2>/dev/null | tr '\n' ' ')"
exit $status
