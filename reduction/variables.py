"""The variables of n°9: x = fV, y = δΩ, θ = β − α, and the constants a, b, c.

Also the sampling box the reduction's claims are checked in: the paper's
ordering a > b > c > 0 (n°9), with the physical relation b² < ac that the
definitions imply (see `n9_reduced_system`).
"""

from __future__ import annotations

import sympy as sp

from derivation.claim import Claim
from derivation.symbols import t

a, b, c = sp.symbols("a b c", positive=True)
x, y = (sp.Function(n, positive=True)(t) for n in ("x", "y"))
x_0, y_0 = sp.symbols("x_0 y_0", positive=True)

# n°11: the new variable φ and the functions of it.
phi = sp.Symbol("varphi", real=True)
lam = sp.Symbol("lambda", real=True)
z = sp.Symbol("z", positive=True)

# n°10: the constants of the special case a = c.
h = sp.Symbol("h", positive=True)
A = sp.Symbol("A", real=True)
C = sp.Symbol("C", positive=True)

# Sampling box, as overrides for derivation.domain (by symbol).
DOMAIN = {
    sp.Symbol("b", positive=True): (0.5, 2),
    sp.Symbol("c", positive=True): (0, b),
    sp.Symbol("a", positive=True): (b, 5 * b),
    sp.Symbol("x", positive=True): (0.01, 10),
    sp.Symbol("y", positive=True): (0.01, 10),
    x_0: (0.01, 10),
    y_0: (0.01, 10),
    phi: (-3, 3),
    lam: (-3, 3),
    z: (0, 1),
    h: (1, 3),
    A: (-1, 1),
    C: (0.1, 10),
    sp.Symbol("s", real=True): (-1, 1),  # sin θ, where a claim is written in it
}


def claim(*args, domain=None, **kwargs) -> Claim:
    """A claim checked in the reduction's sampling box (plus any overrides)."""
    return Claim(*args, domain={**DOMAIN, **(domain or {})}, **kwargs)
