#!/usr/bin/env python3
"""A rasterizer that supports nothing: it answers every request (SPEC §12,
one-shot mode) with `unsupported`. A run with only this candidate judges
nothing, and must say so (exit 3), never pass."""
import json
import sys

sys.stdin.read()
print(json.dumps({"unsupported": "this program draws nothing"}))
