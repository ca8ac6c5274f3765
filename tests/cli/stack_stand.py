#!/usr/bin/env python3
"""The stacked pair with the robot's own build as MC B (docs/robot-build.md): B, the static aarch64
program run under qemu's user-mode emulator, has activated A's motor mode (its ready line); a
high-level client on B stands the robot up (12). Judged on A's sim_truth in A's robot time: the
trunk stands at a standing height for a second and never tips over. Prints B's link events so
far (a link loss is what a loop too slow under qemu would show first); B's loop figures (ticks,
late substeps) are its stop line, in its log once scripts/stack.sh has stopped it.

    PYTHONPATH=<generated python types> stack_stand.py [SECONDS standing, default 1]
    (inside scripts/stack.sh: STACK_B_LOG)
"""
import os
import sys

from stack_client import StackClient, tilt_deg

STAND_HEIGHT_M = (0.22, 0.30)
STOOD_S = 1.0          # of A's robot time, after B reported the stand done
TIPPED_DEG = 35.0


def main():
    stood_s = float(sys.argv[1]) if len(sys.argv) > 1 else STOOD_S
    client = StackClient("stack_stand")
    stood_from = client.stand()
    if not client.spin(30.0 + stood_s, lambda: client.truth_s() >= stood_from + stood_s):
        client.fail("A's truth stopped after the stand")
    standing = [t.position[2] for t in client.truth if t.timestamp * 1e-9 >= stood_from]
    worst_tilt = max(tilt_deg(t.quaternion) for t in client.truth)
    print("stack_stand: standing on A's truth between %.3f and %.3f m over %.1f s (%d samples); largest tilt %.1f deg"
          % (min(standing), max(standing), stood_s, len(standing), worst_tilt))
    with open(os.environ["STACK_B_LOG"]) as log:
        link_lines = [line.rstrip() for line in log if line.startswith("cyberdog2:")]
    print("stack_stand: B's link events:\n  " + "\n  ".join(link_lines))
    if not all(STAND_HEIGHT_M[0] <= h <= STAND_HEIGHT_M[1] for h in standing):
        client.fail("the trunk did not stay between %.2f and %.2f m" % STAND_HEIGHT_M)
    if worst_tilt >= TIPPED_DEG:
        client.fail("the trunk tipped %.1f deg" % worst_tilt)
    print("stack_stand: ok")


if __name__ == "__main__":
    main()
