#!/usr/bin/env python3
"""Hangs on the bad cases: sleeps for ten minutes without answering. See
external_base.py."""

import os
import sys
import time

sys.path.insert(0, os.path.dirname(__file__))
import external_base


def hang(request, log_path):
    time.sleep(600)


external_base.serve(hang)
