#!/usr/bin/env python3
"""The stacked pair in real time (issue 42): MC B (`cerebellum run`, the CyberDog2 motor SDK
backend) drives MC A (`cerebellum sim` serving the motor SDK). A high-level client on B stands the
robot up (12) and walks it (11/3) at VX m/s; judged on A's sim_truth in A's robot time: the trunk
stands at a standing height, the forward speed over the last seconds of the walk is within 15 % of
the command, and the robot never falls. `cerebellum push` at B is refused with the reason (B drives a
real robot). Then A is killed (the link cut): B reports the lost link
and damps within 50 ms of its own time (its log).

    PYTHONPATH=<generated python types> stack_walk.py CEREBELLUM VX
    (inside scripts/stack.sh: STACK_A_PID, STACK_B_LOG)
"""
import math
import os
import re
import signal
import subprocess
import sys
import time

import lcm
from robot_control_cmd_lcmt import robot_control_cmd_lcmt
from robot_control_response_lcmt import robot_control_response_lcmt
from sim_truth_lcmt import sim_truth_lcmt

import heartbeat_spin

CMD_URL = "udpm://239.255.76.67:7671?ttl=0"       # B's high-level interface
RESPONSE_URL = "udpm://239.255.76.67:7670?ttl=0"
TRUTH_URL = "udpm://239.255.76.67:7680?ttl=0"     # A's sim_truth (config/stack/sim.yaml)
B_ODOMETRY_URL = "udpm://239.255.76.67:7672?ttl=0"  # where a simulation would take push and fault
STAND_HEIGHT_M = (0.22, 0.30)
FALLEN_TILT_DEG = 35.0
FALLEN_HEIGHT_M = 0.15
WALK_S = 7.0           # of A's robot time
JUDGED_LAST_S = 3.0    # the speed over the walk's last seconds, once the gait has settled
SPEED_TOLERANCE = 0.15
DAMP_WITHIN_MS = 50.0


def tilt_deg(q):
    w, x, y, z = q
    return math.degrees(math.acos(max(-1.0, min(1.0, 1.0 - 2.0 * (x * x + y * y)))))


def fail(text):
    print("stack_walk: FAILED: " + text)
    # what the two MCs said besides their once-a-second state lines: the link's events, refusals
    for name in ("STACK_B_LOG", "STACK_A_LOG"):
        if name in os.environ and os.path.exists(os.environ[name]):
            with open(os.environ[name]) as log:
                events = [line.rstrip() for line in log if not line.startswith(("t=", "    "))]
            print("stack_walk: %s's events:\n  %s" % (name[6], "\n  ".join(events[-25:])))
    sys.exit(1)


