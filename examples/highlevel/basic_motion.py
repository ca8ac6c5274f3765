#!/usr/bin/env python3
"""Basic motion on the CyberDog2 high-level interface: stand up (recovery stand), raise and lower
the head, set the body height (pose control), lie down.

Needs the generated message modules on PYTHONPATH (<build>/lcm/python, or
<prefix>/share/cerebellum/python when installed) and the `lcm` module (`pip install lcm`).
Runs against `cerebellum sim` with `highlevel.enabled: true`, or a CyberDog2. A step the MC refuses
(switch_status 5, BAN_TRANS) is reported and skipped. Ctrl-C sends PureDamper (7, 0).
"""
import sys
import threading
import time

try:
    import lcm
    lcm.LCM  # a directory called lcm/ on the path imports as an empty namespace package
except (ImportError, AttributeError):
    sys.exit("basic_motion.py: the Python module 'lcm' is missing: pip install lcm (see docs/highlevel.md)")
try:
    from robot_control_cmd_lcmt import robot_control_cmd_lcmt
    from robot_control_response_lcmt import robot_control_response_lcmt
except ImportError:
    sys.exit("basic_motion.py: put the generated types on PYTHONPATH: <build>/lcm/python")

COMMAND_URL = "udpm://239.255.76.67:7671?ttl=255"
RESPONSE_URL = "udpm://239.255.76.67:7670?ttl=255"
HEARTBEAT_PERIOD_S = 0.05   # the MC lies down after 0.5 s without a message
FINISHED_PERCENT = 95
BAN_TRANS = 5
RESPONSES_BEFORE_REFUSAL = 3


def next_life_count(value):
    """life_count is an int8 on the wire: wrap 127 -> -128."""
    return (value + 1 + 128) % 256 - 128


class HighLevelLink:
    """Sends commands with a fresh life_count, repeats the last one as a heartbeat, keeps the newest
    response."""

    def __init__(self):
        self.command_lcm = lcm.LCM(COMMAND_URL)
        self.response_lcm = lcm.LCM(RESPONSE_URL)
        self.response_lcm.subscribe("robot_control_response", self._on_response)
        self.lock = threading.Condition()
        self.command = None
        self.life_count = 0
        self.response = None
        self.responses = 0
        self.responses_at_send = 0
        self.running = True
        self.threads = [threading.Thread(target=self._receive), threading.Thread(target=self._heartbeat)]
        for thread in self.threads:
            thread.start()

    def _on_response(self, channel, data):
        response = robot_control_response_lcmt.decode(data)
        with self.lock:
            self.response = response
            self.responses += 1
            self.lock.notify_all()

    def _receive(self):
        while self.running:
            self.response_lcm.handle_timeout(20)

    def _heartbeat(self):
        while self.running:
            with self.lock:
                if self.command is not None:
                    self.command_lcm.publish("robot_control_cmd", self.command.encode())
            time.sleep(HEARTBEAT_PERIOD_S)

    def send(self, command):
        with self.lock:
            if self.command is None:
                # a mode -1 message only sets the MC's life_count, so the next one is new to it
                sync = robot_control_cmd_lcmt()
                sync.mode = -1
                sync.life_count = self.life_count
                self.command_lcm.publish("robot_control_cmd", sync.encode())
            self.life_count = next_life_count(self.life_count)
            command.life_count = self.life_count
            self.command = command
            self.responses_at_send = self.responses
            self.command_lcm.publish("robot_control_cmd", command.encode())

    def wait_for(self, mode, gait_id, timeout_s):
        """'reached' when the response reports mode/gait with order_process_bar >= 95, 'refused' when
        BAN_TRANS is still reported three responses after the send, else 'timeout'."""
        deadline = time.monotonic() + timeout_s
        with self.lock:
            while True:
                r = self.response
                if r is not None:
                    if r.mode == mode and r.gait_id == gait_id and r.order_process_bar >= FINISHED_PERCENT:
                        return "reached"
                    if r.switch_status == BAN_TRANS and self.responses >= self.responses_at_send + RESPONSES_BEFORE_REFUSAL:
                        return "refused"
                left = deadline - time.monotonic()
                if left <= 0:
                    return "timeout"
                self.lock.wait(min(left, 0.1))

    def close(self):
        self.running = False
        for thread in self.threads:
            thread.join()


def command(mode, gait_id, rpy_des=(0.0, 0.0, 0.0), pos_des=(0.0, 0.0, 0.0), duration_ms=0):
    msg = robot_control_cmd_lcmt()
    msg.mode = mode
    msg.gait_id = gait_id
    msg.contact = 0x0F
    msg.rpy_des = list(rpy_des)
    msg.pos_des = list(pos_des)
    msg.duration = duration_ms
    return msg


# (what, command, must complete)
STEPS = [
    ("stand up (recovery stand)", command(12, 0), True),
    ("head up", command(21, 0, rpy_des=(0.0, 0.3, 0.0), duration_ms=500), False),
    ("head down", command(21, 0, rpy_des=(0.0, -0.3, 0.0), duration_ms=300), False),
    ("body height 0.22 m", command(21, 5, pos_des=(0.0, 0.0, 0.22), duration_ms=400), False),
    ("lie down (PureDamper)", command(7, 0), True),
]


def main():
    link = HighLevelLink()
    failures = 0
    try:
        for what, msg, must_complete in STEPS:
            start = time.monotonic()
            link.send(msg)
            result = link.wait_for(msg.mode, msg.gait_id, 10.0)
            r = link.response
            if result == "reached":
                print("%s: mode %d gait %d reached in %.2f s" % (what, msg.mode, msg.gait_id, time.monotonic() - start))
            else:
                print("%s: mode %d gait %d %s; the MC reports mode %s gait %s switch_status %s" % (
                    what, msg.mode, msg.gait_id, result, r.mode if r else "-", r.gait_id if r else "-",
                    r.switch_status if r else "-"))
                failures += must_complete
            sys.stdout.flush()
            # a timed step holds for its duration before the next one is sent
            time.sleep(max(0.0, start + msg.duration / 1000.0 - time.monotonic()))
    except KeyboardInterrupt:
        print("interrupted: lying down (7, 0)")
        link.send(command(7, 0))
        link.wait_for(7, 0, 2.0)
        link.close()
        return 130
    link.close()
    print("basic_motion: %s" % ("done" if failures == 0 else "failed"))
    return 0 if failures == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
