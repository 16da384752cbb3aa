#!/usr/bin/env python3
"""An external rasterizer (SPEC.md §12, one-shot) that answers the first
ANSWERED requests at once with "unsupported", then sleeps for ten minutes on
every later one: a run to stop with a signal while a case is in flight.

    python3 reports_slow.py PIDS ANSWERED

Each process writes its pid into the folder PIDS (files `<pid>`); a process
that is about to sleep first writes `<pid>.sleeping`, so a test knows when
to send its signal. Standard library only.
"""

import json
import os
import sys
import time

pids, answered = sys.argv[1], int(sys.argv[2])
json.load(sys.stdin)
started = [n for n in os.listdir(pids) if n.isdigit()]
open(os.path.join(pids, str(os.getpid())), "w").close()
if len(started) >= answered:
    open(os.path.join(pids, "%d.sleeping" % os.getpid()), "w").close()
    time.sleep(600)
print(json.dumps({"unsupported": "reports_slow.py draws nothing"}), flush=True)
