"""e^x in straight-line arithmetic, so that a loop over lanes computes it in vector instructions.

The slide's right-hand sides need V = e^−σ at every stage (`engine.rates_in_sigma`);
the C library's exp is a call, which a loop over lanes (`numerics.lanes`) makes
one lane at a time — a third of a lane's step.  This is fdlibm's method
(Sun's e_exp.c, as in most C libraries): x = k ln 2 + r with |r| ≤ ln 2 / 2,
e^r from a rational form of degree 5 in r², then the product with 2^k in two
factors so that subnormal results are rounded once.  Each factor is built
from its exponent's bits, k held in a float throughout: a conversion from
float64 to an integer has no vector instruction before AVX-512, and a loop
that needs one stays scalar (AMD EPYC, AVX2: a batch took 2.1× as long with
k an integer and 2^k read from a table).  Within an ulp of e^x (tested
against mpmath), and the same bits in the single-scene loop and in the lanes
(both call it).
"""

import math
import struct

LN2_HI = 6.93147180369123816490e-01  # ln 2 to 32 bits: k·LN2_HI is exact for |k| < 2^21
LN2_LO = 1.90821492927058770002e-10  # ln 2 − LN2_HI
INV_LN2 = 1.44269504088896338700e+00
P1, P2, P3, P4, P5 = (1.66666666666666019037e-01, -2.77777777770155933842e-03, 6.61375632143793436117e-05,
                      -1.65339022054652515390e-06, 4.13813679705723846039e-08)  # fdlibm's
LOWEST, HIGHEST = -746.0, 710.0  # beyond these, e^x is 0 or ∞ in float64: clamping x changes nothing
EXPONENT_BIAS = 1023.0
# 2^52 + m for an integer 0 ≤ m < 2^52 is a float whose bits are MAGIC_BITS + m: an integral float read as an
# integer without a conversion instruction (AVX2 has none from float64 to int64: the loop stays scalar).
MAGIC = 2.0**52
MAGIC_BITS = 0x4330000000000000
# x + SHIFTER − SHIFTER is x rounded to the nearest integer (|x| < 2^51), still a float: math.floor gives an int,
# a conversion again.
SHIFTER = 1.5 * 2.0**52


def float_bits(x):
    """The bits of the float x as an int64 (compiled: a reinterpretation, no instruction; `compiled`)."""
    return struct.unpack("<q", struct.pack("<d", x))[0]


def bits_float(n):
    """The float whose bits are the int64 n (compiled: a reinterpretation; `compiled`)."""
    return struct.unpack("<d", struct.pack("<q", n))[0]


def two_to(j):
    """2^j for an integral float j, −1022 ≤ j ≤ 1023: its exponent field j + 1023, shifted into place."""
    return bits_float((float_bits(j + (EXPONENT_BIAS + MAGIC)) - MAGIC_BITS) << 52)


def exp(x):
    """e^x for a float x (NaN gives NaN, ±∞ gives ∞ and 0), within an ulp."""
    c = min(max(x, LOWEST), HIGHEST) if x == x else 0.0  # a NaN answered at the end, as a select
    k = (c * INV_LN2 + SHIFTER) - SHIFTER
    hi = c - k * LN2_HI
    lo = k * LN2_LO
    r = hi - lo
    t = r * r
    q = r - t * (P1 + t * (P2 + t * (P3 + t * (P4 + t * P5))))
    y = 1.0 - ((lo - (r * q) / (2.0 - q)) - hi)
    half = (0.5 * k + SHIFTER) - SHIFTER  # 2^k in two normal factors: |half|, |k − half| ≤ 538
    return (y * two_to(half)) * two_to(k - half) if x == x else x
