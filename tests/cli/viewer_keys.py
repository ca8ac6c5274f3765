#!/usr/bin/env python3
"""The viewer's keyboard end to end, paced in real time: xdotool types into `cerebellum sim
--viewer`'s window through the X server (XTEST), as a person's keys would. Judged on the
simulation's truth (sim_truth) and the MC's responses (robot_control_response):

1. 1 stands the robot up; 3 walks (the slow trot); W held: forward at the gait's top speed
   (0.6 m/s, measured between 3 s and 6 s of holding, within 20 %); W released: still 2 s later.
2. space damps (mode 7 gait 0 within a second) from a walk and from a motion.
3. 5 jumps (mode 16, the trunk 15 cm above its stand); 4 runs the named motion (mode 62);
   2 lays the robot down (mode 7 gait 1, the trunk below 0.15 m).

    PYTHONPATH=<generated python types> viewer_keys.py   (on the display of the viewer)
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
WINDOW_TITLE = "cerebellum: simulated CyberDog2"
TOP_SPEED_M_S = 0.6  # the slow trot's velocity_max[0] (gait table)

# (seconds after the start, xdotool command, key)
SCRIPT = [
    (1.0, "key", "1"),       # stand up
    (4.0, "key", "3"),       # walk: the slow trot
    (5.0, "keydown", "w"),   # forward
    (12.0, "keyup", "w"),
    (15.0, "key", "space"),  # damp from the walk
    (17.0, "key", "1"),
    (21.0, "key", "5"),      # jump up
    (25.0, "key", "1"),
    (27.0, "key", "4"),      # the named motion
    (29.0, "key", "space"),  # damp from the motion
    (31.0, "key", "1"),
    (35.0, "key", "2"),      # lie down
]
END_S = 39.0


def xdotool(*args):
    return subprocess.run(["xdotool", *args], check=True, capture_output=True, text=True, timeout=20).stdout


def focus_window():
    window = xdotool("search", "--sync", "--onlyvisible", "--name", WINDOW_TITLE).split()[0]
    xdotool("windowfocus", window)
    # no window manager on the virtual display: the pointer inside the window keeps the focus there
    xdotool("mousemove", "--window", window, "300", "300")
    return window


def heading(q):
    w, x, y, z = q
    return math.atan2(2.0 * (w * z + x * y), 1.0 - 2.0 * (y * y + z * z))


def forward_speed(truth, start_s, end_s):
    window = [t for at, t in truth if start_s <= at <= end_s]
    if len(window) < 2:
        sys.exit("viewer_keys: no truth between %.1f s and %.1f s" % (start_s, end_s))
    first, last = window[0], window[-1]
    dt = (last.timestamp - first.timestamp) * 1e-9
    yaw = heading(first.quaternion)
    dx, dy = last.position[0] - first.position[0], last.position[1] - first.position[1]
    return (dx * math.cos(yaw) + dy * math.sin(yaw)) / dt


def first_response(responses, start_s, seconds, test):
    hits = [at for at, r in responses if start_s <= at <= start_s + seconds and test(r)]
    return hits[0] - start_s if hits else None


def main():
    focus_window()
    responses_lcm = lcm.LCM(RESPONSE_URL)
    truth_lcm = lcm.LCM(TRUTH_URL)
    truth, responses = [], []
    start = time.time()
    responses_lcm.subscribe("robot_control_response", lambda _c, d: responses.append(
        (time.time() - start, robot_control_response_lcmt.decode(d))))
    truth_lcm.subscribe("sim_truth", lambda _c, d: truth.append((time.time() - start, sim_truth_lcmt.decode(d))))
    steps = list(SCRIPT)
    while time.time() - start < END_S:
        if steps and time.time() - start >= steps[0][0]:
            _, command, key = steps.pop(0)
            xdotool(command, key)
        ready, _, _ = select.select([responses_lcm.fileno(), truth_lcm.fileno()], [], [], 0.01)
        if responses_lcm.fileno() in ready:
            responses_lcm.handle()
        if truth_lcm.fileno() in ready:
            truth_lcm.handle()

    fail = []
    standing = [t.position[2] for at, t in truth if 3.5 <= at <= 4.0]
    print("viewer_keys: 1: trunk %.3f m" % (standing[-1] if standing else float("nan")))
    if not standing or standing[-1] < 0.25:
        fail.append("1 did not stand the robot up")
    speed = forward_speed(truth, 8.0, 11.0)
    print("viewer_keys: W held: %.3f m/s forward (the slow trot's top speed %.2f)" % (speed, TOP_SPEED_M_S))
    if abs(speed - TOP_SPEED_M_S) > 0.2 * TOP_SPEED_M_S:
        fail.append("W did not walk forward at the gait's top speed")
    after = [math.hypot(t.velocity[0], t.velocity[1]) for at, t in truth if 14.0 <= at <= 15.0]
    print("viewer_keys: W released: at most %.3f m/s 2 s later" % max(after, default=float("nan")))
    if not after or max(after) > 0.1:
        fail.append("the robot did not stop when W was released")
    for press_s, what in ((15.0, "a walk"), (29.0, "a motion")):
        took = first_response(responses, press_s, 1.0, lambda r: r.mode == 7 and r.gait_id == 0)
        print("viewer_keys: space in %s: mode 7 after %s s" % (what, "%.2f" % took if took is not None else "never"))
        if took is None:
            fail.append("space did not damp from " + what)
    jumped = first_response(responses, 21.0, 1.5, lambda r: r.mode == 16)
    stand_height = [t.position[2] for at, t in truth if 20.0 <= at <= 21.0]
    peak = max((t.position[2] for at, t in truth if 21.0 <= at <= 24.0), default=0.0)
    rise = peak - (stand_height[-1] if stand_height else peak)
    print("viewer_keys: 5: mode 16 %s, the trunk rose %.3f m" % ("seen" if jumped is not None else "never seen", rise))
    if jumped is None or rise < 0.15:
        fail.append("5 did not jump")
    motion = first_response(responses, 27.0, 1.0, lambda r: r.mode == 62)
    print("viewer_keys: 4: mode 62 %s" % ("seen" if motion is not None else "never seen"))
    if motion is None:
        fail.append("4 did not run the motion")
    lying = first_response(responses, 35.0, 1.0, lambda r: r.mode == 7 and r.gait_id == 1)
    low = [t.position[2] for at, t in truth if 37.5 <= at <= 38.5]
    print("viewer_keys: 2: mode 7/1 %s, trunk %.3f m" % ("seen" if lying is not None else "never seen",
                                                         low[-1] if low else float("nan")))
    if lying is None or not low or low[-1] > 0.15:
        fail.append("2 did not lay the robot down")
    if fail:
        sys.exit("viewer_keys: " + "; ".join(fail))
    print("viewer_keys: ok")


if __name__ == "__main__":
    main()
