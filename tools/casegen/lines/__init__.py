"""The bundled line cases (cases/lines/), written by tools/gen_line_cases.py:
the line model and writer (build.py), the cases of the midpoint, rectangle and
parallelogram rules (cases.py) and of diamond-exit (diamond.py), the
independent exact checker (check.py) and the comparison with rastercheck's
own reference (compare.py).
"""
