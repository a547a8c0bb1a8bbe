#!/usr/bin/env python3
"""Writes datastrings.cpp: the texts of the shipped JSON tables and robot templates, marked for
lupdate so that they are translated with the program's own strings. Run it after changing a table
or template, then update the .ts files; tst_translations fails while one is missing."""
import glob
import json
import os
import shutil
import subprocess

HERE = os.path.dirname(os.path.abspath(__file__))
RESOURCES = os.path.dirname(HERE)


def table_strings():
    texts = []
    for path in sorted(glob.glob(os.path.join(RESOURCES, "feetech", "registers-*.json"))):
        with open(path, encoding="utf-8") as f:
            table = json.load(f)
        texts.append(("FeetechRegister", table["title"]))
        for register in table["registers"]:
            texts.append(("FeetechRegister", register["label"]))
            texts.append(("FeetechRegister", register.get("note", "")))
            texts.append(("FeetechRegister", register.get("unit", "")))
            for entry in register.get("choices", []) + register.get("bits", []):
                texts.append(("FeetechRegister", entry["label"]))
    return texts


def robot_strings():
    texts = []
    for path in sorted(glob.glob(os.path.join(RESOURCES, "robots", "*.json"))):
        with open(path, encoding="utf-8") as f:
            robot = json.load(f)
        texts.append(("RobotTemplate", robot["name"]))
        for joint in robot["joints"]:
            texts.append(("Joint", joint["name"]))
    return texts


def quoted(text):
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'


def main():
    seen = set()
    lines = [
        "// The texts of the shipped register tables and robot templates, for lupdate only (never",
        "// compiled). Written by datastrings.py: edit the JSON files, not this one.",
        "#include <QtGlobal>",
        "",
        "static const char *const dataStrings[] = {",
    ]
    for context, text in table_strings() + robot_strings():
        if not text or (context, text) in seen:
            continue
        seen.add((context, text))
        lines.append(f"    QT_TRANSLATE_NOOP({quoted(context)}, {quoted(text)}),")
    lines.append("};")
    path = os.path.join(HERE, "datastrings.cpp")
    with open(path, "w", encoding="utf-8") as f:
        f.write("\n".join(lines) + "\n")
    # Formatted as the rest of the sources (long texts wrapped), when clang-format is there.
    if shutil.which("clang-format"):
        subprocess.run(["clang-format", "-i", path], check=True)


if __name__ == "__main__":
    main()
