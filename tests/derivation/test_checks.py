"""The checks must be able to fail: each is shown a wrong identity or inequality."""

import pytest
import sympy as sp

from derivation import checks
from derivation.domain import sample_point, seeded_rng
from derivation.symbols import R, delta, delta_1, f, g, k, label, theta

x = sp.Symbol("theta", real=True)


def test_exact_zero_recognises_trigonometric_identities():
    assert checks.exact_zero(sp.sin(x) ** 2 + sp.cos(x) ** 2 - 1)
    assert checks.exact_zero(sp.sin(x + theta) - sp.sin(x) * sp.cos(theta) - sp.cos(x) * sp.sin(theta))


def test_exact_zero_rejects_a_nonzero_expression():
    assert not checks.exact_zero(sp.sin(x) - x)
    assert not checks.exact_zero(sp.Matrix([0, R - k]))


def test_numeric_residual_sees_a_difference_far_below_double_precision():
    # 1e-20 relative is invisible to float64, plain to a 30-digit check.
    result = checks.numeric_residual(f * g, f * g * (1 + sp.Float("1e-20", 40)), "test")
    assert not checks.agrees(result)
    assert checks.agrees(checks.numeric_residual(f * g, g * f, "test"))


def test_a_constant_is_evaluated_once_and_said_so():
    """A referee: "30 digits at 5 points" for θ₁ = π/2 claimed five samples of what has no variable."""
    once = checks.numeric_residual(sp.pi / 2, sp.asin(1), "test")
    assert once.points == 1 and checks.agrees(once)
    assert not checks.agrees(checks.numeric_residual(sp.pi / 2, sp.Rational(157, 100), "test"))
    assert checks.numeric_residual(f * g, g * f, "test").points == checks.NUMERIC_POINTS
    root = label("a root, in a test of the checks", r"\theta_{\mathrm{test}}")  # a claim's label: no variable
    assert checks.numeric_residual(root - sp.pi / 2, root - sp.asin(1), "test").points == 1


def test_prove_sign_proves_under_hypothesis_9():
    # δ − fR < 0 is (9) itself.
    assert checks.prove_sign(delta - f * R, "<")
    # Without (9) it cannot be proved.
    assert not checks.prove_sign(delta - f * R, "<", hypothesis={})


def test_prove_sign_uses_the_vertices_of_bounded_atoms():
    expr = R * delta * sp.sin(theta) - f * R**2  # ≤ R(δ − fR) < 0
    assert checks.prove_sign(expr, "<", bounded={sp.sin(theta): (-1, 1)})
    # A sign that fails at a vertex is not proved.
    assert not checks.prove_sign(sp.sin(theta), "<", bounded={sp.sin(theta): (-1, 1)})


def test_prove_sign_refuses_a_strict_sign_of_what_can_be_zero():
    """A strict < or > of 0 is no proof (a mutation of is_negative into is_nonpositive passed every test)."""
    for relation in ("<", ">", "!="):
        assert not checks.prove_sign(sp.Integer(0), relation)
    assert checks.prove_sign(sp.Integer(0), "<=") and checks.prove_sign(sp.Integer(0), ">=")


def test_prove_sign_refuses_non_affine_dependence_on_a_bounded_atom():
    # sin² is not affine in sin: the vertex argument does not apply.
    assert not checks.prove_sign(sp.sin(theta) ** 2 - 2, "<", bounded={sp.sin(theta): (-1, 1)})


def test_dense_sign_finds_a_violation():
    assert not checks.dense_sign(sp.sin(theta), ">", "test")
    assert checks.dense_sign(sp.sin(theta) ** 2 - 2, "<", "test")


def test_numeric_residual_is_relative_for_small_quantities():
    # A quantity of size 1e-12 off by 1e-20 of itself: against an absolute floor of 1 this would pass.
    small = sp.Float("1e-12", 40) * f * g
    assert not checks.agrees(checks.numeric_residual(small, small * (1 + sp.Float("1e-20", 40)), "test"))
    # A stated scale: the same difference against a scale of 1e8 times the quantity is within tolerance.
    assert checks.agrees(checks.numeric_residual(small, small * (1 + sp.Float("1e-20", 40)), "test", scale=1e8 * small))


