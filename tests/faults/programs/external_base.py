"""What the faulty external rasterizers of tests/faults/external.rs share.

Each is a real program speaking SPEC.md §12 in either mode: it answers every
case with no fragments (the test cases cover no pixel centre, so that is a
pass), except the cases whose name starts with "bad", where it does its
fault. Before answering, it appends "pgid <its process group>" to the log
file named by its first argument, so that a test can look for any process
of the run's groups afterwards. Standard library only.
"""

import json
import os
import sys


def log(path, line):
    with open(path, "a") as f:
        f.write(line + "\n")


def empty(request):
    return json.dumps({"primitives": [{"fragments": []} for _ in request["primitives"]]})


def serve(fault):
    """Answers requests; `fault(request, log_path)` answers the bad ones
    (a string to print, or None to print nothing)."""
    log_path = sys.argv[1]
    log(log_path, "pgid %d" % os.getpgid(0))

    def answer(request):
        if request["case"].startswith("bad"):
            return fault(request, log_path)
        return empty(request)

    if "--persistent" in sys.argv:
        for text in sys.stdin:
            request = json.loads(text)
            if request.get("bye"):
                break
            out = answer(request)
            if out is not None:
                print(out, flush=True)
    else:
        out = answer(json.load(sys.stdin))
        if out is not None:
            print(out, flush=True)
