#!/usr/bin/env python3
"""The example rasterizer (examples/python_rasterizer.py) behind protocol v2
(SPEC.md §12.7), misbehaving on chosen cases, for tests/protocol.rs.

    protocol_v2.py LOG [--no-lines] [--v1] [FAULT=CASE ...]

It appends "case NAME" to LOG for every request it receives. Its hello
declares the example's capabilities (without lines under --no-lines); with
--v1 it says no hello and echoes no id. FAULT=CASE makes it misbehave on the
case named CASE:

- stray: two stray lines (text, and JSON with no id) before its answer;
- skip: never answers that case (the next one is answered as usual);
- late: answers it after PROTOCOL_LATE seconds (3 by default), so that the
  late answer comes while the next request is in flight;
- wrongid: answers it with another id;
- hang: stops answering anything from that case on (it sleeps);
- flood: 5000 stray lines before its answer.

With --bad-hello its hello declares a primitive kind that does not exist.

Standard library only.
"""

import importlib.util
import json
import os
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
EXAMPLE = os.path.join(HERE, "..", "..", "..", "examples", "python_rasterizer.py")
spec = importlib.util.spec_from_file_location("example", EXAMPLE)
example = importlib.util.module_from_spec(spec)
spec.loader.exec_module(example)


def main():
    log_path, args = sys.argv[1], sys.argv[2:]
    v2 = "--v1" not in args
    faults = dict(reversed(a.split("=", 1)) for a in args if "=" in a)
    if v2:
        hello = json.loads(json.dumps(example.HELLO))
        if "--no-lines" in args:
            hello["hello"]["capabilities"]["primitives"] = ["triangles", "polygons"]
        if "--bad-hello" in args:
            hello["hello"]["capabilities"]["primitives"] = ["triangles", "spheres"]
        print(json.dumps(hello), flush=True)
    for text in sys.stdin:
        request = json.loads(text)
        if request.get("bye"):
            break
        case = request["case"]
        with open(log_path, "a") as f:
            f.write("case %s\n" % case)
        response = example.rasterize(request)
        if v2:
            response["id"] = request.get("id")
        fault = faults.get(case)
        if fault == "stray":
            print("debug: drawing %s" % case, flush=True)
            print(json.dumps({"progress": 0.5}), flush=True)
        elif fault == "skip":
            continue
        elif fault == "late":
            time.sleep(float(os.environ.get("PROTOCOL_LATE", "3")))
        elif fault == "wrongid":
            response["id"] = "bogus"
        elif fault == "hang":
            time.sleep(600)
        elif fault == "flood":
            for i in range(5000):
                print("stray %d" % i)
            sys.stdout.flush()
        print(json.dumps(response), flush=True)


if __name__ == "__main__":
    main()
