"""The loop of the real-time high-level client tests: repeats the last robot_control_cmd at 10 Hz
(the heartbeat that keeps a command alive) while it handles what arrives on the listened LCM
instances, until a condition holds or the wall-time limit passes (a limit only: the tests judge on
robot time)."""
import select
import time

HEARTBEAT_S = 0.1


def spin(commands, msg, listened, wall_limit_s, until=None, handled=None):
    """True once until() holds; handled(lc) is called after each lc.handle()."""
    end = time.time() + wall_limit_s
    beat = time.time() + HEARTBEAT_S
    while time.time() < end:
        if time.time() >= beat:
            commands.publish("robot_control_cmd", msg.encode())
            beat += HEARTBEAT_S
        ready, _, _ = select.select([lc.fileno() for lc in listened], [], [], 0.01)
        for lc in listened:
            if lc.fileno() in ready:
                lc.handle()
                if handled:
                    handled(lc)
        if until and until():
            return True
    return False
