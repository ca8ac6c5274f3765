#!/usr/bin/env python3
"""Writes the fuzz targets' seed corpora (tests/fuzz/corpus/<target>/): valid inputs of each
decoder and a few broken ones, so fuzzing starts from the interesting shapes. Run once by hand;
the files are committed.

    PYTHONPATH=build/lcm/python /usr/bin/python3 tests/fuzz/make_corpus.py
"""
import os
import shutil
import struct
import sys

from motor_ctrl_lcmt import motor_ctrl_lcmt
from robot_control_cmd_lcmt import robot_control_cmd_lcmt
from file_send_lcmt import file_send_lcmt

root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus")
repo = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def write(target, name, data):
    folder = os.path.join(root, target)
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, name), "wb") as f:
        f.write(data if isinstance(data, bytes) else data.encode())


def crc32_words(data):
    crc = 0xFFFFFFFF
    for w in range(len(data) // 4 - 1):
        word = struct.unpack_from("<I", data, 4 * w)[0]
        for bit in range(31, -1, -1):
            carry = crc & 0x80000000
            crc = (crc << 1) & 0xFFFFFFFF
            if carry:
                crc ^= 0x04C11DB7
            if (word >> bit) & 1:
                crc ^= 0x04C11DB7
    return crc


def high_cmd(mode, gait=0, level=0, foot=0.0, height=0.0, pos=(0, 0), rpy=(0, 0, 0), vel=(0, 0), yaw=0.0, flag=0):
    frame = bytearray(113)
    frame[0] = flag
    frame[10], frame[11], frame[12] = mode, gait, level
    struct.pack_into("<10f", frame, 13, foot, height, *pos, *rpy, *vel, yaw)
    struct.pack_into("<I", frame, 109, crc32_words(bytes(frame)))
    return bytes(frame)


# AlienGo HighCmd: every mode, the example's values, a low-level frame, a short one
write("high_cmd", "idle", high_cmd(0))
write("high_cmd", "force_stand_roll", high_cmd(1, rpy=(0.7, 0, 0)))
write("high_cmd", "walk", high_cmd(2, vel=(0.2, 0), yaw=0.3))
write("high_cmd", "stairs", high_cmd(2, gait=2, vel=(0.1, 0), foot=0.1))
write("high_cmd", "to_position", high_cmd(3, level=2, pos=(1.0, -0.5), rpy=(0, 0, 0.5), height=-0.05))
for mode in (4, 5, 6, 7, 8, 9, 255):
    write("high_cmd", f"mode_{mode}", high_cmd(mode))
write("high_cmd", "low_level", high_cmd(0, flag=0xFF))
write("high_cmd", "short", high_cmd(2)[:60])

# robot_control_cmd and user_gait_file (file_send_lcmt) packets
cmd = robot_control_cmd_lcmt()
cmd.mode, cmd.gait_id, cmd.life_count = 11, 26, 3
cmd.vel_des = [0.5, 0.0, 0.2]
write("robot_control_cmd", "walk", cmd.encode())
cmd.mode, cmd.gait_id, cmd.duration = 62, 2, 3000
write("robot_control_cmd", "motion", cmd.encode())
write("robot_control_cmd", "truncated", cmd.encode()[:40])
gait = file_send_lcmt()
gait.data = "# Gait Def\n[[section]]\ncontact = [1, 1, 1, 1]\nduration = 10\n"
write("robot_control_cmd", "gait_file", gait.encode())

# motor_ctrl frames
frame = motor_ctrl_lcmt()
frame.q_des = [0.0, 0.8, -1.5] * 4
frame.kp_des = [60.0] * 12
frame.kd_des = [2.0] * 12
write("motor_ctrl", "stand", frame.encode())
write("motor_ctrl", "zero", motor_ctrl_lcmt().encode())
write("motor_ctrl", "truncated", frame.encode()[:100])

# user gait files: the forms of section 2.2 and broken ones
write("user_gait_file", "definition", "# Gait Def\n[[section]]\ncontact = [1, 1, 1, 1]\nduration = 10\n\n"
      "[[section]]\ncontact = [0, 1, 1, 0]\nduration = 4\n\n[[section]]\ncontact = [1, 0, 0, 1]\nduration = 5\n")
write("user_gait_file", "parameters", "# Gait Params\n[[step]]\nmode = 11\ngait_id = 110\ncontact = 15\n"
      "vel_des = [0.1, 0.0, 0.0]\nstep_height = [60010.0, 10060.0]\nvalue = 1\nduration = 300\n")
write("user_gait_file", "deep_key", "# Gait Def\n" + "a." * 200 + "b = 1\n")
write("user_gait_file", "no_header", "[[section]]\ncontact = [1, 1, 1, 1]\nduration = 1\n")

# motion files (the shipped ones are seeds too)
import glob
for path in sorted(glob.glob(os.path.join(repo, "config", "motions", "*.toml"))):
    write("motion_file", os.path.basename(path)[:-5], open(path).read())
write("motion_file", "nan_step", "id = 80\nname = \"n\"\n[[step]]\nmode = 21\ngait_id = 0\nrpy_des = [nan, 0, 0]\nduration = 5\n")
write("motion_file", "no_steps", "id = 80\nname = \"n\"\n")

# shared-memory command frames: four leg_control_t (4 joints of 5 floats, int32 flags)
def legs(p, v, kp, kd, t):
    return b"".join(struct.pack("<20fi", *([p, v, kp, kd, t] * 4), 1) for _ in range(4))
write("shm_command", "stand", legs(0.8, 0.0, 60.0, 2.0, 0.0))
write("shm_command", "zero", legs(0, 0, 0, 0, 0))
write("shm_command", "absurd", legs(1e30, -1e30, 1e9, -5.0, 1e6))

# sim_command texts
write("sim_command_text", "push", "push 10 0 0 1")
write("sim_command_text", "too_strong", "push 900 0 0 1")
write("sim_command_text", "nan", "push nan 0 0 1")
write("sim_command_text", "unknown", "teleport 1 2 3")
write("sim_command_text", "fault_motor", "fault motor FR_knee disconnected for 2")
write("sim_command_text", "fault_battery", "fault battery soc 15")
write("sim_command_text", "fault_bad", "fault motor 12 derated 1.5")
write("sim_command_text", "fault_link", "fault link highlevel drop 0.5")
write("fault_scenario", "scenario", "faults:\n  - at_s: 5\n    fault: motor FR_knee disconnected\n    duration_s: 4\n"
      "  - {at_s: 12, fault: battery soc 4}\n  - {at_s: 20, fault: clear}\n")
write("fault_scenario", "duplicate_key", "faults:\n  - {at_s: 1, fault: imu stuck, at_s: 2}\n")
write("fault_scenario", "bad_fault", "faults:\n  - {at_s: 1, fault: wheel 3 flat}\n")
write("fault_scenario", "not_a_list", "faults: {at_s: 1}\n")

# configuration files: the shipped ones and broken ones
for name in ("cerebellum.yaml", "demo.yaml", "robot-network.yaml"):
    with open(os.path.join(repo, "config", name), "rb") as f:
        write("config_yaml", name, f.read())
write("config_yaml", "unknown_key", "robot:\n  modle: x\n")
write("config_yaml", "wrong_type", "loop: {period_s: fast}\n")
write("config_yaml", "anchors", "a: &x [1, 2]\nb: *x\n")
print("corpora written to", root)
