# Shared by the tests that run the seeds' example programs and user programs against
# `cerebellum sim` (source it from bash).

# seed_file <seeds dir>: prints the CyberDog2 seed (000_*.txt), or exits 77 (skipped) without it
seed_file() {
  local seed
  seed=$(ls "$1"/000_*.txt 2>/dev/null | head -1)
  if [[ -z "$seed" ]]; then
    echo "skipped: no seed 000_*.txt in $1 (shared/ is not beside the repository)" >&2
    exit 77
  fi
  echo "$seed"
}

# extract_code_block <seed> <heading regex> <fence regex> <out file> <text it must contain>:
# the first fenced block of that language after the heading, exactly as written
extract_code_block() {
  # the patterns go through the environment: awk -v would eat their backslashes
  heading="$2" fence="$3" awk '$0 ~ ENVIRON["heading"] {found = 1; next}
       found && $0 ~ ENVIRON["fence"] {inside = 1; next}
       inside && /^```/ {exit}
       inside {print}' "$1" > "$4"
  if ! grep -q "$5" "$4"; then
    echo "could not extract the example after /$2/ from $1"
    exit 1
  fi
  echo "extracted $(wc -l < "$4") lines from $1"
}

# build_seed_motor_example <seed> <work dir> <c++ compiler> <include dirs, ':'-separated>
#                          <libcyber_dog_motor_sdk.so>: the seed's motor SDK example (section 3.4),
# extracted and compiled unmodified as a user's build would (the SDK's include directories, the
# library, liblcm, threads; no extra includes) into <work dir>/seed_example_motor_ctrl; exits 1
# with the compiler's output when it does not compile
build_seed_motor_example() {
  local seed=$1 work=$2 cxx=$3 include_dirs=$4 sdk_library=$5
  local example="$work/seed_example_motor_ctrl.cpp"
  extract_code_block "$seed" '^### 3\.4' '^```c\+\+' "$example" "custom_interface.hpp"
  local flags=() dirs=() dir lcm_libs
  IFS=: read -r -a dirs <<< "$include_dirs"
  for dir in "${dirs[@]}"; do [[ -n "$dir" ]] && flags+=("-I$dir"); done
  lcm_libs=$(pkg-config --libs lcm 2>/dev/null || echo -llcm)
  # shellcheck disable=SC2086
  if ! "$cxx" -std=c++17 -fno-strict-aliasing "${flags[@]}" "$example" -o "$work/seed_example_motor_ctrl" \
       "$sdk_library" -Wl,-rpath,"$(dirname "$sdk_library")" $lcm_libs -pthread > "$work/compile.log" 2>&1; then
    echo "FAILED: the seed's example does not compile against custom_interface.hpp:"
    cat "$work/compile.log"
    exit 1
  fi
  echo "compiled unmodified"
}

# start_sim <log file> <cerebellum> <sim arguments...>: starts `cerebellum sim` in the background,
# sets sim_pid and waits for its ready line; exits 1 with the log when it does not start
start_sim() {
  local log=$1
  shift
  "$@" > "$log" 2>&1 &
  sim_pid=$!
  for _ in $(seq 300); do
    grep -q "cerebellum ready" "$log" && return 0
    kill -0 "$sim_pid" 2>/dev/null || break
    sleep 0.1
  done
  echo "the MC did not start:"
  cat "$log"
  kill "$sim_pid" 2>/dev/null
  exit 1
}

# start_truth_watch <log file> <generated python types dir>: watches the simulation's ground truth
# (channel sim_truth) in the background until the simulation stops; sets truth_pid
start_truth_watch() {
  PYTHONPATH="$2" /usr/bin/python3 "$(dirname "${BASH_SOURCE[0]}")/../scripts/sim_truth_watch.py" > "$1" 2>&1 &
  truth_pid=$!
}

# truth_value <log file> <key>: a final value of scripts/sim_truth_watch.py's summary
truth_value() {
  sed -n "s/^$2=//p" "$1"
}

# expect <description> <regex>: a line of $steps_log (the distinct responses, in order) matching
# regex at or after line $from; moves $from there and prints "seen", or prints MISSING and sets
# fail=1
expect() {
  local line
  line=$(tail -n +"$from" "$steps_log" | grep -n -m1 -E "$2" | cut -d: -f1)
  if [[ -z "$line" ]]; then
    echo "MISSING: $1 (/$2/ after line $from)"; fail=1; return
  fi
  from=$((from + line - 1))
  echo "seen: $1"
}

# start_status_recorder <cerebellum> <log file>: `cerebellum status` records the responses at
# 50 Hz in the background; sets status_pid
start_status_recorder() {
  "$1" status --rate 50 --count 100000 --timeout 10 > "$2" 2>&1 &
  status_pid=$!
}

# stop_status_recorder: stops the recorder (as Ctrl-C does) and waits for it
stop_status_recorder() {
  kill -INT "$status_pid" 2>/dev/null
  wait "$status_pid" 2>/dev/null
}

# distinct_steps <status log> <last field> <steps log>: the recorder's response lines cut to fields
# 1..last, repeats merged, in order
distinct_steps() {
  cut -d' ' -f1-"$2" "$1" | grep '^mode' | uniq > "$3"
}

# print_steps <steps log>: the steps, each run of lines that differ only in their progress bar as
# one line with the bar's first and last value ("bar 0..95"), so a failed test's output stays short
print_steps() {
  awk '{ bar = $6; key = $0; sub(/ bar [0-9]+ /, " bar * ", key) }
       key != last { if (NR > 1) flush(); last = key; first = bar; n = 0 }
       { final = bar; n++ }
       function flush(   line) { line = last; sub(/ bar \* /, " bar " (first == final ? first : first ".." final) " ", line)
                                 print line (n > 1 ? "  [" n " lines]" : "") }
       END { if (NR > 0) flush() }' "$1"
}
