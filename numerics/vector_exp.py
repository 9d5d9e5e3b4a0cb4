"""e^x in straight-line arithmetic, so that a loop over lanes computes it in vector instructions.

The slide's right-hand sides need V = e^−σ at every stage (`engine.rates_in_sigma`);
the C library's exp is a call, which a loop over lanes (`numerics.lanes`) makes
one lane at a time — a third of a lane's step.  This is fdlibm's method
(Sun's e_exp.c, as in most C libraries): x = k ln 2 + r with |r| ≤ ln 2 / 2,
e^r from a rational form of degree 5 in r², then the product with 2^k, read
from a table in two factors so that subnormal results are rounded once.
Within an ulp of e^x (tested against mpmath), and the same bits in the
single-scene loop and in the lanes (both call it).
"""

import math

import numpy as np

LN2_HI = 6.93147180369123816490e-01  # ln 2 to 32 bits: k·LN2_HI is exact for |k| < 2^21
LN2_LO = 1.90821492927058770002e-10  # ln 2 − LN2_HI
INV_LN2 = 1.44269504088896338700e+00
P1, P2, P3, P4, P5 = (1.66666666666666019037e-01, -2.77777777770155933842e-03, 6.61375632143793436117e-05,
                      -1.65339022054652515390e-06, 4.13813679705723846039e-08)  # fdlibm's
LOWEST, HIGHEST = -746.0, 710.0  # beyond these, e^x is 0 or ∞ in float64: clamping x changes nothing
TWO_POWER = 2.0 ** np.arange(-540, 541)  # 2^j for j = −540 … 540: 2^k = 2^(k//2) · 2^(k − k//2), |k| ≤ 1077
OFFSET = 540


def exp(x):
    """e^x for a float x (NaN gives NaN, ±∞ gives ∞ and 0), within an ulp."""
    c = min(max(x, LOWEST), HIGHEST) if x == x else 0.0  # a NaN answered at the end, as a select
    k = math.floor(c * INV_LN2 + 0.5)
    hi = c - k * LN2_HI
    lo = k * LN2_LO
    r = hi - lo
    t = r * r
    q = r - t * (P1 + t * (P2 + t * (P3 + t * (P4 + t * P5))))
    y = 1.0 - ((lo - (r * q) / (2.0 - q)) - hi)
    half = math.floor(0.5 * k)
    # float(): interpreted, a Python float overflows to ∞ quietly where a NumPy scalar warns
    return (y * float(TWO_POWER[int(half) + OFFSET])) * float(TWO_POWER[int(k - half) + OFFSET]) if x == x else x
