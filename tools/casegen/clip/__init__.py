"""The clip-space cases (cases/clip/), written by tools/gen_clip.py: the exact
model of SPEC.md section 16 (homogeneous.py), the case model and writer
(build.py), the cases (cases.py), evaluating and writing them
(generate.py), the separately written screen-space test and its worked
example (screen.py), the cross-checks (check.py), the wrong variants
that prove the pins can fail (mutants.py), and random cases for a
differential test of the reference (random_cases.py).
"""
