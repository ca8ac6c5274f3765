#!/usr/bin/env bash
# `cerebellum sweep` as a user runs it, one case per ctest (tests/cli/CMakeLists.txt):
#   sweep_cli_test.sh CASE CEREBELLUM
# Every run is a lockstep simulation inside the worker processes: no sockets, no wall clock in
# the results. Each case works in its own temporary folder, removed at the end.
set -euo pipefail
case_name=$1
cerebellum=$(realpath "$2")
root=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

# three cells of a robot standing up (cheap), the seeds as the axis
write_stand_sweep() {
  cat > stand.yaml <<'YAML'
duration_s: 3
robot: {sensor_noise: true}
commands:
  - {at_s: 0, mode: 12}
sweep:
  seed: [1, 2, 3]
YAML
}

case "$case_name" in
  runs_every_cell_and_a_rerun_continues)
    write_stand_sweep
    "$cerebellum" sweep stand.yaml -j 2 --out out > first.txt 2>&1 || fail "the sweep failed: $(cat first.txt)"
    [[ $(wc -l < out/results.csv) -eq 4 ]] || fail "results.csv has not a header and 3 rows: $(cat out/results.csv)"
    grep -q '^cell,seed,outcome,' out/results.csv || fail "header: $(head -1 out/results.csv)"
    [[ $(grep -c ',ok,' out/results.csv) -eq 3 ]] || fail "not 3 runs ok: $(cat out/results.csv)"
    grep -q '| all | 3 | 3 |' out/summary.md || fail "summary: $(cat out/summary.md)"
    # a progress bar only on a terminal: none in a file
    ! grep -q $'\r' first.txt || fail "a progress bar was drawn into a file"
    cp out/results.csv first.csv
    "$cerebellum" sweep stand.yaml -j 2 --out out > second.txt 2>&1 || fail "the rerun failed: $(cat second.txt)"
    grep -q '3 already finished in out, 0 to run' second.txt || fail "the rerun did not keep the cells: $(cat second.txt)"
    cmp -s first.csv out/results.csv || fail "the rerun changed the results"
    # one cell alone gives the sweep's row
    "$cerebellum" sweep stand.yaml --cell 1 > alone.txt 2>&1 || fail "the replay failed: $(cat alone.txt)"
    [[ "$(sed -n 2p alone.txt)" == "$(sed -n 3p out/results.csv)" ]] || fail "the replay's row differs: $(cat alone.txt)"
    # the plots of the results
    /usr/bin/python3 "$root/scripts/plot_sweep.py" out > plot.txt 2>&1 || fail "plot_sweep failed: $(cat plot.txt)"
    for png in outcomes_by_seed falls max_tilt; do
      [[ -s out/plots/$png.png ]] || fail "no $png.png: $(cat plot.txt)"
    done
    echo "PASS"
    ;;
  a_crashed_worker_marks_its_cell_and_the_sweep_goes_on)
    # cell 1 runs for a simulated day, so it is surely running when it is killed
    cat > crash.yaml <<'YAML'
end_after_last_push_s: 0.5
commands:
  - {at_s: 0, mode: 12}
pushes:
  - {at_s: 1, impulse_n_s: 0}
sweep:
  push_at_s: [1, 86400, 2]
