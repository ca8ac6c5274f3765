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
import os
import re
import signal
import subprocess
import sys
import time

from stack_client import B_ODOMETRY_URL, StackClient, tilt_deg

STAND_HEIGHT_M = (0.22, 0.30)
FALLEN_TILT_DEG = 35.0
FALLEN_HEIGHT_M = 0.15
WALK_S = 7.0           # of A's robot time
JUDGED_LAST_S = 3.0    # the speed over the walk's last seconds, once the gait has settled
SPEED_TOLERANCE = 0.15
DAMP_WITHIN_MS = 50.0


def main():
    exe, vx = sys.argv[1], float(sys.argv[2])
    client = StackClient("stack_walk")
    fail, send, spin, truth_s, msg = client.fail, client.send, client.spin, client.truth_s, client.msg
    stood_from = client.stand()
    spin(30.0, lambda: truth_s() >= stood_from + 1.0)
    standing = [t.position[2] for t in client.truth if t.timestamp * 1e-9 >= stood_from]
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
    walk = [t for t in client.truth if t.timestamp * 1e-9 >= stood_from]
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

    # B's own figures, as `cerebellum status --diagnostics` shows them: its loop and its robot's link
    status = subprocess.run([exe, "status", "--ttl", "0", "--diagnostics", "--rate", "0.5", "--count", "2"],
                            capture_output=True, text=True, timeout=30)
    figures = [line for line in status.stdout.splitlines() if line.startswith("mc: loop period")]
    print("stack_walk: cerebellum status --diagnostics at B: %s" % (figures[-1] if figures else status.stdout))
    robot = {"cyberdog2-motor-sdk": "cyberdog2_motor_sdk", "zsibot-shm": "zsibot_shm"}[
        os.environ.get("STACK_ROBOT", "cyberdog2-motor-sdk")]
    if not figures or (" | %s link: state age p50 " % robot) not in figures[-1]:
        fail("B's status does not show its loop period and its link's figures")

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
    pattern = re.compile(r"link lost at ([0-9.]+) s robot time: no .+? for ([0-9.]+) ms")
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
