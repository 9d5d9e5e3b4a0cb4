"""The Taylor integrator and its generated recurrences, on known solutions; the Taylor reference against GBS."""

import dataclasses

import mpmath
import pytest
import sympy as sp

from numerics import hard_cases, reference_motion, taylor

x, y, th, w = sp.symbols("x y theta omega", real=True)
STEPS = 2000  # ten times what any problem here takes: a broken recurrence fails instead of grinding


def test_generated_coefficients_are_the_taylor_series():
    # y' = e(x): y_k = e_{k−1}/k; every rule (sin, cos, exp, log, sqrt, rational and integer
    # powers, quotients, products) against mpmath's numerical Taylor expansion.
    exprs = [
        sp.sqrt(1 + x**2) * sp.log(2 + x) / (3 + x**2) + sp.exp(-x) * sp.cos(x),
        (1 + x) ** sp.Rational(-3, 2) + x**3 - sp.sin(x) ** 2 / (2 + sp.exp(x)),
        (2 + x) ** sp.Rational(1, 3) * sp.log(1 + x**2 + sp.exp(x)) + x**-2,
    ]
    for e in exprs:
        gen = taylor.generate([e], [y], indep=x)
        with mpmath.workdps(50):
            x0 = mpmath.mpf("0.3")
            coefs = gen.fn(x0, [mpmath.mpf(0)], (), 16)[0]
            expected = mpmath.taylor(sp.lambdify(x, e, "mpmath"), x0, 15)
            for k in range(16):
                assert abs(coefs[k + 1] * (k + 1) - expected[k]) < mpmath.mpf(10) ** -40 * (1 + abs(expected[k]))


def test_dot_is_fdot():
    with mpmath.workdps(60):
        a = [mpmath.mpf(k + 1) / 7 * mpmath.mpf(10) ** -k for k in range(40)]
        b = [mpmath.mpf(-1) ** k / (k + 3) for k in range(40)]
        assert taylor.dot(a, b) == mpmath.fdot(a, b)
        assert taylor.dot([], []) == 0


@pytest.mark.parametrize("digits", [15, 30, 50])
def test_exponential_to_the_asked_digits(digits):
    gen = taylor.generate([y], [y])
    (state,), stats = taylor.solve(gen, [], 0, [1], [mpmath.mpf(3)], digits, max_steps=STEPS)
    with mpmath.workdps(digits + 10):
        assert abs(state[0] - mpmath.e**3) / mpmath.e**3 < mpmath.mpf(10) ** (-digits)
    assert stats.steps >= 1


def test_oscillator_lands_on_every_requested_time():
    gen = taylor.generate([w, -th], [th, w])
    times = [mpmath.mpf(k) / 3 for k in range(1, 10)]
    states, _ = taylor.solve(gen, [], 0, [0, 1], times, 50, max_steps=STEPS)
    with mpmath.workdps(60):
        for t, (s, c) in zip(times, states):
            assert abs(s - mpmath.sin(t)) < mpmath.mpf(10) ** -50
            assert abs(c - mpmath.cos(t)) < mpmath.mpf(10) ** -50


def test_a_time_dependent_right_hand_side():
    gen = taylor.generate([sp.cos(x) * sp.exp(-x / 2)], [y], indep=x)
    (state,), _ = taylor.solve(gen, [], 0, [0], [mpmath.mpf(5)], 50, max_steps=STEPS)
    with mpmath.workdps(60):
        exact = mpmath.quad(lambda s: mpmath.cos(s) * mpmath.exp(-s / 2), [0, 5])
        assert abs(state[0] - exact) < mpmath.mpf(10) ** -50


def test_pendulum_half_period_as_an_event_and_its_energy():
    # θ'' = −g sin θ from rest at θ0: ω returns to zero at half the period 2K(sin²(θ0/2))/√g.
    g = sp.Symbol("g", positive=True)
    gen = taylor.generate([w, -g * sp.sin(th)], [th, w], [g])
    with mpmath.workdps(60):
        tol = mpmath.mpf(10) ** -52
        theta0, g_ = mpmath.mpf(2), mpmath.mpf("9.81")
        jet = gen.bind([g_])
        outcome = taylor.integrate(jet, 0, [theta0, 0], 10, tol, events=[lambda t, s: s[1]], max_steps=STEPS)
        assert outcome.event == 0
        half = 2 * mpmath.ellipk(mpmath.sin(theta0 / 2) ** 2) / mpmath.sqrt(g_)
        assert abs(outcome.t - half) < mpmath.mpf(10) ** -48
        assert abs(outcome.y[0] + theta0) < mpmath.mpf(10) ** -48
        energy = lambda s: s[1] ** 2 / 2 - g_ * mpmath.cos(s[0])  # noqa: E731
        end = taylor.integrate(jet, 0, [theta0, 0], 30, tol, max_steps=STEPS)
        assert abs(energy(end.y) - energy([theta0, 0])) < mpmath.mpf(10) ** -49


