"""The two mpmath routes: their agreement is measured, and a wrong route would show."""

import mpmath
import pytest

from numerics import route_checks


def test_agreement_is_in_digits_relative_to_the_motion():
    with mpmath.workdps(40):
        _agreement_at_40_digits()


def _agreement_at_40_digits():
    a = {"t_slide_end": mpmath.mpf(1), "t_roll_end": mpmath.mpf(10), "t_pivot_end": None, "rest": (mpmath.mpf(3), mpmath.mpf(4)),
         "omega_end": (mpmath.mpf(1), mpmath.mpf(0))}
    b = dict(a, t_slide_end=mpmath.mpf(1) + mpmath.mpf("1e-20"), rest=(mpmath.mpf(3), mpmath.mpf(4) + mpmath.mpf("5e-25")))
    got = route_checks.agreement(a, b, 30)
    assert got["t_slide_end"] == 21.0  # 1e-20 over the 10 s the motion lasts
    assert got["rest"] == 25.0 and got["t_roll_end"] == 99.0


@pytest.mark.slow
def test_a_perturbed_route_is_caught(monkeypatch):
    """The Cartesian route with its rolling couple off by 1e-20 relative: the claim's digits drop below 25."""
    from numerics import cartesian_reference

    real = cartesian_reference.reference

    def off(scene, digits=30, **kw):
        motion = real(scene, digits=digits, **kw)
        if motion.rest is not None:
            motion.rest = tuple(x * (1 + mpmath.mpf("1e-20")) for x in motion.rest)
        return motion

    sample = route_checks.scenes()["hard: sample"]
    monkeypatch.setattr(cartesian_reference, "reference", off)
    monkeypatch.setattr(route_checks, "scenes", lambda: {"sample": sample})
    (check,) = route_checks.claims()
    verdict = check.check()
    assert verdict.status == "failed" and verdict.digits < 25


def test_agreement_compares_the_spin_at_the_end_of_sliding():
    with mpmath.workdps(40):
        a = {"t_slide_end": mpmath.mpf(1), "t_roll_end": mpmath.mpf(10), "t_pivot_end": None,
             "rest": (mpmath.mpf(3), mpmath.mpf(4)), "omega_end": (mpmath.mpf(1), mpmath.mpf(0))}
        b = dict(a, omega_end=(mpmath.mpf(1), mpmath.mpf("1e-12")))
        assert route_checks.agreement(a, b, 30)["omega_end"] == 12.0


def test_every_scene_is_compared(monkeypatch):
    """routes_agree takes the worst over all the scenes: the last one off at 10 digits shows (a mutation audit:
    comparing the first scene alone left the claim confirmed)."""
    from numerics import cartesian_reference, reference_motion

    one = {"t_slide_end": mpmath.mpf(1), "t_roll_end": mpmath.mpf(2), "t_pivot_end": None, "rest": (mpmath.mpf(3), mpmath.mpf(4)),
           "omega_end": None}
    monkeypatch.setattr(route_checks, "scenes", lambda: {"a": 0, "b": 1, "c": 2})
    monkeypatch.setattr(route_checks, "as_dict", lambda ref: ref)
    monkeypatch.setattr(reference_motion, "reference", lambda scene, digits, method: one)
    monkeypatch.setattr(cartesian_reference, "reference", lambda scene, digits: dict(one, rest=(3, 4 + 5e-10 * (scene == 2))))
    assert route_checks.routes_agree() == (10.0, 3)


