"""Where the paper's symbols live: the sampling box for numeric checks.

The box is the paper's "cas réel du billard ordinaire" (n°5): positive
lengths, 0 < delta < fR (eq. (9)), a ball made of concentric homogeneous
layers (k below the hollow shell's sqrt(2/3) R).  A bound may depend on
symbols sampled before it (delta < f R), so bounds are SymPy expressions.

Every draw comes from a generator seeded by the claim id: a numeric check
gives the same digits on every machine and every run.
"""

from __future__ import annotations

import hashlib
import random
from typing import Mapping

import numpy as np
import sympy as sp

from derivation import symbols as s

Bounds = tuple[sp.Expr, sp.Expr]

# Bounds by symbol name, so that a snapshot symbol (V, Omega', ...) finds its box.
PHYSICAL: dict[str, Bounds] = {
    "R": (0.01, 0.1),
    "k": (0.3 * s.R, 0.8 * s.R),
    "m": (0.05, 1),
    "g": (1, 20),
    "f": (0.05, 0.6),
    "delta": (0, s.f * s.R),  # eq. (9)
    "delta_1": (0, s.delta),  # n°6: delta_1 <= delta
    "f_1": (0, s.f),  # n°7: f_1 <= f
    "epsilon": (0, 0.01),
    "V": (0.01, 10),
    "Omega": (0.01, 100),
    "V_0": (0.01, 10),
    "Omega_0": (0.01, 100),
    "r": (-100, 100),
    "r_0": (0.01, 100),
    "p": (-100, 100),
    "q": (-100, 100),
    "u": (-10, 10),
    "v": (-10, 10),
    "w": (-10, 10),
    "alpha": (-sp.pi, sp.pi),
    "beta": (-sp.pi, sp.pi),
    "alpha_0": (-sp.pi, sp.pi),
    "beta_0": (-sp.pi, sp.pi),
    "theta": (-sp.pi, sp.pi),
    "t": (0, 1),
    "xi": (-2, 2),
    "eta": (-2, 2),
    # Generic force and couple components, the normal reaction, sign(r).
    "X": (-10, 10),
    "Y": (-10, 10),
    "Z": (-10, 10),
    "L": (-10, 10),
    "M": (-10, 10),
    "N": (-10, 10),
    "n": (0.1, 10),
    "s_r": (-1, 1),
    "t_1": (0, 1),
    "2T": (0, 10),
    # OCR glyphs (symbols.ocr_*), in the box of the letter they stand for.
    "partial": (0, s.f * s.R),
    "hat_c": (0, s.f * s.R),
    "U": (0.01, 10),
    "rho": (-100, 100),
    "zeta": (-2, 2),
}
# A derivative (a name with accents) or a label ("[...]", see symbols.label)
# has no box of its own: any moderate value.
DERIVATIVE_BOUNDS: Bounds = (-10, 10)


def bounds_for(symbol: sp.Symbol, overrides: Mapping[sp.Symbol, Bounds]) -> Bounds:
    if symbol in overrides:
        return overrides[symbol]
    name = symbol.name
    if name in PHYSICAL:
        return PHYSICAL[name]
    if name.endswith("'") or name.startswith("["):
        return DERIVATIVE_BOUNDS
    raise KeyError(f"no sampling box for symbol {name!r}; give one in the claim's domain")


def seeded_rng(key: str) -> random.Random:
    return random.Random(int.from_bytes(hashlib.sha256(key.encode()).digest()[:8], "big"))


def _in_order(symbols: set[sp.Symbol], overrides: Mapping[sp.Symbol, Bounds]) -> list[sp.Symbol]:
    """The symbols and those their bounds need, each after what it depends on."""
    order: list[sp.Symbol] = []
    pending, todo = set(symbols), list(symbols)
    while todo:  # what their bounds need, and what those need (δ₁ needs δ, which needs f and R)
        for bound in bounds_for(todo.pop(), overrides):
            new = sp.sympify(bound).free_symbols - pending
            pending |= new
            todo += new
    while pending:
        ready = sorted(
            (x for x in pending if all(sp.sympify(b).free_symbols <= set(order) for b in bounds_for(x, overrides))),
            key=lambda x: x.name,
        )
        if not ready:
            raise ValueError(f"circular sampling bounds among {sorted(x.name for x in pending)}")
        order += ready
        pending -= set(ready)
    return order


def sample_point(
    symbols: set[sp.Symbol],
    rng: random.Random,
    overrides: Mapping[sp.Symbol, Bounds] = {},
    dps: int = 30,
) -> dict[sp.Symbol, sp.Float]:
    """One random point strictly inside every box, exact to ``dps`` + 10 digits."""
    point: dict[sp.Symbol, sp.Float] = {}
    for sym in _in_order(symbols, overrides):
        lo, hi = (sp.sympify(b).evalf(dps + 10, subs=point) for b in bounds_for(sym, overrides))
        # Stay clear of the ends: identities are checked at generic points.
        frac = rng.uniform(0.02, 0.98)
        point[sym] = sp.Float(lo + sp.Float(frac, dps + 10) * (hi - lo), dps + 10)
    return point


def sample_array(
    symbols: set[sp.Symbol],
    rng: random.Random,
    n: int,
    overrides: Mapping[sp.Symbol, Bounds] = {},
) -> dict[sp.Symbol, np.ndarray]:
    """``n`` random float64 points at once, for dense (non-proof) sign checks."""
    gen = np.random.default_rng(rng.getrandbits(64))
    columns: dict[sp.Symbol, np.ndarray] = {}
    for sym in _in_order(symbols, overrides):
        args = list(columns)
        lo, hi = (
            np.broadcast_to(sp.lambdify(args, sp.sympify(b), "numpy")(*columns.values()), (n,))
            for b in bounds_for(sym, overrides)
        )
        columns[sym] = lo + gen.uniform(0.001, 0.999, n) * (hi - lo)
    return columns