def test_kepler_orbit_returns_after_one_period():
    # r'' = −r/|r|³, eccentricity 0.6, semi-major axis 1: period 2π, energy −1/2, angular momentum √(1−e²).
    px, py, vx, vy = sp.symbols("px py vx vy", real=True)
    r3 = (px**2 + py**2) ** sp.Rational(3, 2)
    gen = taylor.generate([vx, vy, -px / r3, -py / r3], [px, py, vx, vy])
    with mpmath.workdps(60):
        e = mpmath.mpf("0.6")
        start = [1 - e, mpmath.mpf(0), mpmath.mpf(0), mpmath.sqrt((1 + e) / (1 - e))]
        out = taylor.integrate(gen.bind([]), 0, start, 2 * mpmath.pi, mpmath.mpf(10) ** -52, max_steps=STEPS)
        for a, b in zip(out.y, start):
            assert abs(a - b) < mpmath.mpf(10) ** -45
        px_, py_, vx_, vy_ = out.y
        assert abs((vx_**2 + vy_**2) / 2 - 1 / mpmath.sqrt(px_**2 + py_**2) + mpmath.mpf(1) / 2) < mpmath.mpf(10) ** -48
        assert abs(px_ * vy_ - py_ * vx_ - mpmath.sqrt(1 - e**2)) < mpmath.mpf(10) ** -48


def _gbs_reference(scene, digits):
    """The GBS reference's quantities, computed here by Gragg–Bulirsch–Stoer: the benchmark's cache was used, but an
    entry it lacks is computed by the default method, Taylor's, and the test compared Taylor with itself (a trust
    audit)."""
    ref = reference_motion.reference(dataclasses.replace(scene, times=()), digits=digits, method="gbs")
    end = ref.slide_end
    return ref.t_slide_end, list(ref.rest), [end.p, end.q]


@pytest.mark.slow  # the GBS integrator, ten to thirty times slower than Taylor's: about a minute for the five
@pytest.mark.parametrize("name", ["sample", "delta close to fR", "huge spin, small speed", "draw, little side spin", "straight draw"])
def test_taylor_reference_agrees_with_gbs(name, monkeypatch):
    monkeypatch.setattr(taylor, "MAX_STEPS", STEPS)
    scene = hard_cases.hard_cases()[name]
    ref = reference_motion.reference(scene, digits=30, method="taylor")
    t_end, rest, omega = _gbs_reference(scene, 30)
    with mpmath.workdps(50):
        # Vectors by their norm: a component that is zero in exact arithmetic is noise in both.
        digits = lambda a, b: -mpmath.log10(mpmath.norm([x - y for x, y in zip(a, b)]) / mpmath.norm(b))  # noqa: E731
        assert digits([ref.t_slide_end], [t_end]) >= 25
        assert digits(ref.rest, rest) >= 25
        assert digits((ref.slide_end.p, ref.slide_end.q), omega) >= 25


@pytest.mark.parametrize("name", ["sample", "straight draw", "delta close to fR"])
def test_cartesian_route_agrees_with_the_log_slip_route(name, monkeypatch):
    # Eqs. (4)–(6) in t with their own end of slide (cartesian_reference.tail) against the σ = −ln V route.
    from numerics import cartesian_reference

    monkeypatch.setattr(taylor, "MAX_STEPS", STEPS)
    scene = hard_cases.hard_cases()[name]
    c = cartesian_reference.reference(scene, digits=30)
    r = reference_motion.reference(scene, digits=30, method="taylor")
    with mpmath.workdps(40):
        digits = lambda a, b: -mpmath.log10(mpmath.norm([x - y for x, y in zip(a, b)]) / mpmath.norm(b))  # noqa: E731
        assert digits([c.t_slide_end], [r.t_slide_end]) >= 25
        assert digits(c.rest, r.rest) >= 25
        assert digits((c.slide_end["p"], c.slide_end["q"]), (r.slide_end.p, r.slide_end.q)) >= 25
        assert digits([c.t_roll_end], [r.t_roll_end]) >= 25


def test_cartesian_tail_is_second_order(monkeypatch):
    # Handing over at V₁ and at V₁/10 must change the slide's end by ~100× less than V₁ itself would.
    from numerics import cartesian_reference

    monkeypatch.setattr(taylor, "MAX_STEPS", STEPS)

    scene = hard_cases.hard_cases()["sample"]
    ends = [cartesian_reference.reference(scene, digits=30, end_fraction=f).t_slide_end for f in ("1e-6", "1e-7", "1e-8")]
    with mpmath.workdps(40):
        d1, d2 = abs(ends[0] - ends[2]), abs(ends[1] - ends[2])
        assert d1 < mpmath.mpf("1e-11") and d2 < d1 / 50


def test_the_timing_of_the_methods_times_both_integrators(monkeypatch):
    """`python -m numerics.taylor_timing methods` compares GBS with Taylor: once the reference's default became
    Taylor, its "gbs_s" column timed Taylor twice and its agreement compared Taylor with itself (an audit)."""
    from numerics import reference_motion, taylor_timing

    asked = []
    true_reference = reference_motion.reference

    def recorded(scene, digits=30, times=(), method="taylor"):
        asked.append(method)
        return true_reference(scene, digits=digits, times=times, method="taylor")

    monkeypatch.setattr(reference_motion, "reference", recorded)
    rows = list(taylor_timing.methods([15], names=("centre hit",)))
    assert asked == ["gbs", "taylor"] and rows[0]["case"] == "centre hit"
