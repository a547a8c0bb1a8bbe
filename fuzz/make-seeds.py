#!/usr/bin/env python3
# Writes the first seeds of every fuzz target into OUT/<target>/ from the spec's hex frames, the
# tests' known answers and resources/: run-campaign.sh merges them into fuzz/corpus/ (minimized).
import glob
import json
import os
import re
import sys

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(root, "build-fuzz", "seeds")
spec = sys.argv[2] if len(sys.argv) > 2 else "/work/shared/spec"


def seed(target, name, data):
    folder = os.path.join(out, target)
    os.makedirs(folder, exist_ok=True)
    if isinstance(data, str):
        data = data.encode()
    with open(os.path.join(folder, name), "wb") as f:
        f.write(data)


def read(path):
    with open(os.path.join(root, path), "rb") as f:
        return f.read()


# Hex frames: the spec documents' (runs of at least four hex pairs) and tests/specvectors.h's.
frames = []
for doc in sorted(glob.glob(os.path.join(spec, "*.md"))):
    with open(doc, encoding="utf-8") as f:
        for run in re.findall(r"(?:\b[0-9A-F]{2} ){3,}[0-9A-F]{2}\b", f.read()):
            frames.append(bytes.fromhex(run))
for run in re.findall(r'"([0-9A-F ]{16,})"', read("tests/specvectors.h").decode()):
    frames.append(bytes.fromhex(run.replace(" ", "")))
ptk = [f for f in frames if f[:2] == b"\xaf\xfa"]
feetech = [f for f in frames if f[:2] == b"\xff\xff"]

