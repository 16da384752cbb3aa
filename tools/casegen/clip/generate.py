"""Evaluating and writing the clip-space cases: every case's frame under the
model, its checks, and the text of every file the generator owns
(cases/clip/*.json and cases/triangles/spec_provoking_last.json).
"""

import filecmp
import os
import tempfile

from casegen import ROOT
from casegen.clip import cases  # noqa: F401 (registers the cases)
from casegen.clip import screen
from casegen.clip.build import CASES, model_scene, render
from casegen.clip.homogeneous import rasterize

CLIP_DIR = os.path.join("cases", "clip")


def evaluate():
    """{name: frame} and {name: samples_covered} of every case; asserts each
    case's checks, and no overdraw in a watertight one."""
    names = [c["name"] for c in CASES]
    assert len(names) == len(set(names)), "duplicate case names"
    frames = {c["name"]: rasterize(model_scene(c)) for c in CASES}
    counts = {name: len(f) for name, f in frames.items()}
    for c in CASES:
        frame = frames[c["name"]]
        for i, check in enumerate(c["checks"]):
            assert check(frame, counts), "check %d of %s fails" % (i, c["name"])
        if c["watertight"]:
            assert all(cell[0] == 1 for cell in frame.values()), "overdraw in " + c["name"]
    return frames, counts


def files(counts):
    """{path below the repository root: text} of every file written."""
    out = {}
    for c in CASES:
        n = counts[c["name"]]
        expect = {}
        if c["watertight"]:
            expect["watertight"] = True
        expect["samples_covered"] = n
        description = c["description"].format(N=n, **counts)
        out[os.path.join(CLIP_DIR, c["name"] + ".json")] = render(c, expect, description)
    path, text = screen.provoking_last_case()
    out[path] = text
    return out


def write(out, root=ROOT):
    """Writes the files below root; clears stale *.json files of cases/clip."""
    clip_dir = os.path.join(root, CLIP_DIR)
    os.makedirs(clip_dir, exist_ok=True)
    for f in os.listdir(clip_dir):
        if f.endswith(".json"):
            os.remove(os.path.join(clip_dir, f))
    for path, text in out.items():
        full = os.path.join(root, path)
        os.makedirs(os.path.dirname(full), exist_ok=True)
        with open(full, "w") as f:
            f.write(text)


def stale_against(out, root=ROOT):
    """Regenerates into a temporary folder and compares it with root: the
    files that differ, are missing, or are *.json files of cases/clip the
    generator does not write."""
    bad = []
    with tempfile.TemporaryDirectory() as tmp:
        write(out, tmp)
        for path in sorted(out):
            full = os.path.join(root, path)
            if not os.path.exists(full):
                bad.append(path + " (missing)")
            elif not filecmp.cmp(os.path.join(tmp, path), full, shallow=False):
                bad.append(path + " (differs)")
    clip_dir = os.path.join(root, CLIP_DIR)
    if os.path.isdir(clip_dir):
        for f in sorted(os.listdir(clip_dir)):
            if f.endswith(".json") and os.path.join(CLIP_DIR, f) not in out:
                bad.append(os.path.join(CLIP_DIR, f) + " (not generated)")
    return bad
