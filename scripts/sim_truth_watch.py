#!/usr/bin/env python3
"""Watches the simulation's ground truth (channel sim_truth of `cerebellum sim`) and summarises it:
for judging a client program on what the simulated robot really did, not on the MC's estimate.

    PYTHONPATH=build/lcm/python /usr/bin/python3 scripts/sim_truth_watch.py [--idle S] [--url URL]

Runs until SIGINT / SIGTERM, or until no message arrived for --idle seconds after the first one
(the simulation stopped), then prints one summary line and the final state as KEY=VALUE lines
(final_x_m, final_y_m, final_height_m, final_tilt_deg, final_feet_down, lowest_height_m,
highest_height_m, largest_tilt_deg, largest_low_tilt_deg, messages). largest_low_tilt_deg is the
largest tilt while the trunk was below --low-height-m: a robot on its side or back is low and
tilted, one standing on its hind feet on purpose (mode 64) is tilted but high.
"""
import argparse
import math
import select
import signal
import sys
import time

import lcm
from sim_truth_lcmt import sim_truth_lcmt


def tilt_deg(q):
    """Angle between the trunk's up axis and the world's, from a (w, x, y, z) quaternion."""
    w, x, y, z = q
    up_z = 1.0 - 2.0 * (x * x + y * y)  # z component of the body z axis in the world
    return math.degrees(math.acos(max(-1.0, min(1.0, up_z))))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--url", default="udpm://239.255.76.67:7667?ttl=0", help="the odometry URL of the sim")
    parser.add_argument("--idle", type=float, default=1.5, help="seconds of silence that end the watch")
    parser.add_argument("--low-height-m", type=float, default=0.15,
                        help="below this trunk height a tilt counts in largest_low_tilt_deg")
    args = parser.parse_args()

    stop = []
    signal.signal(signal.SIGINT, lambda *_: stop.append(1))
    signal.signal(signal.SIGTERM, lambda *_: stop.append(1))
    messages = []

    def on_truth(_channel, data):
        messages.append(sim_truth_lcmt.decode(data))

    lc = lcm.LCM(args.url)
    lc.subscribe("sim_truth", on_truth)
    last_arrival = None
    while not stop:
        ready, _, _ = select.select([lc.fileno()], [], [], 0.1)
        if ready:
            lc.handle()
            last_arrival = time.monotonic()
        elif last_arrival is not None and time.monotonic() - last_arrival > args.idle:
            break

    if not messages:
        print("sim_truth: no message (is `cerebellum sim` running in this network namespace?)")
        return 1
    final = messages[-1]
    span_s = (final.timestamp - messages[0].timestamp) * 1e-9
    feet = "".join("1" if c else "0" for c in final.foot_contact)
    summary = {
        "messages": len(messages),
        "final_x_m": f"{final.position[0]:.3f}",
        "final_y_m": f"{final.position[1]:.3f}",
        "final_height_m": f"{final.position[2]:.3f}",
        "final_tilt_deg": f"{tilt_deg(final.quaternion):.1f}",
        "final_feet_down": feet,
        "lowest_height_m": f"{min(m.position[2] for m in messages):.3f}",
        "highest_height_m": f"{max(m.position[2] for m in messages):.3f}",
        "largest_tilt_deg": f"{max(tilt_deg(m.quaternion) for m in messages):.1f}",
        "largest_low_tilt_deg": f"{max([tilt_deg(m.quaternion) for m in messages if m.position[2] < args.low_height_m] + [0.0]):.1f}",
    }
    print(f"sim_truth: {len(messages)} messages over {span_s:.2f} s of simulated time; final height "
          f"{summary['final_height_m']} m, tilt {summary['final_tilt_deg']} deg, feet down (FR FL RR RL) {feet}")
    for key, value in summary.items():
        print(f"{key}={value}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
