#!/usr/bin/env python3
"""`cerebellum drive` end to end, paced in real time: SDL's virtual joystick, played from a script,
drives the program through the same game-controller path as a real pad, against `cerebellum sim`.
Judged on the simulation's truth (sim_truth) and the MC's responses:

1. drive_walk_unplug.pad: A stands the robot up, the left stick at 0.575 forward walks it: the
   slow trot at 0.3 m/s (half the travel past the 15 % dead zone, of the gait's 0.6 m/s); measured
   on the truth between 3 s and 8 s of walking, along the trunk's heading. Unplugged while walking:
   drive sends the stop and ends, the robot is still 1.5 s later.
2. drive_walk_damp.pad (a new drive, the robot damped by the first one's silence): A, the stick full
   forward, then B while walking: the MC reports mode 7 gait 0 within a second.
3. drive_damp_every_mode.pad: B from a stand (12), from a motion (62) and from a jump (16) under way:
   mode 7 gait 0 within a second each time.
4. drive_pose.pad: in mode 11, stick released, the right stick full up: the trunk's nose up (the
   truth's pitch, right-handed about the body's left axis, below -0.2 rad for the 0.3 rad asked).

    PYTHONPATH=<generated python types> drive_pad.py <cerebellum> <walk-unplug script> <walk-damp script>
"""
import math
import select
import subprocess
import sys
import time

import lcm
from robot_control_response_lcmt import robot_control_response_lcmt
from sim_truth_lcmt import sim_truth_lcmt

RESPONSE_URL = "udpm://239.255.76.67:7670?ttl=0"
TRUTH_URL = "udpm://239.255.76.67:7667?ttl=0"
WALK_START_S = 6.0      # the scripts' stick
UNPLUG_S = 14.0
EXPECTED_SPEED_M_S = 0.3
SPEED_TOLERANCE = 0.25  # of the expected speed
DAMP_PRESS_S = 9.0      # drive_walk_damp.pad
POSE_UP_S = 7.5         # drive_pose.pad: the right stick up
POSE_UNPLUG_S = 11.0


def heading(q):
    w, x, y, z = q
    return math.atan2(2.0 * (w * z + x * y), 1.0 - 2.0 * (y * y + z * z))


def run_drive(exe, script, seconds):
    """runs drive with the script for seconds of wall time; returns (truth, responses, output) with
    each sample's time since drive started"""
    responses = lcm.LCM(RESPONSE_URL)
    truth = lcm.LCM(TRUTH_URL)
    seen = {"truth": [], "response": []}
    start = time.time()
    responses.subscribe("robot_control_response", lambda _c, d: seen["response"].append(
        (time.time() - start, robot_control_response_lcmt.decode(d))))
    truth.subscribe("sim_truth", lambda _c, d: seen["truth"].append((time.time() - start, sim_truth_lcmt.decode(d))))
    drive = subprocess.Popen([exe, "drive", "--ttl", "0", "--virtual-pad", script], stdout=subprocess.PIPE,
                             stderr=subprocess.STDOUT, text=True)
    while time.time() - start < seconds:
        ready, _, _ = select.select([responses.fileno(), truth.fileno()], [], [], 0.01)
        if responses.fileno() in ready:
            responses.handle()
        if truth.fileno() in ready:
            truth.handle()
    try:
        output, _ = drive.communicate(timeout=5)
    except subprocess.TimeoutExpired:
        drive.kill()
        output, _ = drive.communicate()
        sys.exit("drive_pad: drive did not end after the pad was unplugged:\n" + output)
    print(output, end="")
    if drive.returncode != 0:
        sys.exit("drive_pad: drive exited with %d" % drive.returncode)
    return seen["truth"], seen["response"], output


def walk_and_unplug(exe, script):
    truth, _, output = run_drive(exe, script, UNPLUG_S + 3.0)
    window = [t for at, t in truth if WALK_START_S + 3.0 <= at <= WALK_START_S + 8.0]
    if len(window) < 2:
        sys.exit("drive_pad: no truth while walking")
    first, last = window[0], window[-1]
    dt = (last.timestamp - first.timestamp) * 1e-9
    yaw = heading(first.quaternion)
    dx, dy = last.position[0] - first.position[0], last.position[1] - first.position[1]
    forward = (dx * math.cos(yaw) + dy * math.sin(yaw)) / dt
    sideways = (-dx * math.sin(yaw) + dy * math.cos(yaw)) / dt
    print("drive_pad: walked %.3f m/s forward, %.3f m/s sideways (commanded %.2f forward)" %
          (forward, sideways, EXPECTED_SPEED_M_S))
    if abs(forward - EXPECTED_SPEED_M_S) > SPEED_TOLERANCE * EXPECTED_SPEED_M_S or abs(sideways) > 0.1:
        sys.exit("drive_pad: the robot did not walk forward at the commanded speed")
    if "gamepad unplugged: sent the stop" not in output:
        sys.exit("drive_pad: drive did not send the stop when the pad was unplugged")
    after = [t for at, t in truth if at >= UNPLUG_S + 1.5]
    fastest = max((math.hypot(t.velocity[0], t.velocity[1]) for t in after), default=None)
    if fastest is None:
        sys.exit("drive_pad: no truth after the unplug")
    print("drive_pad: unplugged: at most %.3f m/s from 1.5 s after" % fastest)
    if fastest > 0.1:
        sys.exit("drive_pad: the robot did not stop after the pad was unplugged")


def damp_from(exe, script, presses, seconds):
    """presses: (the script's time of B, the mode running just before it)"""
    _, responses, _ = run_drive(exe, script, seconds)
    for press_s, mode in presses:
        before = [r.mode for at, r in responses if press_s - 0.3 <= at < press_s]
        # within a second of the press: later the heartbeat timeout after the unplug damps too
        damped = [at for at, r in responses if press_s <= at <= press_s + 1.0 and r.mode == 7 and r.gait_id == 0]
        if not before or before[-1] != mode:
            sys.exit("drive_pad: mode %d was not running before the damp button at %.1f s (%s)" % (mode, press_s, before))
        if not damped:
            sys.exit("drive_pad: the damp button in mode %d did not bring mode 7" % mode)
        print("drive_pad: damp button in mode %d: mode 7 after %.2f s" % (mode, damped[0] - press_s))


def pitch_of(q):
    w, x, y, z = q
    return math.asin(max(-1.0, min(1.0, 2.0 * (w * y - z * x))))


def head_up(exe, script):
    truth, _, _ = run_drive(exe, script, POSE_UNPLUG_S + 1.0)
    window = [pitch_of(t.quaternion) for at, t in truth if POSE_UP_S + 1.5 <= at <= POSE_UNPLUG_S - 0.5]
    if not window:
        sys.exit("drive_pad: no truth while the right stick was up")
    print("drive_pad: right stick up: trunk pitch %.3f .. %.3f rad (negative: nose up)" % (min(window), max(window)))
    if max(window) > -0.2:
        sys.exit("drive_pad: the right stick up did not raise the head")


def main():
    exe, walk_unplug, walk_damp, damp_every_mode, pose = sys.argv[1:6]
    walk_and_unplug(exe, walk_unplug)
    damp_from(exe, walk_damp, [(DAMP_PRESS_S, 11)], DAMP_PRESS_S + 3.0)
    damp_from(exe, damp_every_mode, [(5.0, 12), (12.0, 62), (18.0, 16)], 20.5)
    head_up(exe, pose)
    print("drive_pad: ok")


if __name__ == "__main__":
    main()
