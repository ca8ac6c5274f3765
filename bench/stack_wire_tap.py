#!/usr/bin/env python3
"""The motor SDK link of the stacked pair as seen on the wire (bench/stack_figures.sh): neither end
of the CyberDog2's motor SDK echoes a frame, so a third process in the pair's network namespace
listens to both directions of the control URL and times them on its own clock:

- command -> next state: from each `motor_ctrl` (B's frame) to the first `spi_data` (A's state)
  after it. A lower bound of the command-to-state round trip: A takes a frame at its next 2 ms
  tick, and a frame that came in while a tick ran is first seen in the state a tick later.
- state -> next command: from each `spi_data` to B's first `motor_ctrl` after it (B's receive,
  compute and send).

Prints one line: both as p50 / p99 / max in ms, with the counts.

    PYTHONPATH=<generated python types> stack_wire_tap.py SECONDS [URL]
"""
import select
import sys
import time

import lcm


def percentiles(values):
    """p50 / p99 / max by nearest rank, in ms."""
    if not values:
        return "none seen"
    ordered = sorted(values)

    def rank(p):
        return ordered[min(len(ordered) - 1, max(0, int(-(-p * len(ordered) // 100)) - 1))]

    return "p50 %.2f / p99 %.2f / max %.2f ms" % (rank(50) * 1e3, rank(99) * 1e3, ordered[-1] * 1e3)


def main():
    seconds = float(sys.argv[1])
    url = sys.argv[2] if len(sys.argv) > 2 else "udpm://239.255.76.67:7667?ttl=0"
    events = []  # (time, "c" for a command or "s" for a state)
    lc = lcm.LCM(url)
    lc.subscribe("motor_ctrl", lambda *_: events.append((time.monotonic(), "c")))
    lc.subscribe("spi_data", lambda *_: events.append((time.monotonic(), "s")))
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        ready, _, _ = select.select([lc.fileno()], [], [], 0.05)
        if ready:
            lc.handle()
    command_to_state, state_to_command = [], []
    pending = {"c": [], "s": []}  # of each kind, the messages no message of the other kind followed yet
    for at, kind in events:
        other = "s" if kind == "c" else "c"
        answered = command_to_state if other == "c" else state_to_command
        answered.extend(at - sent for sent in pending[other])
        pending[other] = []
        pending[kind].append(at)
    commands = sum(1 for _, kind in events if kind == "c")
    print("motor SDK on the wire over %.0f s: %d commands, %d states; command -> next state %s; "
          "state -> next command %s" % (seconds, commands, len(events) - commands, percentiles(command_to_state),
                                        percentiles(state_to_command)))
    return 0 if commands and command_to_state else 1


if __name__ == "__main__":
    sys.exit(main())
