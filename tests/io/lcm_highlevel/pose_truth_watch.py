#!/usr/bin/env python3
"""Watches the simulation's ground truth (sim_truth) together with the MC's responses
(robot_control_response) while a client runs, and reports the trunk's pitch in the pose-control
phase (mode 21 gait 0): for judging the seed's "head up" / "head down" on what the simulated robot
really did. Pitch is right-handed about the body's y axis (to the left): negative is nose up.

    PYTHONPATH=<generated python types> python3 pose_truth_watch.py
    (SIM_TRUTH_URL: where the simulation's truth comes, when not on the default odometry url)

Runs until SIGINT / SIGTERM, then prints KEY=VALUE lines:
  most_nose_up_in_21_0_rad   the most nose-up pitch while the response said mode 21 gait 0
  pitch_when_21_5_came_rad   the pitch of the last truth sample before the response said 21/5
  samples_in_21_0            truth samples taken in that phase
"""
import os
import select
import signal
import sys

import lcm
from robot_control_response_lcmt import robot_control_response_lcmt
from sim_truth_lcmt import sim_truth_lcmt

TRUTH_URL = os.environ.get("SIM_TRUTH_URL", "udpm://239.255.76.67:7667?ttl=0")
RESPONSE_URL = "udpm://239.255.76.67:7670?ttl=0"


def pitch_of(q):
    """ZYX pitch of a (w, x, y, z) body-to-world quaternion."""
    w, x, y, z = q
    s = max(-1.0, min(1.0, 2.0 * (w * y - z * x)))
    import math
    return math.asin(s)


def main():
    stop = []
    signal.signal(signal.SIGINT, lambda *_: stop.append(1))
    signal.signal(signal.SIGTERM, lambda *_: stop.append(1))
    state = {"mode": None, "last_pitch": None, "before_21_5": None, "most_nose_up": None, "samples": 0}

    def on_response(_channel, data):
        r = robot_control_response_lcmt.decode(data)
        if (r.mode, r.gait_id) == (21, 5) and state["before_21_5"] is None and state["samples"] > 0:
            state["before_21_5"] = state["last_pitch"]
        state["mode"] = (r.mode, r.gait_id)

    def on_truth(_channel, data):
        t = sim_truth_lcmt.decode(data)
        pitch = pitch_of(t.quaternion)
        state["last_pitch"] = pitch
        if state["mode"] == (21, 0):
            state["samples"] += 1
            if state["most_nose_up"] is None or pitch < state["most_nose_up"]:
                state["most_nose_up"] = pitch

    truth = lcm.LCM(TRUTH_URL)
    truth.subscribe("sim_truth", on_truth)
    responses = lcm.LCM(RESPONSE_URL)
    responses.subscribe("robot_control_response", on_response)
    while not stop:
        ready, _, _ = select.select([truth.fileno(), responses.fileno()], [], [], 0.1)
        if responses.fileno() in ready:
            responses.handle()
        if truth.fileno() in ready:
            truth.handle()

    def show(value):
        return "none" if value is None else f"{value:.4f}"
    print(f"most_nose_up_in_21_0_rad={show(state['most_nose_up'])}")
    print(f"pitch_when_21_5_came_rad={show(state['before_21_5'])}")
    print(f"samples_in_21_0={state['samples']}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
