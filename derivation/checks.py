"""How a claim is checked: an exact symbolic test and a 30-digit numeric one.

Neither is enough alone: ``simplify`` failing to reach 0 proves nothing, and
a numeric agreement at a few points is not a proof.  So an identity counts
only when both agree; an inequality is proved under the paper's hypotheses
where the vertex argument below applies, and otherwise sampled densely and
marked as such.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass
from typing import Mapping

import mpmath
import numpy as np
import sympy as sp

from derivation import symbols as s
from derivation.domain import Bounds, sample_array, sample_point, seeded_rng

DIGITS = 30
NUMERIC_POINTS = 5
# Two 30-digit evaluations of one number agree to well under 1e-25 relative.
NUMERIC_TOLERANCE = sp.Float("1e-25")
DENSE_SAMPLES = 20000

# delta < f R (eq. (9)) as a substitution over positive symbols: a proof under
# positive symbols then is a proof under the paper's hypothesis.  (psi, a letter the appendix uses
# for nothing else: sigma is -ln V there.)
psi = sp.Symbol("psi", positive=True)
HYPOTHESIS_9 = {s.delta: s.f * s.R / (1 + psi)}


def _elements(expr) -> list[sp.Expr]:
    return list(expr) if isinstance(expr, sp.MatrixBase) else [sp.sympify(expr)]


def _rational_zero(e: sp.Expr) -> bool | None:
    """For a sum of rational terms: brought to one denominator with polynomial
    arithmetic (fast, sparse), is the numerator the zero polynomial?  None when
    ``e`` is no rational function of its symbols (a sine, a root): undecided."""
    gens = sorted(e.free_symbols, key=lambda x: x.name)
    if not gens or not e.is_rational_function(*gens):
        return None
    try:
        numerator, denominator = sp.Poly(0, *gens), sp.Poly(1, *gens)
        for term in sp.Add.make_args(sp.expand(e, deep=False, mul=False, multinomial=False)):
            n, d = (sp.Poly(part, *gens) for part in sp.fraction(sp.together(term)))
            numerator, denominator = numerator * d + n * denominator, denominator * d
    except sp.PolynomialError:
        return None
    return numerator.is_zero


def exact_zero(expr) -> bool:
    """True only when SymPy reduces every element of ``expr`` to exactly 0.  A rational function is decided by
    its numerator alone: a nonzero polynomial is no identity, and the simplifiers after it only took minutes to
    say so (a wrong J ran past 290 s: a mutation audit)."""
    simplifiers = (
        lambda e: e,
        lambda e: sp.cancel(sp.expand_trig(sp.expand(e))),
        sp.simplify,
        lambda e: sp.simplify(sp.expand_trig(e)),
    )

    def zero(e) -> bool:
        decided = _rational_zero(e)
        return decided if decided is not None else any(step(e) == 0 for step in simplifiers)

    return all(zero(e) for e in _elements(expr))


def _evaluate(expr: sp.Expr, point: Mapping[sp.Symbol, sp.Float]) -> mpmath.mpf:
    value = sp.sympify(expr).evalf(DIGITS, subs=dict(point))
    if not value.is_number or value.has(sp.zoo, sp.nan, sp.oo, -sp.oo):
        raise ValueError(f"{expr} does not evaluate to a finite number at {point}")
    if not value.is_real:
        # A printed form with a glyph in it can go complex (a log of a sign):
        # then it plainly differs from the derived real value.
        return mpmath.mpf(abs(complex(value)))
    return mpmath.mpf(value)


@dataclass(frozen=True)
class NumericResult:
    points: int
    digits: float  # decimal digits of agreement at the worst point (30 = all asked for)
    worst: mpmath.mpf  # largest relative residual


def worst_of(*errors):
    """The largest of a numeric check's errors, a NaN counted as infinite: ``max(worst, nan)`` keeps ``worst``,
    and a check whose quadrature came out NaN passed at its full digits (a mutation audit)."""
    return max(e if e == e else mpmath.inf for e in errors)


def numeric_residual(
    left,
    right,
    key: str,
    overrides: Mapping[sp.Symbol, Bounds] = {},
    points: int = NUMERIC_POINTS,
    scale: sp.Expr | None = None,
) -> NumericResult:
    """Size of ``left - right`` at seeded random points (one when there is no variable), at 30 digits, relative to
    ``scale`` (an expression, the size the claim states for its quantity) or, by default, to max(|left|, |right|)."""
    left_e, right_e = _elements(left), _elements(right)
    free = set().union(*(sp.sympify(e).free_symbols for e in left_e + right_e + ([scale] if scale is not None else [])))
    # A constant (θ₁ = π/2, J = 729/4: a label, named on both sides, against a value): one evaluation, not m.
    points = points if any(x.name not in s.LABEL_TEX for x in free) else 1
    rng = seeded_rng(key)
    worst = mpmath.mpf(0)
    with mpmath.workdps(DIGITS + 10):
        for _ in range(points):
            point = sample_point(free, rng, overrides)
            for a, b in zip(left_e, right_e):
                diff = _evaluate(a - b, point)
                if diff == 0:
                    continue
                size = abs(_evaluate(scale, point)) if scale is not None else max(abs(_evaluate(a, point)), abs(_evaluate(b, point)))
                worst = worst_of(worst, abs(diff) / size if size > 0 else mpmath.inf)
    digits = DIGITS if worst == 0 else float(min(DIGITS, -mpmath.log10(worst)))
    return NumericResult(points, digits, worst)


def numeric_sign(
    expr, relation: str, key: str, overrides: Mapping[sp.Symbol, Bounds] = {}, points: int = NUMERIC_POINTS
) -> bool:
    """``expr relation 0`` at seeded random points, at 30 digits."""
    free = set().union(*(e.free_symbols for e in _elements(expr)))
    rng = seeded_rng(key)
    with mpmath.workdps(DIGITS + 10):
        for _ in range(points):
            point = sample_point(free, rng, overrides)
            if not all(_holds(_evaluate(e, point), relation) for e in _elements(expr)):
                return False
    return True


def _holds(value, relation: str) -> bool:
    return {
        "<": value < 0,
        "<=": value <= 0,
        ">": value > 0,
        ">=": value >= 0,
        "!=": value != 0,
    }[relation]


def _sympy_sign_holds(expr: sp.Expr, relation: str) -> bool:
    prop = {"<": "is_negative", "<=": "is_nonpositive", ">": "is_positive", ">=": "is_nonnegative"}
    if relation == "!=":
        return bool(expr.is_positive) or bool(expr.is_negative)
    return bool(getattr(expr, prop[relation]))


def prove_sign(
    expr,
    relation: str,
    bounded: Mapping[sp.Expr, tuple[sp.Expr, sp.Expr]] = {},
    hypothesis: Mapping[sp.Symbol, sp.Expr] = HYPOTHESIS_9,
) -> bool:
    """Prove ``expr relation 0`` for every element, or return False.

    ``bounded`` lists atoms confined to an interval (sin(theta) in [-1, 1],
    delta_1 in [0, delta]).  Each element must be affine in every such atom,
    so its extremes over the box lie at the vertices; at each vertex the
    hypothesis is substituted (delta = f R / (1 + psi)) and SymPy's
    assumptions on positive symbols must decide the sign.  Treating sin and
    cos of one angle as independent only enlarges the box, so the proof stays
    sound.
    """
    dummies = {atom: sp.Dummy(f"b{i}") for i, atom in enumerate(bounded)}
    for element in _elements(expr):
        e = sp.sympify(element).subs(dummies)
        if any(sp.cancel(sp.diff(e, x, 2)) != 0 for x in dummies.values()):
            return False
        for vertex in itertools.product(*(bounded[a] for a in bounded)):
            at_vertex = e.subs({dummies[a]: val for a, val in zip(bounded, vertex)})
            at_vertex = sp.factor(sp.cancel(at_vertex.subs(hypothesis)))
            if not _sympy_sign_holds(at_vertex, relation):
                return False
    return True


def outside_bounds(
    bounded: Mapping[sp.Expr, tuple[sp.Expr, sp.Expr]], key: str, overrides: Mapping[sp.Symbol, Bounds] = {},
    samples: int = DENSE_SAMPLES,
) -> sp.Expr | None:
    """The first atom of ``bounded`` found outside its interval on a dense sample of the domain (None: none).
    `prove_sign` proves a sign over the intervals given: one narrower than the atom's range proves too little,
    and would still say "proved" (a mutation audit: sin θ in [−1, 0], δ₁ in [0, 0])."""
    if not bounded:
        return None
    exprs = [sp.sympify(e) for atom, interval in bounded.items() for e in (atom, *interval)]
    free = sorted(set().union(*(e.free_symbols for e in exprs)), key=lambda x: x.name)
    columns = sample_array(set(free), seeded_rng("bounds:" + key), samples, overrides)

    def values(e):
        return np.broadcast_to(sp.lambdify(free, e, "numpy")(*(columns[x] for x in free)), (samples,))

    for atom, (lo, hi) in bounded.items():
        v = values(atom)
        if not np.all((values(lo) <= v) & (v <= values(hi))):
            return atom
    return None


def unmet_hypothesis(
    hypothesis: Mapping[sp.Basic, sp.Expr], key: str, overrides: Mapping[sp.Symbol, Bounds] = {},
    samples: int = DENSE_SAMPLES,
) -> sp.Expr | None:
    """The first atom the hypothesis replaces by a signed symbol (cos θ by c_θ > 0) that leaves that sign
    on a dense sample of the domain (None: none).  Such a substitution is an assumption, and a proof under
    it proves nothing where the atom has the other sign (a mutation audit: θ in (0, π) with cos θ > 0)."""
    signs = {"positive": ">", "nonnegative": ">=", "negative": "<", "nonpositive": "<="}
    for atom, replacement in hypothesis.items():
        if isinstance(atom, sp.Symbol) or not isinstance(replacement, sp.Symbol):
            continue  # δ = fR/(1 + ψ) is (9) itself; the sampling boxes are (9)'s
        relation = next((rel for name, rel in signs.items() if getattr(replacement, f"is_{name}")), None)
        if relation is None:
            continue
        free = sorted(atom.free_symbols, key=lambda x: x.name)
        columns = sample_array(set(free), seeded_rng("hypothesis:" + key), samples, overrides)
        values = np.broadcast_to(sp.lambdify(free, atom, "numpy")(*(columns[x] for x in free)), (samples,))
        if not np.all(_holds(values, relation)):
            return atom
    return None


def dense_sign(
    expr, relation: str, key: str, overrides: Mapping[sp.Symbol, Bounds] = {}, samples: int = DENSE_SAMPLES
) -> bool:
    """``expr relation 0`` on a dense float sample of the domain (not a proof)."""
    elements = _elements(expr)
    free = sorted(set().union(*(e.free_symbols for e in elements)), key=lambda x: x.name)
    columns = sample_array(set(free), seeded_rng("dense:" + key), samples, overrides)
    for e in elements:
        values = np.broadcast_to(sp.lambdify(free, e, "numpy")(*(columns[x] for x in free)), (samples,))
        if not np.all(_holds(values, relation)):
            return False
    return True


def is_strictly_nonzero_somewhere(result: NumericResult) -> bool:
    """A numeric residual far above rounding: the two forms really differ."""
    return result.worst > NUMERIC_TOLERANCE * 10**10


def agrees(result: NumericResult) -> bool:
    return result.worst <= NUMERIC_TOLERANCE

