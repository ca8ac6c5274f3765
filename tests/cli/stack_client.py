"""A high-level client of the stacked pair's MC B (scripts/stack.sh), watching MC A's sim_truth:
what the stacked tests (stack_walk.py, stack_b_killed.py) share. Wall time only bounds the waits
(generous on a loaded machine); A's robot time judges."""
import math
import os
import sys

import lcm
from robot_control_cmd_lcmt import robot_control_cmd_lcmt
from robot_control_response_lcmt import robot_control_response_lcmt
from sim_truth_lcmt import sim_truth_lcmt

import heartbeat_spin

CMD_URL = "udpm://239.255.76.67:7671?ttl=0"       # B's high-level interface
RESPONSE_URL = "udpm://239.255.76.67:7670?ttl=0"
TRUTH_URL = "udpm://239.255.76.67:7680?ttl=0"     # A's sim_truth (config/stack/sim.yaml)
B_ODOMETRY_URL = "udpm://239.255.76.67:7672?ttl=0"  # where a simulation would take push and fault


def tilt_deg(q):
    """the trunk's tilt from upright, degrees, of a (w, x, y, z) quaternion"""
    w, x, y, z = q
    return math.degrees(math.acos(max(-1.0, min(1.0, 1.0 - 2.0 * (x * x + y * y)))))


class StackClient:
    def __init__(self, name):
        self.name = name
        self.commands = lcm.LCM(CMD_URL)
        self.responses = lcm.LCM(RESPONSE_URL)
        self.truth_lcm = lcm.LCM(TRUTH_URL)
        self.response = None
        self.truth = []
        self.responses.subscribe("robot_control_response", self._on_response)
        self.truth_lcm.subscribe("sim_truth", lambda _c, d: self.truth.append(sim_truth_lcmt.decode(d)))
        self.msg = robot_control_cmd_lcmt()

    def _on_response(self, _channel, data):
        self.response = robot_control_response_lcmt.decode(data)

    def fail(self, text):
        print("%s: FAILED: %s" % (self.name, text))
        # what the two MCs said besides their once-a-second state lines: the link's events, refusals
        for variable in ("STACK_B_LOG", "STACK_A_LOG"):
            if variable in os.environ and os.path.exists(os.environ[variable]):
                with open(os.environ[variable]) as log:
                    events = [line.rstrip() for line in log if not line.startswith(("t=", "    "))]
                print("%s: %s's events:\n  %s" % (self.name, variable[6], "\n  ".join(events[-25:])))
        sys.exit(1)

    def send(self, mode, gait):
        self.msg.mode, self.msg.gait_id = mode, gait
        self.msg.life_count = (self.msg.life_count + 1) % 128
        self.commands.publish("robot_control_cmd", self.msg.encode())

    def truth_s(self):
        """A's newest robot time, from its sim_truth"""
        return self.truth[-1].timestamp * 1e-9 if self.truth else 0.0

    def spin(self, wall_limit_s, until):
        return heartbeat_spin.spin(self.commands, self.msg, [self.responses, self.truth_lcm], wall_limit_s, until)

    def stand(self):
        """12 through B until it reports the stand done; A's robot time then"""
        self.send(12, 0)
        if not self.spin(60.0, lambda: self.response is not None and self.response.mode == 12
                         and self.response.order_process_bar >= 95):
            self.fail("B did not report the recovery stand done (mode 12, bar >= 95)")
        return self.truth_s()
