#!/usr/bin/env python3
"""A rasterizer that is not deterministic, for tests/repeat.rs: area8.py's
exact point sampling (protocol v2, SPEC.md §12), except that the second
time it is asked for a scene it leaves out the first fragment of the first
primitive that has one. Under `run --repeat N` its second repetition of
every case it draws differs from the first: FLAKY.

It counts the requests for each scene (canvas, rules and primitives) in
files under the folder `--state DIR` names, so the count survives however
many processes the run starts.

Flags:
  --state DIR   where the counts are kept (required)
  --steady      never leave a fragment out (deterministic: never FLAKY)
"""

import hashlib
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import area8  # noqa: E402  (beside this file)

ARGS = sys.argv[1:]
STATE = ARGS[ARGS.index("--state") + 1]
STEADY = "--steady" in ARGS


def times_asked(req):
    """How many times this scene has been asked for, this time included."""
    scene = {k: req.get(k) for k in ("canvas", "rules", "primitives")}
    key = hashlib.sha256(json.dumps(scene, sort_keys=True).encode()).hexdigest()
    path = os.path.join(STATE, key)
    n = int(open(path).read()) + 1 if os.path.exists(path) else 1
    with open(path, "w") as f:
        f.write(str(n))
    return n


def answer(req):
    reply = area8.answer(req)
    if STEADY or times_asked(req) != 2:
        return reply
    for prim in reply.get("primitives", []):
        if prim.get("fragments"):
            prim["fragments"] = prim["fragments"][1:]
            break
    return reply


def main():
    caps = {"primitives": ["triangles"], "fill_rules": ["top-left"], "coverage_only": True}
    hello = {"protocol": 2, "name": "flaky", "version": "1", "capabilities": caps}
    area8.serve(hello, answer)


if __name__ == "__main__":
    main()
