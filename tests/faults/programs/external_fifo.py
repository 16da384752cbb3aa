#!/usr/bin/env python3
"""Answers the bad cases with {"exr": PATH} where PATH is a FIFO that no
one ever writes: opening it for reading would block forever. See
external_base.py."""

import json
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(__file__))
import external_base


def fifo(request, log_path):
    path = os.path.join(tempfile.mkdtemp(prefix="rastercheck-fifo-"), "frame.exr")
    os.mkfifo(path)
    return json.dumps({"exr": path})


external_base.serve(fifo)
