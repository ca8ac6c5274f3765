#!/usr/bin/env python3
"""The stacked pair in real time (issue 42) over a poor link: a high-level client on MC B stands the
robot up (12); then `cerebellum fault link LINK` on MC A drops 10 % of the command frames B sends
(motor_sdk: its motor_ctrl packets; shm: its lowlevel.h command frames, by STACK_ROBOT) and delays
the rest by 2 ms, and the client walks the robot at 1.0 m/s (11/3). Judged on A's sim_truth in A's
robot time: over the last 5 s of an 8 s walk the forward speed is within 10 % of the command and
the robot never falls; A took both faults.

    PYTHONPATH=<generated python types> stack_faulty_link.py CEREBELLUM   (inside scripts/stack.sh)
"""
import os
import subprocess
import sys

from stack_client import StackClient, TRUTH_URL, tilt_deg

VX_M_S = 1.0
WALK_S = 8.0
JUDGED_LAST_S = 5.0
SPEED_TOLERANCE = 0.10
FALLEN_TILT_DEG = 35.0
FALLEN_HEIGHT_M = 0.15
FAULTS = (["drop", "0.1"], ["delay", "0.002"])
# the link B's commands take into A, per robot
LINKS = {"cyberdog2-motor-sdk": "motor_sdk", "zsibot-shm": "shm"}


def main():
    exe = sys.argv[1]
    link = LINKS[os.environ.get("STACK_ROBOT", "cyberdog2-motor-sdk")]
    client = StackClient("stack_faulty_link")
    stood_from = client.stand()
    client.spin(30.0, lambda: client.truth_s() >= stood_from + 1.0)
    for fault in FAULTS:
        # A takes push and fault on the url of its sim_truth (config/stack/sim.yaml)
        taken = subprocess.run([exe, "fault", "link", link] + fault + ["--url", TRUTH_URL, "--timeout", "10"],
                               capture_output=True, text=True)
        print("stack_faulty_link: cerebellum fault link %s %s at A: exit %d, %s"
              % (link, " ".join(fault), taken.returncode, taken.stdout.strip()))
        if taken.returncode != 0:
            client.fail("A did not take the link fault: " + taken.stdout + taken.stderr)

    client.msg.vel_des = [VX_M_S, 0.0, 0.0]
    client.msg.step_height = [0.05, 0.05]
    client.send(11, 3)
    walk_from = client.truth_s()
    if not client.spin(90.0, lambda: client.truth_s() >= walk_from + WALK_S):
        client.fail("A's truth stopped during the walk")
    walk = [t for t in client.truth if t.timestamp * 1e-9 >= walk_from]
    judged = [t for t in walk if t.timestamp * 1e-9 >= walk_from + WALK_S - JUDGED_LAST_S]
    span_s = (judged[-1].timestamp - judged[0].timestamp) * 1e-9
    speed = (judged[-1].position[0] - judged[0].position[0]) / span_s
    worst_tilt = max(tilt_deg(t.quaternion) for t in walk)
    lowest = min(t.position[2] for t in walk)
    print("stack_faulty_link: walking 11/3 at %.1f m/s asked over a link dropping 10 %% and 2 ms late: %.3f m/s "
          "on A's truth over its last %.1f s; largest tilt %.1f deg, lowest trunk %.3f m"
          % (VX_M_S, speed, span_s, worst_tilt, lowest))
    if worst_tilt > FALLEN_TILT_DEG or lowest < FALLEN_HEIGHT_M:
        client.fail("the robot fell")
    if abs(speed - VX_M_S) > SPEED_TOLERANCE * VX_M_S:
        client.fail("the speed is not within %.0f %% of the command" % (SPEED_TOLERANCE * 100))
    print("stack_faulty_link: ok")


if __name__ == "__main__":
    main()
