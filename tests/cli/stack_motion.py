#!/usr/bin/env python3
"""The stacked pair in real time (issue 42), a named motion through B: a high-level client on MC B
stands the robot up (12), runs the hand shake (62/2, config/motions) to its end and gets it down
(7/1). Judged on B's responses (the motion runs, reaches bar >= 95 and hands over to the pose hold
21/3; the get-down reaches bar 100) and on A's sim_truth in A's robot time: during the motion a
front foot is off the ground for at least half a second (the paw is given), the robot never tips
over nor sinks, and it lies at the end.

    PYTHONPATH=<generated python types> stack_motion.py   (inside scripts/stack.sh)
"""
from stack_client import StackClient, tilt_deg

PAW_UP_S = 0.5
TIPPED_DEG = 35.0
SUNK_M = 0.15
LYING_M = 0.15


def main():
    client = StackClient("stack_motion")
    stood_from = client.stand()
    client.spin(30.0, lambda: client.truth_s() >= stood_from + 0.5)
    seen = set()

    def motion_ended():
        r = client.response
        if r is not None and r.mode == 62 and r.gait_id == 2:
            seen.add("running")
            if r.order_process_bar >= 95:
                seen.add("nearly done")
        # the motion's entry ends with the motion: the pose hold follows
        return "running" in seen and r is not None and r.mode == 21 and r.gait_id == 3
    client.send(62, 2)
    motion_from = client.truth_s()
    if not client.spin(60.0, motion_ended):
        client.fail("B did not run the hand shake to its end (62/2 seen: %s)" % sorted(seen))
    motion_to = client.truth_s()
    during = [t for t in client.truth if motion_from <= t.timestamp * 1e-9 <= motion_to]
    dt_s = (during[-1].timestamp - during[0].timestamp) * 1e-9 / max(1, len(during) - 1)
    contacts = [list(t.foot_contact) for t in during]  # decoded lazily, readable once
    paw_up_s = max(sum(1 for c in contacts if not c[leg]) * dt_s for leg in (0, 1))
    worst_tilt = max(tilt_deg(t.quaternion) for t in during)
    lowest = min(t.position[2] for t in during)
    print("stack_motion: hand shake through B over %.2f s of A's time (reached bar >= 95: %s); a front foot "
          "off the ground %.2f s; largest tilt %.1f deg, lowest trunk %.3f m"
          % (motion_to - motion_from, "nearly done" in seen, paw_up_s, worst_tilt, lowest))
    if "nearly done" not in seen:
        client.fail("the hand shake did not reach bar >= 95")
    if paw_up_s < PAW_UP_S:
        client.fail("no front foot was off the ground for %.1f s on A's truth" % PAW_UP_S)
    if worst_tilt > TIPPED_DEG or lowest < SUNK_M:
        client.fail("the robot tipped or sank during the motion")

    client.send(7, 1)
    if not client.spin(30.0, lambda: client.response is not None and client.response.mode == 7
                       and client.response.order_process_bar >= 100):
        client.fail("B did not report the get-down done (7/1, bar 100)")
    down_from = client.truth_s()
    client.spin(10.0, lambda: client.truth_s() >= down_from + 0.5)
    final = client.truth[-1]
    print("stack_motion: got down through B: trunk at %.3f m on A's truth, tilt %.1f deg"
          % (final.position[2], tilt_deg(final.quaternion)))
    if final.position[2] > LYING_M:
        client.fail("the robot does not lie at the end")
    print("stack_motion: ok")


if __name__ == "__main__":
    main()
