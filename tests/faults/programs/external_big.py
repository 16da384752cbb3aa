#!/usr/bin/env python3
"""A persistent program with big, right answers, for tests/faults/bounded.rs
(issue 36: answers and requests in bounded memory).

    external_big.py full     protocol v1 (no hello): every case is answered
                             with primitive 0 covering every pixel, as
                             fragments [x, y]
    external_big.py motion   protocol v2, declaring motion: every case is
                             answered with primitive 0 covering no pixel at
                             any instant (an empty time coverage list)

The cases it is given are drawn so that these answers are right (one
triangle over the whole canvas; one moving sliver that covers no pixel
centre at any instant). Its own memory stays
small: a request is read in chunks and only its head is looked at (its
id, its canvas), and an answer is written a row at a time, so the peak RSS
a test measures is rastercheck's. Standard library only.
"""

import re
import sys

CHUNK = 1 << 20


def requests():
    """Yields the first megabyte of each request line, reading the rest
    without keeping it."""
    stdin = sys.stdin.buffer
    while True:
        head = stdin.readline(CHUNK)
        if not head:
            return
        line_done = head.endswith(b"\n")
        while not line_done:
            more = stdin.readline(CHUNK)
            if not more:
                return
            line_done = more.endswith(b"\n")
        yield head.decode("utf-8", "replace")


def main():
    motion = sys.argv[1:] == ["motion"]
    out = sys.stdout
    if motion:
        out.write('{"hello": {"protocol": 2, "name": "big", "version": "1", '
                  '"capabilities": {"primitives": ["triangles"], "motion": true}}}\n')
        out.flush()
    for head in requests():
        if '"bye"' in head[:20]:
            return
        width = int(re.search(r'"width":(\d+)', head).group(1))
        height = int(re.search(r'"height":(\d+)', head).group(1))
        if motion:
            rid = re.search(r'"id":("(?:[^"\\]|\\.)*")', head).group(1)
            out.write('{"id":%s,"primitives":[{"time":[]}]}\n' % rid)
            out.flush()
            continue
        out.write('{"primitives":[{"fragments":[')
        item = "[%d,%d]"
        for y in range(height):
            row = ",".join(item % (x, y) for x in range(width))
            out.write(row if y == 0 else "," + row)
        out.write("]}]}\n")
        out.flush()


if __name__ == "__main__":
    main()
