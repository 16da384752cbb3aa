"""The antialiasing and polygon cases (cases/antialias/, cases/polygons/),
written by tools/gen_aa_cases.py: the checker's primitives (primitives.py),
its exact coverage and areas (check.py), the bounds and the evaluation of a
case (evaluate.py), and the cases (cases.py). The hard cases' polygons and
antialiased cases are evaluated by the same checker.
"""
