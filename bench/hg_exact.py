#!/usr/bin/env python3
"""hg_exact.py - the double HG samples of mist_ddcheck checked exactly.

HG's inverse CDF is a rational function of g and xi,
    u = (1 + g^2 - ((1 - g^2) / (1 - g + 2 g xi))^2) / (2 g)   (u = 2 xi - 1 at g = 0),
so each sample can be compared with the exact root rounded to double (Python's
Fraction, and float() of a Fraction rounds correctly).  Reads the lines
"S g xi u" (hex floats) that MIST_DDCHECK_DUMP=1 ./build/mist_ddcheck prints:

    MIST_DDCHECK_DUMP=1 ./build/mist_ddcheck | python3 bench/hg_exact.py

and prints how many samples are not the exact root correctly rounded, and how
many of those lie within 1e-30 of a midpoint between two doubles (where a
float128 reference cannot decide).  Standard library only."""
import math
import sys
from fractions import Fraction as F

n = bad = bad_tie = ties = 0
tiny = F(1, 10**30)
for line in sys.stdin:
    if not line.startswith("S "):
        continue
    _, g, xi, u = line.split()
    g, xi, u = F(float.fromhex(g)), F(float.fromhex(xi)), float.fromhex(u)
    if g == 0:
        exact = 2 * xi - 1
    elif abs(g) == 1:
        exact = g
    else:
        t = (1 - g * g) / (1 - g + 2 * g * xi)
        exact = (1 + g * g - t * t) / (2 * g)
    r = float(exact)
    nb = math.nextafter(r, 2.0 if exact > F(r) else -2.0)
    tie = abs(exact - (F(r) + F(nb)) / 2) < tiny
    n += 1
    ties += tie
    if r != u:
        bad += 1
        bad_tie += tie
print(f"{n} HG samples: {bad} not the exact root correctly rounded, {bad_tie} of them "
      f"within 1e-30 of a midpoint ({ties} roots are)")
