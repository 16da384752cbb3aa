"""The bundled triangle cases (cases/triangles/ and cases/readme.json), written
by tools/gen_cases.py: the cases (cases.py), the format-documenting readme
(readme.py) and the independent exact checker behind `--check` (check.py).
"""
