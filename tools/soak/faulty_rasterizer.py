#!/usr/bin/env python3
"""A persistent external rasterizer that fails on purpose, for tools/soak.py.

It speaks SPEC.md §12.4 (JSON Lines) and really draws: every answer comes
from examples/python_rasterizer.py's `rasterize`. On about 3 % of the cases,
chosen from a hash of the case's name (so a run without faults can be
compared with one with them, case by case), it misbehaves instead:

- crash (1 %): writes half a response line, then exits with status 3;
- hang (1 %): never answers (sleeps until it is killed);
- garbage (1 %): answers a line that is not JSON, or (every other such
  case) a JSON response that breaks §12.2.

With --clean it never misbehaves: the same program, for the clean run.
With --log PATH it appends "pgid N" (its process group) to PATH when it
starts, then each request's case name as it reads it: how tools/soak.py
follows a run's progress and finds every process group it must see gone.

    python3 tools/soak/faulty_rasterizer.py [--clean] [--log PATH]

Standard library only.
"""

import hashlib
import json
import os
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "examples"))
import python_rasterizer  # noqa: E402

FAULTS = ("crash", "hang", "garbage")


def fault_of(name):
    """The fault a case gets ("crash", "hang", "garbage") or None, from its name."""
    h = int.from_bytes(hashlib.sha256(name.encode()).digest()[:8], "big")
    return {0: "crash", 1: "hang", 2: "garbage"}.get(h % 100)


def garbage(request):
    h = int.from_bytes(hashlib.sha256(request["case"].encode()).digest()[8:16], "big")
    if h % 2 == 0:
        return "this is not JSON {"
    # One primitive too many: well-formed JSON, a broken response.
    extra = len(request["primitives"]) + 1
    return json.dumps({"primitives": [{"fragments": []}] * extra})


def main():
    args = sys.argv[1:]
    clean = "--clean" in args
    log = open(args[args.index("--log") + 1], "a", buffering=1) if "--log" in args else None
    if log:
        log.write("pgid %d\n" % os.getpgid(0))
    out = sys.stdout
    for text in sys.stdin:
        request = json.loads(text)
        if request.get("bye"):
            break
        if log:
            log.write(request["case"] + "\n")
        fault = None if clean else fault_of(request["case"])
        if fault == "crash":
            out.write('{"primitives": [{"fragm')
            out.flush()
            os._exit(3)
        elif fault == "hang":
            while True:
                time.sleep(3600)
        elif fault == "garbage":
            out.write(garbage(request) + "\n")
        else:
            out.write(json.dumps(python_rasterizer.rasterize(request)) + "\n")
        out.flush()


if __name__ == "__main__":
    main()
