#!/usr/bin/env python3
"""The stacked pair in real time (issue 42), a jump through B: a high-level client on MC B stands
the robot up (12) and asks for the jump forward 30 cm (16/4). Judged on MC A's sim_truth in A's
robot time: every foot leaves the ground at once (a jump, not a step), the trunk lands 30 cm
ahead within 10 cm, stands level (within 0.15 rad) and high (above 0.2 m) 3 s after the command,
never tips over, and B reports the jump done (mode 16, gait 4, bar 100).

    PYTHONPATH=<generated python types> stack_jump.py   (inside scripts/stack.sh)
"""
import math

from stack_client import StackClient, tilt_deg

FORWARD_M = 0.30
FORWARD_TOLERANCE_M = 0.10
SETTLE_S = 3.0
LEVEL_RAD = 0.15
STAND_M = 0.20
TIPPED_DEG = 35.0


def main():
    client = StackClient("stack_jump")
    stood_from = client.stand()
    client.spin(30.0, lambda: client.truth_s() >= stood_from + 1.0)
    start = client.truth[-1].position
    client.send(16, 4)
    jumped_from = client.truth_s()
    if not client.spin(60.0, lambda: client.truth_s() >= jumped_from + SETTLE_S):
        client.fail("A's truth stopped during the jump")
    after = [t for t in client.truth if t.timestamp * 1e-9 > jumped_from]
    airborne = any(not any(t.foot_contact) for t in after)
    end = after[-1]
    forward_m = end.position[0] - start[0]
    worst_tilt = max(tilt_deg(t.quaternion) for t in after)
    response = client.response
    print("stack_jump: 16/4 through B: airborne %s, landed %.3f m ahead (%.3f m sideways), standing at %.3f m, "
          "tilt %.1f deg at the end and %.1f deg at most; B reports mode %d gait %d bar %d"
          % ("yes" if airborne else "no", forward_m, end.position[1] - start[1], end.position[2],
             tilt_deg(end.quaternion), worst_tilt, response.mode, response.gait_id, response.order_process_bar))
    if not airborne:
        client.fail("no moment with every foot off the ground")
    if abs(forward_m - FORWARD_M) > FORWARD_TOLERANCE_M:
        client.fail("not %.2f m ahead within %.2f m" % (FORWARD_M, FORWARD_TOLERANCE_M))
    if worst_tilt > TIPPED_DEG or math.radians(tilt_deg(end.quaternion)) > LEVEL_RAD or end.position[2] < STAND_M:
        client.fail("it did not land standing")
    if (response.mode, response.gait_id, response.order_process_bar) != (16, 4, 100):
        client.fail("B does not report the jump done")
    print("stack_jump: ok")


if __name__ == "__main__":
    main()
