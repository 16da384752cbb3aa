#!/usr/bin/env python3
"""Starts a grandchild on the bad cases, which logs "grandchild PID" and
sleeps for ten minutes holding stdout and stderr open. On "bad_hang" the
program itself then hangs (killed at the time limit); on any other bad case
it answers and exits, leaving the grandchild behind. See external_base.py."""

import os
import sys
import time

sys.path.insert(0, os.path.dirname(__file__))
import external_base


def fork(request, log_path):
    pid = os.fork()
    if pid == 0:
        external_base.log(log_path, "grandchild %d" % os.getpid())
        time.sleep(600)
        os._exit(0)
    if request["case"] == "bad_hang":
        time.sleep(600)
    return external_base.empty(request)


external_base.serve(fork)