def test_bounded_intervals_are_checked_on_the_domain_and_sampling_takes_what_bounds_need():
    """`outside_bounds`: an interval narrower than its atom's range is found; the sampling of δ₁ alone needs δ,
    whose box needs f and R (the order was taken one level deep: "circular sampling bounds")."""
    from derivation import domain
    from derivation.symbols import delta_1

    assert domain._in_order({delta_1}, {}) == [R, f, delta, delta_1]
    assert checks.outside_bounds({delta_1: (0, delta), sp.sin(theta): (-1, 1)}, "test") is None
    assert checks.outside_bounds({delta_1: (0, delta / 2)}, "test") == delta_1
    assert checks.outside_bounds({sp.sin(theta): (-1, 1), delta_1: (0, delta), sp.cos(theta): (0, 1)}, "test") == sp.cos(theta)


def test_a_hypothesis_on_an_atom_is_checked_on_the_domain():
    """`unmet_hypothesis`: cos θ > 0 (n8.theta_increases) holds for θ acute, not over (0, π), and a claim whose
    domain the hypothesis does not fit raises instead of proving (a mutation audit: it said "proved")."""
    import dataclasses

    from derivation import n8_general

    c_theta = sp.Symbol("c_theta", positive=True)
    assert checks.unmet_hypothesis({sp.cos(theta): c_theta}, "test", {theta: (0, sp.pi / 2)}) is None
    assert checks.unmet_hypothesis({sp.cos(theta): c_theta}, "test", {theta: (0, sp.pi)}) == sp.cos(theta)
    assert checks.unmet_hypothesis(checks.HYPOTHESIS_9, "test") is None  # (9) itself is the sampling box's
    claim = next(c for c in n8_general.claims() if c.id == "n8.theta_increases")
    assert claim.check().status == "confirmed"
    wide = dataclasses.replace(claim, domain={theta: (0, sp.pi)})
    verdict = wide.check()
    assert verdict.status == "failed" and "leaves the sign the hypothesis gives it" in verdict.note, verdict


def test_a_rational_function_is_decided_by_its_numerator_without_the_simplifiers(monkeypatch):
    """A wrong J (a rational function) ran past 290 s in simplify before failing (a mutation audit): polynomial
    arithmetic decides it; the simplifiers serve only what is not a rational function."""
    monkeypatch.setattr(checks.sp, "simplify", lambda e: pytest.fail("simplify called on a rational function"))
    assert checks.exact_zero(f / (R + k) - f * R / (R**2 + k * R))
    assert not checks.exact_zero(f / (R + k) - f / (R + 2 * k))
    assert checks._rational_zero(sp.sin(theta) - sp.sin(theta)) is None  # not rational: for the simplifiers


def test_a_nan_is_the_worst_error_of_a_numeric_check():
    """max(worst, nan) keeps worst: a quadrature that came out NaN passed at its full digits (a mutation audit)."""
    import mpmath

    assert checks.worst_of(mpmath.mpf(0), mpmath.nan) == mpmath.inf and checks.worst_of(0.0, float("nan"), 1e-30) == mpmath.inf
    assert checks.worst_of(mpmath.mpf("1e-30"), mpmath.mpf("2e-30")) == mpmath.mpf("2e-30")


# A mutation audit of derivation/ and reduction/ (each test below fails on the mutant it names, passes here).


def test_a_sign_is_proved_only_if_it_holds_at_every_vertex():
    """M01: the proof looked at one vertex (the first, or the last) and passed.  This sign fails only at the vertex
    sin θ = −1, δ₁ = δ, a middle one."""
    e = (1 - sp.sin(theta)) * delta_1 / delta - 1
    assert not checks.prove_sign(e, "<", bounded={sp.sin(theta): (-1, 1), delta_1: (0, delta)})
    assert not checks.prove_sign(-sp.sin(theta), "<", bounded={sp.sin(theta): (-1, 1)})


def test_the_numeric_check_evaluates_every_point():
    """M02: checking one point of five passed.  f − f₀ vanishes at the first point only."""
    first = sample_point({f}, seeded_rng("probe"))[f]
    assert not checks.agrees(checks.numeric_residual(f, first, "probe"))


def test_the_points_cover_the_papers_box():
    """M03: the points narrowed to a corner of the box (δ ≤ 0.01 fR) passed every claim: 200 draws spread over
    0 < δ < fR."""
    rng = seeded_rng("coverage")
    ratios = [p[delta] / (p[f] * p[R]) for p in (sample_point({delta}, rng) for _ in range(200))]
    assert all(0 < q < 1 for q in ratios) and max(ratios) > 0.9 and min(ratios) < 0.1
