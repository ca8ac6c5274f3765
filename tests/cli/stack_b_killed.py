#!/usr/bin/env python3
"""The stacked pair in real time (issue 42), B killed: a high-level client on MC B stands the robot
up (12), then B dies at once (SIGKILL, as a crashed MC or a cut network would stop its frames).
MC A, the robot, must protect itself as the vendor's own does, by the rule of the interface B
drove (STACK_ROBOT):
- cyberdog2-motor-sdk: its frames come late and then stop, so after 500 ms A reports err_flag bit 1
  in its log and damps; the trunk still stands 0.4 s after the kill (the last frame decays,
  nothing drops);
- zsibot-shm: the daemon's rule, no command frame for about 10 cycles (10 ms): the command is
  cleared and the motors damped, and A's log says so.
Either way, judged on A's sim_truth in A's robot time: the trunk stood, is down below 0.15 m within
3 s of the kill, and never tips over.

    PYTHONPATH=<generated python types> stack_b_killed.py
    (inside scripts/stack.sh: STACK_B_PID, STACK_A_LOG, STACK_ROBOT)
"""
import os
import signal
import time

from stack_client import StackClient, tilt_deg

STAND_HEIGHT_M = (0.22, 0.30)
STILL_STANDING_S = 0.4    # before the motor SDK's 500 ms loss rule: the last frame held, decayed
STILL_STANDING_M = 0.20
LYING_M = 0.15
LYING_WITHIN_S = 3.0
TIPPED_DEG = 35.0
# per robot: what A's log says when its protection acts, and whether the robot holds a while first
A_PROTECTION = {
    "cyberdog2-motor-sdk": ("motor sdk: err_flag 0x02: communication lost over 500 ms", True),
    "zsibot-shm": ("cycles: command cleared, motors damped", False),
}


def main():
    a_lost_line, holds_first = A_PROTECTION[os.environ.get("STACK_ROBOT", "cyberdog2-motor-sdk")]
    client = StackClient("stack_b_killed")
    stood_from = client.stand()
    client.spin(30.0, lambda: client.truth_s() >= stood_from + 1.0)
    height_m = client.truth[-1].position[2]
    print("stack_b_killed: standing on A's truth at %.3f m" % height_m)
    if not STAND_HEIGHT_M[0] <= height_m <= STAND_HEIGHT_M[1]:
        client.fail("the trunk does not stand at %.2f .. %.2f m" % STAND_HEIGHT_M)

    os.kill(int(os.environ["STACK_B_PID"]), signal.SIGKILL)
    killed_s = client.truth_s()
    # no client any more: listen to A's truth only (the heartbeat goes to a dead B, harmlessly)
    if not client.spin(60.0, lambda: client.truth_s() >= killed_s + LYING_WITHIN_S):
        client.fail("A's truth stopped after B was killed")
    after = [t for t in client.truth if t.timestamp * 1e-9 > killed_s]
    early = [t.position[2] for t in after if t.timestamp * 1e-9 <= killed_s + STILL_STANDING_S]
    down = [t for t in after if t.position[2] < LYING_M]
    worst_tilt = max(tilt_deg(t.quaternion) for t in after)
    print("stack_b_killed: B killed at %.2f s of A's time; lowest in the first %.1f s %.3f m; below %.2f m "
          "after %s; largest tilt %.1f deg"
          % (killed_s, STILL_STANDING_S, min(early) if early else float("nan"), LYING_M,
             "%.2f s" % (down[0].timestamp * 1e-9 - killed_s) if down else "never", worst_tilt))
    if holds_first and (not early or min(early) < STILL_STANDING_M):
        client.fail("the robot dropped before A's 500 ms loss rule")
    if not down:
        client.fail("the robot did not lie down within %.1f s of B's death" % LYING_WITHIN_S)
    if worst_tilt > TIPPED_DEG:
        client.fail("the robot tipped over")
    end = time.time() + 5.0
    while time.time() < end:
        with open(os.environ["STACK_A_LOG"]) as log:
            lines = [line.strip() for line in log if a_lost_line in line]
            if lines:
                print("stack_b_killed: A's log: " + lines[0])
                print("stack_b_killed: ok")
                return
        time.sleep(0.2)
    client.fail("A's log does not report the lost frames ('%s')" % a_lost_line)


if __name__ == "__main__":
    main()