YAML
    "$cerebellum" sweep crash.yaml -j 3 --out out > sweep.txt 2>&1 &
    sweep_pid=$!
    worker=""
    for _ in $(seq 1 600); do
      worker=$(pgrep -P "$sweep_pid" -f -- '--cell 1 ' || true)
      [[ -n "$worker" ]] && break
      sleep 0.1
    done
    [[ -n "$worker" ]] || fail "cell 1's worker never started"
    kill -KILL "$worker"
    status=0
    wait "$sweep_pid" || status=$?
    [[ $status -eq 3 ]] || fail "exit status $status, not 3 (a cell crashed): $(cat sweep.txt)"
    grep -q '^1,86400,1,crashed,' out/results.csv || fail "cell 1 is not marked crashed: $(cat out/results.csv)"
    [[ $(grep -c ',ok,' out/results.csv) -eq 2 ]] || fail "the other cells did not finish: $(cat out/results.csv)"
    grep -q 'cell 1 crashed (killed by signal 9' sweep.txt || fail "the crash was not reported: $(cat sweep.txt)"
    grep -q 'crashed (killed by signal 9 (Killed)) | out/cells/1.log | `cerebellum sweep .*crash.yaml --cell 1`' out/summary.md ||
      fail "the summary does not give the crash, its log and the replay: $(cat out/summary.md)"
    "$cerebellum" sweep --status out > status.txt 2>&1 || true
    grep -q '3 cells: 2 finished (ok 2), 1 crashed, 0 not run yet' status.txt || fail "status: $(cat status.txt)"
    echo "PASS"
    ;;
  a_grid_above_the_limit_needs_yes)
    {
      echo "duration_s: 1"
      echo "commands: [{at_s: 0, mode: 12}]"
      echo "pushes: [{at_s: 0.5, impulse_n_s: 1}]"
      echo "sweep:"
      echo "  seed: [$(seq -s, 1 101)]"
      echo "  push_impulse_n_s: [$(seq -s, 1 101)]"
    } > big.yaml
    status=0
    "$cerebellum" sweep big.yaml --out out > big.txt 2>&1 || status=$?
    [[ $status -eq 2 ]] || fail "exit status $status, not 2: $(cat big.txt)"
    grep -q 'the grid (seed 101 x push_impulse_n_s 101) has 10201 cells, more than 10000; give --yes' big.txt ||
      fail "no refusal: $(cat big.txt)"
    [[ ! -e out ]] || fail "a refused sweep created its folder"
    echo "PASS"
    ;;
  bad_input_is_refused_with_the_key)
    printf 'duration_s: 3\ncommands: [{at_s: 0, mode: 12}]\nsweep:\n  seed: []\n' > empty_axis.yaml
    status=0
    "$cerebellum" sweep empty_axis.yaml > out.txt 2>&1 || status=$?
    [[ $status -eq 2 ]] || fail "exit status $status, not 2"
    grep -q 'scenario empty_axis.yaml: sweep.seed has no values; give at least one' out.txt || fail "$(cat out.txt)"
    printf 'duration_s: [3\n' > malformed.yaml
    "$cerebellum" sweep malformed.yaml > out.txt 2>&1 && fail "a malformed file was accepted"
    grep -q 'scenario malformed.yaml: not valid YAML' out.txt || fail "$(cat out.txt)"
    "$cerebellum" sweep nowhere.yaml > out.txt 2>&1 && fail "a missing file was accepted"
    grep -q 'scenario nowhere.yaml: ' out.txt || fail "$(cat out.txt)"
    write_stand_sweep
    "$cerebellum" sweep stand.yaml --cell 3 > out.txt 2>&1 && fail "a cell outside the grid was accepted"
    grep -q -- '--cell 3 is outside the grid of 3 cells (0..2)' out.txt || fail "$(cat out.txt)"
    "$cerebellum" sweep stand.yaml --slice 2/2 > out.txt 2>&1 && fail "a bad slice was accepted"
    grep -q -- "--slice: '2' is not a whole number in \[0, 1\]" out.txt || fail "$(cat out.txt)"
    # a folder of another scenario is not mixed into
    mkdir other && printf 'x' > other/scenario.yaml
    "$cerebellum" sweep stand.yaml --out other > out.txt 2>&1 && fail "another sweep's folder was used"
    grep -q 'the output folder other holds a sweep of another scenario' out.txt || fail "$(cat out.txt)"
    "$cerebellum" sweep --status nothing_here > out.txt 2>&1 && fail "status of no sweep succeeded"
    grep -q 'nothing_here holds no sweep' out.txt || fail "$(cat out.txt)"
    echo "PASS"
    ;;
  a_replay_records_a_video)
    printf 'duration_s: 1\ncommands:\n  - {at_s: 0, mode: 12}\n' > short.yaml
    "$cerebellum" sweep short.yaml --cell 0 --record run.mp4 > replay.txt 2>&1 || fail "the replay failed: $(cat replay.txt)"
    grep -q '^0,1,ok,1.000,' replay.txt || fail "no row: $(cat replay.txt)"
    grep -q 'video of 30 frames written to run.mp4' replay.txt || fail "no video: $(cat replay.txt)"
    duration=$(ffprobe -v error -show_entries format=duration -of csv=p=0 run.mp4)
    [[ "$duration" == 1.000000 ]] || fail "the video lasts $duration s, not the run's 1 s"
    status=0
    "$cerebellum" sweep short.yaml --record run.mp4 > no_cell.txt 2>&1 || status=$?
    [[ $status -eq 2 ]] && grep -q -- '--record FILE.mp4 films one cell: give --cell K' no_cell.txt || fail "$(cat no_cell.txt)"
    echo "PASS"
    ;;
  *)
    fail "unknown case $case_name"
    ;;
esac
