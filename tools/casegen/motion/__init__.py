"""The motion-blur cases (cases/motion/), written by tools/gen_motion_cases.py:
exact quadratic surds and polynomials in tau (quadratic.py), the two
per-instant predicates (predicates.py), moving primitives and their exact
time coverage (primitives.py), the sample method's instants (instants.py),
the case registry, bounds and evaluate() (evaluate.py), the cases
(cases.py), and the wrong variants that prove the checks can fail
(mutants.py). It shares no code with the antialiasing checker but the
sample patterns (casegen/samples.py).
"""
