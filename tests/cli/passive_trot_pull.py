#!/usr/bin/env python3
"""The passive trot (11/4) through the program, paced in real time: a high-level client stands the
robot (12), enters gait 4 as soon as the stand reports bar >= 95 with the 5 cm steps that
`cerebellum cmd walk --gait 4` asks for, and heartbeats it at 10 Hz; WAIT s later `cerebellum push
15 0 --duration PULL` pulls the trunk. Judged on the simulation's truth (sim_truth), in robot time:
the robot followed the pull, and once released it stands (all four feet down, trunk below
0.15 m/s, from then on) within 1.5 s.

    PYTHONPATH=<generated python types> passive_trot_pull.py <cerebellum> WAIT PULL
"""
import math
import subprocess
import sys

import lcm
from robot_control_cmd_lcmt import robot_control_cmd_lcmt
from robot_control_response_lcmt import robot_control_response_lcmt
from sim_truth_lcmt import sim_truth_lcmt

import heartbeat_spin

CMD_URL = "udpm://239.255.76.67:7671?ttl=0"
RESPONSE_URL = "udpm://239.255.76.67:7670?ttl=0"
TRUTH_URL = "udpm://239.255.76.67:7667?ttl=0"
STEP_HEIGHT_M = 0.05
LIMIT_S = 1.5


def main():
    exe, wait_s, pull_s = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
    commands = lcm.LCM(CMD_URL)
    responses = lcm.LCM(RESPONSE_URL)
    truth = lcm.LCM(TRUTH_URL)
    seen = {"response": None, "truth": None}
    responses.subscribe("robot_control_response",
                        lambda _c, d: seen.__setitem__("response", robot_control_response_lcmt.decode(d)))
    truth.subscribe("sim_truth", lambda _c, d: seen.__setitem__("truth", sim_truth_lcmt.decode(d)))
    msg = robot_control_cmd_lcmt()

    def send(mode, gait):
        msg.mode, msg.gait_id = mode, gait
        msg.life_count = (msg.life_count + 1) % 128
        commands.publish("robot_control_cmd", msg.encode())

    def spin(seconds, each=None, until=None):
        on_truth = (lambda lc: each(seen["truth"]) if lc is truth else None) if each else None
        return heartbeat_spin.spin(commands, msg, [responses, truth], seconds, until, on_truth)

    send(12, 0)
    if not spin(15.0, until=lambda: seen["response"] is not None and seen["response"].mode == 12
                and seen["response"].order_process_bar >= 95):
        sys.exit("passive_trot_pull: the recovery stand did not finish")
    msg.step_height = [STEP_HEIGHT_M, STEP_HEIGHT_M]
    send(11, 4)
    spin(wait_s)
    start = seen["truth"]
    subprocess.run([exe, "push", "15", "0", "--duration", str(pull_s)], check=True, stdout=subprocess.DEVNULL)
    pushed_ns = seen["truth"].timestamp
    release_ns = pushed_ns + int(pull_s * 1e9)
    state = {"stood_ns": None, "last": None}

    def each(t):
        if t.timestamp < release_ns:
            return
        standing = all(t.foot_contact) and math.hypot(t.velocity[0], t.velocity[1]) < 0.15
        if not standing:
            state["stood_ns"] = None
        elif state["stood_ns"] is None:
            state["stood_ns"] = t.timestamp
        state["last"] = t

    spin(pull_s + 4.0, each)
    last = state["last"]
    if last is None:
        sys.exit("passive_trot_pull: no truth after the release")
    moved_m = last.position[0] - start.position[0]
    print("passive_trot_pull: wait %.1f s, pull %.1f s: moved %.2f m along the pull" % (wait_s, pull_s, moved_m))
    if moved_m < 0.3:
        sys.exit("passive_trot_pull: it did not follow the pull")
    if state["stood_ns"] is None:
        sys.exit("passive_trot_pull: still stepping %.1f s after the release" % ((last.timestamp - release_ns) * 1e-9))
    stood_s = (state["stood_ns"] - release_ns) * 1e-9
    print("passive_trot_pull: released, standing after %.2f s (limit %.1f s)" % (stood_s, LIMIT_S))
    if stood_s > LIMIT_S:
        sys.exit("passive_trot_pull: too slow to stand")


if __name__ == "__main__":
    main()
