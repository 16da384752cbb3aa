#!/usr/bin/env python3
"""Answers the bad cases with {"exr": PATH}: an 8 MB EXR whose header says
32768×32768 (a valid scan-line header, uncompressed, channels coverage and
primitive; its offset table and pixels are cut short). Decoding it as the
header says would take 8 GiB. See external_base.py."""

import json
import os
import struct
import sys
import tempfile

sys.path.insert(0, os.path.dirname(__file__))
import external_base

SIDE = 32768


def attribute(name, kind, value):
    return name.encode() + b"\0" + kind.encode() + b"\0" + struct.pack("<i", len(value)) + value


def huge_exr(path):
    channels = b""
    for name in ["coverage", "primitive"]:
        # pixel type 2 (float), pLinear, reserved, x and y sampling 1
        channels += name.encode() + b"\0" + struct.pack("<iB3xii", 2, 0, 1, 1)
    channels += b"\0"
    window = struct.pack("<iiii", 0, 0, SIDE - 1, SIDE - 1)
    header = b"".join([
        struct.pack("<ii", 20000630, 2),
        attribute("channels", "chlist", channels),
        attribute("compression", "compression", b"\0"),
        attribute("dataWindow", "box2i", window),
        attribute("displayWindow", "box2i", window),
        attribute("lineOrder", "lineOrder", b"\0"),
        attribute("pixelAspectRatio", "float", struct.pack("<f", 1.0)),
        attribute("screenWindowCenter", "v2f", struct.pack("<ff", 0.0, 0.0)),
        attribute("screenWindowWidth", "float", struct.pack("<f", 1.0)),
        b"\0",
    ])
    with open(path, "wb") as f:
        f.write(header)
        line = SIDE * 4 * 2 + 8
        start = len(header) + 8 * SIDE
        f.write(b"".join(struct.pack("<Q", start + y * line) for y in range(SIDE)))
        f.truncate(8 * 1024 * 1024)


def answer(request, log_path):
    path = os.path.join(tempfile.mkdtemp(prefix="rastercheck-huge-"), "frame.exr")
    huge_exr(path)
    return json.dumps({"exr": path})


if __name__ == "__main__" and len(sys.argv) == 3 and sys.argv[1] == "--write":
    huge_exr(sys.argv[2])
else:
    external_base.serve(answer)