# Framers: byte 0 says how many piece sizes follow (0: the stream whole).
for target, family in (("ptk_framer", ptk), ("feetech_framer", feetech)):
    for i, frame in enumerate(family):
        seed(target, "frame-%03d" % i, b"\x00" + frame)
    stream = b"".join(family)
    seed(target, "all-whole", b"\x00" + stream)
    seed(target, "all-pieces", b"\x03\x01\x07\x02" + stream)
    seed(target, "noise", b"\x02\x05\x0b" + b"\x13\x37" + stream[: len(stream) // 2] + b"\x00" * 3
         + stream[len(stream) // 2:] + stream[:5])
    corrupt = bytearray(stream)
    for at in range(9, len(corrupt), 17):
        corrupt[at] ^= 0x5A
    seed(target, "corrupt", b"\x01\x04" + bytes(corrupt))

# Decoder: bytes as captured and as typed.
for i, frame in enumerate(ptk[:8] + feetech[:8]):
    seed("decoder", "bytes-%03d" % i, frame)
seed("decoder", "typed-spaced", " ".join("%02X" % b for b in ptk[0] + ptk[1]))
seed("decoder", "typed-0x", ",".join("0x%02x" % b for b in feetech[0] + feetech[-1]))
seed("decoder", "typed-run", "".join("%02x" % b for b in feetech[1]) + ":" + "AB-CD")
seed("decoder", "mixed", b"\x13" + ptk[0] + b"\xff" + feetech[0] + feetech[1][:-1])

# The tables and templates as the project ships them.
for family in ("scs", "sts", "sms", "hls"):
    seed("register_table", family + ".json", read("resources/feetech/registers-%s.json" % family))
seed("model_table", "models.json", read("resources/feetech/models.json"))
seed("simulator_data", "simulator.json", read("resources/feetech/simulator.json"))
for path in sorted(glob.glob(os.path.join(root, "resources/robots/*.json"))):
    name = os.path.basename(path)
    seed("robot_template", name, read(path))
    seed("settings_file", name, read(path))

# Profiles, as the tests write them.
profiles = {
    "ptk.json": {"format": "servobench-profile", "version": 1, "family": "ptk", "model": "",
                 "note": "bench", "parameters": {"min_pulse_us": 500, "max_pulse_us": 2500}},
    "sts.json": {"format": "servobench-profile", "version": 1, "family": "sts",
                 "model": "STS3215", "saved": "2026-11-24T12:00:00Z",
                 "parameters": {"p_gain": 22, "position_offset": 300, "max_angle_limit": 4000}},
    "scs.json": {"format": "servobench-profile", "version": 1, "family": "scs",
                 "parameters": {"p_gain": 10}},
    "newer.json": {"format": "servobench-profile", "version": 2, "family": "sts",
                   "parameters": {}},
}
for name, profile in profiles.items():
    text = json.dumps(profile, indent=2)
    seed("profile", name, text)
    seed("settings_file", "profile-" + name, text)

seed("pose", "pose.json", json.dumps(
    {"format": "servobench-pose", "version": 1, "name": "rest",
     "servos": [{"id": 1, "baud": 1000000, "position": 2048},
                {"id": 2, "baud": 1000000, "position": -300},
                {"id": 1, "baud": 115200, "position": 1234}]}, indent=2))
seed("pose", "fraction.json", '{"format": "servobench-pose", "version": 1, "servos": '
     '[{"id": 1, "baud": 1000000, "position": 10.5}]}')

seed("lerobot_calibration", "two-motors.json", json.dumps(
    {"shoulder_pan": {"id": 1, "drive_mode": 0, "homing_offset": -1200, "range_min": 800,
                      "range_max": 3300},
     "wrist_roll": {"id": 5, "drive_mode": 0, "homing_offset": 15, "range_min": 0,
                    "range_max": 4095}}, indent=4))
seed("lerobot_calibration", "one-past-the-last.json",
     '{"wrist_roll": {"id": 5, "drive_mode": 0, "homing_offset": 0, "range_min": 0, '
     '"range_max": 4096}}')
seed("lerobot_calibration", "one-motor.json",
     '{"gripper": {"id": 6, "drive_mode": 0, "homing_offset": 2047, "range_min": 0, '
     '"range_max": 1}}')

header = ("time_s,id,position_step,speed_step_per_s,load_percent,voltage_v,temperature_c,"
          "current_ma,status,moving")
seed("telemetry_csv", "recording.csv", header + "\n0.000,1,2048,0,0.0,12.1,31,5,0,0\n"
     "0.020,1,2050,40,1.5,12.1,31,,32,1\n0.021,2,100,-40,-3.0,,,,0,0\n")
seed("telemetry_csv", "header-only.csv", header + "\n")

# The simulator state of fuzz_sim_state's bus: STS3215 ID 1, SCS009 ID 2, HLS ID 3.
def image(major, minor, servo_id):
    eeprom = bytearray(256)
    eeprom[3], eeprom[4], eeprom[5], eeprom[6] = major, minor, servo_id, 0
    return eeprom.hex()

seed("sim_state", "state.json", json.dumps(
    {"format": 1, "servos": [{"model": "STS3215", "eeprom": image(9, 3, 1)},
                             {"model": "SCS009/SCS0009", "eeprom": image(5, 4, 2)},
                             {"model": "HLSxx", "eeprom": image(10, 0, 3)}]}, indent=4))

# A shared bus: what a program and the servos exchange, as chunks (a length byte whose top bit
# says the program's side, then the bytes), and the recording the share writes of it.
def chunk(from_program, data):
    return bytes([(0x80 if from_program else 0) | len(data)]) + data

def packet(servo, code, params=b""):
    body = bytes([servo, len(params) + 2, code]) + params
    return b"\xff\xff" + body + bytes([~sum(body) & 0xFF])

# An STS3215's session as LeRobot starts one: the model, the feedback, a write, a SYNC READ.
identity = bytes([3, 10, 0, 9, 3, 1, 0, 0, 1, 0, 0, 0, 0, 0xFF, 0x0F, 0x46, 0x50, 0x28])
feetech_requests = [packet(1, 0x01), packet(1, 0x02, b"\x03\x02"), packet(1, 0x02, b"\x00\x13"),
                    packet(1, 0x02, b"\x38\x08"), packet(1, 0x03, b"\x37\x00"),
                    packet(1, 0x03, b"\x2a\x00\x08"), packet(0xFE, 0x82, b"\x38\x02\x01")]
feetech_answers = [packet(1, 0), packet(1, 0, b"\x09\x03"), packet(1, 0, identity[:19]),
                   packet(1, 0, b"\x00\x08\x00\x00\x00\x00\x78\x1e"), packet(1, 0), packet(1, 0x20),
                   packet(1, 0, b"\x00\x08")]
exchange = b""
for request, answer in zip(feetech_requests, feetech_answers):
    exchange += chunk(True, request) + chunk(False, answer)
seed("share_traffic", "spec-exchanges", exchange)
seed("share_traffic", "split-and-echoed",
     b"".join(chunk(True, r[:3]) + chunk(True, r[3:]) + chunk(False, r) + chunk(False, a)
              for r, a in zip(feetech_requests[:6], feetech_answers[:6])))

recording = ["# servobench share recording 1", "# port /dev/ttyACM0 at 1000000 baud, started "
             "2026-12-01T10:00:00Z"]
at = 0.0
for request, answer in zip(feetech_requests, feetech_answers):
    at += 0.0004
    recording.append("%.6f program %s" % (at, request.hex(" ").upper()))
    at += 0.0003
    recording.append("%.6f bus %s" % (at, answer.hex(" ").upper()))
recording.append("%.6f note alert eeprom-unlocked 1: EEPROM left unlocked" % (at + 5))
recording.append("%.6f own FF FF 01 04 02 38 02 BE" % (at + 5.1))
recording.append("%.6f own-answer FF FF 01 04 00 00 08 F2" % (at + 5.1003))
seed("share_recording", "spec-exchanges.log", "\n".join(recording) + "\n")
