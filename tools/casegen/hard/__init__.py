"""The catalogue of hard cases (cases/hard/), written by
tools/gen_hard_cases.py: the case model (build.py), the triangle and line
cases (cases.py) with their independent exact checker (check.py), and the
polygon and antialiasing cases (aa_cases.py), evaluated by the antialiasing
checker with their own claims asserted.
"""
