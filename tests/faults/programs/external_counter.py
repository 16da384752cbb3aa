#!/usr/bin/env python3
"""Logs, per case, how many file descriptors and threads its parent
(rastercheck) has at that moment: "count CASE FDS THREADS". On the bad cases
it first starts a grandchild that sleeps for ten minutes holding stdout and
stderr open (as external_forker.py does), then answers like the others: with
no fragments. See external_base.py."""

import os
import sys
import time

sys.path.insert(0, os.path.dirname(__file__))
import external_base

plain = external_base.empty


def counted(request):
    parent = os.getppid()
    fds = len(os.listdir("/proc/%d/fd" % parent))
    tasks = len(os.listdir("/proc/%d/task" % parent))
    external_base.log(sys.argv[1], "count %s %d %d" % (request["case"], fds, tasks))
    return plain(request)


def fork_then_answer(request, log_path):
    if os.fork() == 0:
        time.sleep(600)
        os._exit(0)
    return counted(request)


external_base.empty = counted
external_base.serve(fork_then_answer)
