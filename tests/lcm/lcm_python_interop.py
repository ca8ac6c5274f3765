#!/usr/bin/env python3
"""Python side of the lcm interop test; the generated modules must be on PYTHONPATH.

  encode robot_control_cmd   print the hex encoding of the known command
  encode motor_ctrl          print the hex encoding of the known motor command
  check robot_control_response HEX   decode HEX, exit 0 if it holds the known values
The known values are repeated in lcm_python_interop_test.cpp.
"""
import struct
import sys

from motor_ctrl_lcmt import motor_ctrl_lcmt
from robot_control_cmd_lcmt import robot_control_cmd_lcmt
from robot_control_response_lcmt import robot_control_response_lcmt


def known_robot_control_cmd():
    msg = robot_control_cmd_lcmt()
    msg.mode = 11
    msg.gait_id = 27
    msg.contact = 15
    msg.life_count = -100
    msg.vel_des = [0.5, -0.25, 1.3]
    msg.rpy_des = [0.1, -0.2, 0.3]
    msg.pos_des = [0.0, 0.0, 0.235]
    msg.acc_des = [i - 2.5 for i in range(6)]
    msg.ctrl_point = [0.01, 0.02, 0.03]
    msg.foot_pose = [0.05 * i for i in range(6)]
    msg.step_height = [0.03, 0.05]
    msg.value = 6
    msg.duration = 3000
    return msg


def known_motor_ctrl():
    msg = motor_ctrl_lcmt()
    msg.q_des = [0.1 * i - 0.6 for i in range(12)]
    msg.qd_des = [-0.5 * i for i in range(12)]
    msg.kp_des = [60.0 + i for i in range(12)]
    msg.kd_des = [2.0 + 0.25 * i for i in range(12)]
    msg.tau_des = [0.5 * (i - 6) for i in range(12)]
    return msg


def response_mismatches(msg):
    expected = {
        "mode": 62,
        "gait_id": 3,
        "contact": 0b1011,
        "order_process_bar": 95,
        "switch_status": 5,
        "ori_error": 1,
        "footpos_error": 0x0A5C,
    }
    wrong = [f"{name} = {getattr(msg, name)}, expected {value}"
             for name, value in expected.items() if getattr(msg, name) != value]
    for i, error in enumerate(msg.motor_error):
        if error & 0xFFFFFFFF != 0x80000000 | (1 << i):
            wrong.append(f"motor_error[{i}] = {error:#x}")
    return wrong


def main(argv):
    if argv[1:] == ["encode", "robot_control_cmd"]:
        print(known_robot_control_cmd().encode().hex())
        return 0
    if argv[1:] == ["encode", "motor_ctrl"]:
        print(known_motor_ctrl().encode().hex())
        return 0
    if len(argv) == 4 and argv[1:3] == ["check", "robot_control_response"]:
        try:
            msg = robot_control_response_lcmt.decode(bytes.fromhex(argv[3]))
        except (ValueError, struct.error) as error:
            print(f"decode failed: {error}")
            return 1
        wrong = response_mismatches(msg)
        for line in wrong:
            print(line)
        return 1 if wrong else 0
    print(__doc__, file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv))
