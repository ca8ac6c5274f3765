#!/usr/bin/env bash
# `cerebellum sweep --slurm` through a real single-node Slurm started here (slurm_single_node.sh:
# munged, slurmctld, slurmd on 127.0.0.1, stopped at the end even on failure), compared run for
# run with the same sweep run locally: lockstep runs are deterministic, so results.csv must be
# the same bytes. Then Slurm unreachable: the refusal names what was tried. Runs inside
# scripts/netns_run.sh (tests/cli/CMakeLists.txt).
#   sweep_slurm_test.sh CEREBELLUM
set -euo pipefail
cerebellum=$(realpath "$1")
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
chmod 0755 "$work"
source "$here/slurm_single_node.sh"
trap 'slurm_stop; rm -rf "$work"' EXIT
cd "$work"

fail() {
  echo "FAIL: $*" >&2
  slurm_logs >&2 || true
  exit 1
}

# five cells of a few seconds of robot time: stand up, trot in place, a shove from the side
cat > shove.yaml <<'YAML'
duration_s: 6
robot: {sensor_noise: true}
commands:
  - {at_s: 0, mode: 12}
  - {at_s: 3, mode: 11, gait: 3}
pushes:
  - {at_s: 4.5, impulse_n_s: 0, direction_deg: 90}
settle_speed_m_s: 0.3
sweep:
  push_impulse_n_s: [0, 10, 20, 30, 45]
YAML

slurm_start "$work/slurm" || fail "the single-node Slurm did not start"

status=0
"$cerebellum" sweep shove.yaml --slurm --tasks 2 --time 10 --out slurm_out > slurm.txt 2>&1 || status=$?
[[ $status -le 1 ]] || fail "the Slurm sweep ended with $status: $(cat slurm.txt)"
grep -q 'Slurm job [0-9]*, 2 array tasks' slurm.txt || fail "no job was submitted: $(cat slurm.txt)"
[[ -s slurm_out/slurm/task-0.out && -s slurm_out/slurm/task-1.out ]] || fail "the array's tasks left no output"
[[ $(wc -l < slurm_out/results.csv) -eq 6 ]] || fail "not 5 rows: $(cat slurm_out/results.csv)"

status=0
"$cerebellum" sweep shove.yaml -j 2 --out local_out > local.txt 2>&1 || status=$?
[[ $status -le 1 ]] || fail "the local sweep ended with $status: $(cat local.txt)"
cmp slurm_out/results.csv local_out/results.csv ||
  fail "Slurm and local results differ:"$'\n'"$(diff slurm_out/results.csv local_out/results.csv)"

"$cerebellum" sweep --status slurm_out > status.txt 2>&1 || true
grep -q '5 cells: 5 finished' status.txt || fail "status: $(cat status.txt)"
grep -q 'Slurm job(s) [0-9]' status.txt || fail "status names no job: $(cat status.txt)"

# no controller: the refusal names sbatch and what the controller answered
slurm_stop
status=0
"$cerebellum" sweep shove.yaml --slurm --out down_out > down.txt 2>&1 || status=$?
[[ $status -eq 2 ]] || fail "with the controller down the exit status is $status, not 2: $(cat down.txt)"
grep -q 'Slurm is not reachable: /usr/bin/sbatch failed (exit [0-9]*): .*; the controller: /usr/bin/scontrol ping' down.txt ||
  fail "the refusal does not name what was tried: $(cat down.txt)"
status=0
"$cerebellum" sweep shove.yaml --slurm --sbatch /nowhere/sbatch --out down_out > none.txt 2>&1 || status=$?
[[ $status -eq 2 ]] || fail "a missing sbatch gave $status, not 2"
grep -q "Slurm is not reachable: no program '/nowhere/sbatch' (not an executable file)" none.txt || fail "$(cat none.txt)"
echo "PASS: $(tail -n +2 local_out/results.csv | cut -d, -f1-4 | tr '\n' ' ')"
