#!/usr/bin/env bash
# `cerebellum gait upload` against a running MC: an unsafe parameter file is refused with its
# reason, the shipped moonwalk is stored (both results 0), and `cerebellum cmd raw --mode 62
# --gait 110` runs it from Off (the robot stands up first) to the end.
#   gait_upload.sh <cerebellum> <work dir> <source dir>   (with_sim.sh runs the MC)
set -u
cerebellum=$1
work=$2
gaits=$3/config/user_gaits
fail=0
# a landing point 0.3 m in front of the hip: no leg reaches it
sed '0,/landing_pos_des = \[0.050/s//landing_pos_des = [0.300/' "$gaits/moonwalk_params.toml" > "$work/far.toml"
"$cerebellum" gait upload "$gaits/moonwalk_def.toml" "$work/far.toml" > "$work/refused.log" 2>&1
status=$?
cat "$work/refused.log"
if [[ $status -ne 1 ]] || ! grep -q "far.toml: result 1 (refused): step 1: landing point of FR (x 0.300" "$work/refused.log"; then
  echo "WRONG: the unsafe parameters were not refused with their reason"; fail=1
fi
"$cerebellum" gait upload "$gaits/moonwalk_def.toml" "$gaits/moonwalk_params.toml" > "$work/upload.log" 2>&1
status=$?
cat "$work/upload.log"
if [[ $status -ne 0 ]] || ! grep -q "ready: run it" "$work/upload.log"; then
  echo "WRONG: the moonwalk was not stored"; fail=1
fi
"$cerebellum" cmd raw --mode 62 --gait 110 --timeout 40 --hold 2 > "$work/run.log" 2>&1
status=$?
cat "$work/run.log"
if [[ $status -ne 0 ]] || ! grep -q "mode 62 gait 110 reached" "$work/run.log"; then
  echo "WRONG: the uploaded gait did not run to its end as motion 62/110"; fail=1
fi
exit "$fail"
