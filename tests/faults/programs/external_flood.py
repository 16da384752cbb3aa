#!/usr/bin/env python3
"""Floods stdout on the bad cases: an endless response that never ends
(until rastercheck stops reading and kills it). See external_base.py."""

import sys

sys.path.insert(0, __import__("os").path.dirname(__file__))
import external_base


def flood(request, log_path):
    chunk = b'{"primitives": [' + b" " * (1 << 20)
    out = sys.stdout.buffer
    out.write(chunk)
    try:
        while True:
            out.write(b" " * (1 << 20))
    except BrokenPipeError:
        sys.exit(1)


external_base.serve(flood)