def test_a_quantity_one_route_misses_is_a_disagreement():
    """An audit: a rest point against rolling for ever, or a missing Ω at the end of sliding, was skipped (the
    claim stayed confirmed with the Cartesian rolling returning nothing); a rest at the origin against one 1 mm
    away was skipped too (its size 0)."""
    with mpmath.workdps(40):
        a = {"t_slide_end": mpmath.mpf(1), "t_roll_end": mpmath.mpf(7), "t_pivot_end": mpmath.mpf(2),
             "rest": (mpmath.mpf(3), mpmath.mpf(4)), "omega_end": (mpmath.mpf(1), mpmath.mpf(0))}
        never = dict(a, t_roll_end=None, rest=None, omega_end=None, t_pivot_end=None)
        for got in (route_checks.agreement(a, never, 30), route_checks.agreement(never, a, 30)):
            assert got == {"t_slide_end": 99.0, "t_roll_end": 0.0, "t_pivot_end": 0.0, "rest": 0.0, "omega_end": 0.0}
        assert route_checks.agreement(never, never, 30) == {"t_slide_end": 99.0}  # neither has them: nothing to compare
        origin = dict(a, rest=(mpmath.mpf(0), mpmath.mpf(0)))
        assert route_checks.agreement(dict(a, rest=(mpmath.mpf("1e-3"), mpmath.mpf(0))), origin, 30)["rest"] == 0.0
        assert route_checks.agreement(origin, origin, 30)["rest"] == 99.0


def test_the_end_of_the_pivot_is_compared():
    with mpmath.workdps(40):
        a = {"t_slide_end": mpmath.mpf(1), "t_roll_end": mpmath.mpf(2), "t_pivot_end": mpmath.mpf(10),
             "rest": (mpmath.mpf(3), mpmath.mpf(4)), "omega_end": None}
        assert route_checks.agreement(dict(a, t_pivot_end=mpmath.mpf(10) + mpmath.mpf("1e-15")), a, 30)["t_pivot_end"] == 16.0


def test_the_cartesian_rolling_is_the_closed_form_not_the_references():
    """The Cartesian route's rolling and pivot are n°7's and eq. (5)'s closed forms, agreeing with the reference's
    integration; and a wrong rolling in the reference shows in the claim (an audit found the Cartesian route
    calling the reference's own `_roll`: a rolling 1% too long stayed confirmed at 33 digits)."""
    from numerics import cartesian_reference, reference_motion

    scene = route_checks.scenes()["hard: pivoting, r0 != 0"]
    with mpmath.workdps(40):
        P, tol = scene.params, mpmath.mpf(10) ** -32
        start = [mpmath.mpf(x) for x in ("0.1", "-0.2", "30", "-40")]
        out = reference_motion.ReferenceMotion(30, 0, None, None, None, None)
        t_end, rest = cartesian_reference.roll(P, start, mpmath.mpf(1))
        t_ref, rest_ref = reference_motion._roll(P, start, mpmath.mpf(1), tol, [], out, "taylor")
        assert abs(t_end - t_ref) < 1e-28 and max(abs(x - y) for x, y in zip(rest, rest_ref)) < 1e-28
        r0 = mpmath.mpf(-7)
        assert abs(cartesian_reference.pivot(P, r0) - reference_motion._pivot(P, r0, tol)) < 1e-28


def test_a_wrong_reference_rolling_is_caught(monkeypatch):
    from numerics import reference_motion

    real = reference_motion._roll

    def longer(*args, **kw):
        t, rest = real(*args, **kw)
        return (None, None) if t is None else (t * (1 + mpmath.mpf("1e-20")), rest)

    sample = route_checks.scenes()["hard: sample"]
    monkeypatch.setattr(reference_motion, "_roll", longer)
    monkeypatch.setattr(route_checks, "scenes", lambda: {"sample": sample})
    worst, n = route_checks.routes_agree()
    assert n == 1 and worst < 25


def test_routes_that_compare_nothing_show_no_agreement(monkeypatch):
    """An audit: with no quantity both routes have on any scene, the worst stayed ∞ and read as 40 digits."""
    from numerics import cartesian_reference, reference_motion

    none = {"t_slide_end": None, "t_roll_end": None, "t_pivot_end": None, "rest": None, "omega_end": None}
    monkeypatch.setattr(route_checks, "scenes", lambda: {"a": 0})
    monkeypatch.setattr(route_checks, "as_dict", lambda ref: ref)
    monkeypatch.setattr(reference_motion, "reference", lambda scene, digits, method: none)
    monkeypatch.setattr(cartesian_reference, "reference", lambda scene, digits: none)
    assert route_checks.routes_agree() == (0.0, 1)
