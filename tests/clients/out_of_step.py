#!/usr/bin/env python3
"""The example rasterizer (examples/python_rasterizer.py) in persistent mode,
falling out of step with rastercheck in the ways of issue 36, for
tests/faults/persistent.rs.

    out_of_step.py [--v2] [--exit-after-answer] [--idle-flood BYTES]
                   [--busy-gap MS] [KIND=CASE ...]

Version 1 (no hello, no ids) unless --v2 (the example's hello, ids echoed).

- KIND=CASE writes one extra line before its answer to the case named CASE:
  `unsupported` a valid {"unsupported": ...} answer, `object` a JSON object
  that is no answer ({"progress": 0.5}). Under version 1 nothing tells the
  extra line from an answer: a rastercheck that takes it for one stays an
  answer behind for the rest of the run.
- --busy-gap MS: between the extra line and the answer, computes for MS
  milliseconds (never sleeping), as a program slow to encode its answer
  would: for a while only the extra line is there to read.
- --exit-after-answer: exits after every answer (the next request finds a
  process that is gone).
- --idle-flood BYTES: after every answer, writes BYTES more to stdout, in
  lines of 1 KiB, while no request is in flight (stops when stdout closes).

Standard library only.
"""

import importlib.util
import json
import os
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
EXAMPLE = os.path.join(HERE, "..", "..", "examples", "python_rasterizer.py")
spec = importlib.util.spec_from_file_location("example", EXAMPLE)
example = importlib.util.module_from_spec(spec)
spec.loader.exec_module(example)

EXTRA = {
    "unsupported": {"unsupported": "not drawn here"},
    "object": {"progress": 0.5},
}


def main():
    args = sys.argv[1:]
    v2 = "--v2" in args
    exit_after = "--exit-after-answer" in args
    flood = 0
    if "--idle-flood" in args:
        flood = int(args[args.index("--idle-flood") + 1])
    gap = 0.0
    if "--busy-gap" in args:
        gap = float(args[args.index("--busy-gap") + 1]) / 1000.0
    extra = dict(reversed(a.split("=", 1)) for a in args if "=" in a)
    if v2:
        print(json.dumps(example.HELLO), flush=True)
    for text in sys.stdin:
        request = json.loads(text)
        if request.get("bye"):
            break
        response = example.rasterize(request)
        if v2:
            response["id"] = request.get("id")
        kind = extra.get(request["case"])
        if kind is not None:
            print(json.dumps(EXTRA[kind]), flush=True)
            end = time.perf_counter() + gap
            while time.perf_counter() < end:
                pass
        print(json.dumps(response), flush=True)
        if exit_after:
            return
        if flood:
            line = b"x" * 1023 + b"\n"
            block = line * 1024
            written = 0
            try:
                while written < flood:
                    sys.stdout.buffer.write(block)
                    written += len(block)
                sys.stdout.buffer.flush()
            except BrokenPipeError:
                return


if __name__ == "__main__":
    main()