def main():
    exe, vx = sys.argv[1], float(sys.argv[2])
    commands = lcm.LCM(CMD_URL)
    responses = lcm.LCM(RESPONSE_URL)
    truth = lcm.LCM(TRUTH_URL)
    seen = {"response": None, "truth": []}
    responses.subscribe("robot_control_response",
                        lambda _c, d: seen.__setitem__("response", robot_control_response_lcmt.decode(d)))
    truth.subscribe("sim_truth", lambda _c, d: seen["truth"].append(sim_truth_lcmt.decode(d)))
    msg = robot_control_cmd_lcmt()

    def send(mode, gait):
        msg.mode, msg.gait_id = mode, gait
        msg.life_count = (msg.life_count + 1) % 128
        commands.publish("robot_control_cmd", msg.encode())

    def truth_s():
        return seen["truth"][-1].timestamp * 1e-9 if seen["truth"] else 0.0

    # wall time only bounds the waits (generous on a loaded machine); robot time judges
    def spin(wall_limit_s, until):
        return heartbeat_spin.spin(commands, msg, [responses, truth], wall_limit_s, until)

    send(12, 0)
    if not spin(60.0, lambda: seen["response"] is not None and seen["response"].mode == 12
                and seen["response"].order_process_bar >= 95):
        fail("B did not report the recovery stand done (mode 12, bar >= 95)")
    stood_from = truth_s()
    spin(30.0, lambda: truth_s() >= stood_from + 1.0)
    standing = [t.position[2] for t in seen["truth"] if t.timestamp * 1e-9 >= stood_from]
    height_m = sum(standing) / max(1, len(standing))
    print("stack_walk: standing on A's truth at %.3f m (over %d samples)" % (height_m, len(standing)))
    if not STAND_HEIGHT_M[0] <= height_m <= STAND_HEIGHT_M[1]:
        fail("the trunk does not stand at %.2f .. %.2f m" % STAND_HEIGHT_M)

    msg.vel_des = [vx, 0.0, 0.0]
    msg.step_height = [0.05, 0.05]
    send(11, 3)
    walk_from = truth_s()
    if not spin(90.0, lambda: truth_s() >= walk_from + WALK_S):
        fail("A's truth stopped during the walk (%.1f s of %.1f s)" % (truth_s() - walk_from, WALK_S))
    walk = [t for t in seen["truth"] if t.timestamp * 1e-9 >= stood_from]
    worst_tilt = max(tilt_deg(t.quaternion) for t in walk)
    lowest = min(t.position[2] for t in walk)
    judged = [t for t in walk if t.timestamp * 1e-9 >= walk_from + WALK_S - JUDGED_LAST_S]
    span_s = (judged[-1].timestamp - judged[0].timestamp) * 1e-9
    speed = (judged[-1].position[0] - judged[0].position[0]) / span_s
    print("stack_walk: walking 11/3 at %.2f m/s asked: %.3f m/s on A's truth over its last %.1f s; "
          "largest tilt %.1f deg, lowest trunk %.3f m" % (vx, speed, span_s, worst_tilt, lowest))
    if worst_tilt > FALLEN_TILT_DEG or lowest < FALLEN_HEIGHT_M:
        fail("the robot fell")
    if abs(speed - vx) > SPEED_TOLERANCE * vx:
        fail("the speed is not within %.0f %% of the command" % (SPEED_TOLERANCE * 100))

    push = subprocess.run([exe, "push", "10", "0", "--url", B_ODOMETRY_URL, "--timeout", "10"],
                          capture_output=True, text=True)
    print("stack_walk: cerebellum push at B: exit %d, %s" % (push.returncode, push.stdout.strip()))
    if push.returncode != 1 or "this MC drives a real robot" not in push.stdout:
        fail("B did not refuse the push with its reason: " + push.stdout + push.stderr)

    # the link cut: A dies at once, as a robot's MC or its network would; B's report is the first
    # loss logged after it
    with open(os.environ["STACK_B_LOG"]) as log:
        lines_before_kill = sum(1 for _ in log)
    os.kill(int(os.environ["STACK_A_PID"]), signal.SIGKILL)
    pattern = re.compile(r"link lost at ([0-9.]+) s robot time: no spi_data or state_estimator for ([0-9.]+) ms")
    found = None
    end = time.time() + 10.0
    while found is None and time.time() < end:
        spin(0.2, lambda: False)
        with open(os.environ["STACK_B_LOG"]) as log:
            for line in list(log)[lines_before_kill:]:
                match = pattern.search(line)
                if match:
                    found = (float(match.group(1)), float(match.group(2)))
                    break
    if found is None:
        fail("B did not report the lost link within 10 s of A's death")
    print("stack_walk: A killed; B lost the link at %.3f s of its robot time after %.1f ms without state "
          "and damps (limit %.0f ms)" % (found[0], found[1], DAMP_WITHIN_MS))
    if found[1] > DAMP_WITHIN_MS:
        fail("B damped too late")
    # and the protection it took: its once-a-second line after the loss shows the damping
    protected = re.compile(r"^t=\s*([0-9.]+) s .*PROTECTED \((damping|motors off), causes 0x([0-9a-f]+)")
    end = time.time() + 10.0
    while time.time() < end:
        with open(os.environ["STACK_B_LOG"]) as log:
            # cause bit 0: a motor error (every motor reads disconnected while the link is lost)
            shown = [float(m.group(1)) for m in map(protected.search, log)
                     if m and float(m.group(1)) > found[0] and int(m.group(3), 16) & 0x01]
        if shown:
            print("stack_walk: B's report at %.2f s: protected for a motor that does not answer" % shown[0])
            print("stack_walk: ok")
            return
        time.sleep(0.2)
    fail("B's report never showed the protection after the lost link")


if __name__ == "__main__":
    main()
