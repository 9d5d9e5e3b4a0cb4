"""The two mpmath routes: their agreement is measured, and a wrong route would show."""

import mpmath
import pytest

from numerics import route_checks


def test_agreement_is_in_digits_relative_to_the_motion():
    with mpmath.workdps(40):
        _agreement_at_40_digits()


def _agreement_at_40_digits():
    a = {"t_slide_end": mpmath.mpf(1), "t_roll_end": mpmath.mpf(10), "rest": (mpmath.mpf(3), mpmath.mpf(4)),
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
        a = {"t_slide_end": mpmath.mpf(1), "t_roll_end": mpmath.mpf(10), "rest": (mpmath.mpf(3), mpmath.mpf(4)),
             "omega_end": (mpmath.mpf(1), mpmath.mpf(0))}
        b = dict(a, omega_end=(mpmath.mpf(1), mpmath.mpf("1e-12")))
        assert route_checks.agreement(a, b, 30)["omega_end"] == 12.0


def test_every_scene_is_compared(monkeypatch):
    """routes_agree takes the worst over all the scenes: the last one off at 10 digits shows (a mutation audit:
    comparing the first scene alone left the claim confirmed)."""
    from numerics import cartesian_reference, reference_motion

    one = {"t_slide_end": mpmath.mpf(1), "t_roll_end": mpmath.mpf(2), "rest": (mpmath.mpf(3), mpmath.mpf(4)), "omega_end": None}
    monkeypatch.setattr(route_checks, "scenes", lambda: {"a": 0, "b": 1, "c": 2})
    monkeypatch.setattr(route_checks, "as_dict", lambda ref: ref)
    monkeypatch.setattr(reference_motion, "reference", lambda scene, digits, method: one)
    monkeypatch.setattr(cartesian_reference, "reference", lambda scene, digits: dict(one, rest=(3, 4 + 5e-10 * (scene == 2))))
    assert route_checks.routes_agree() == (10.0, 3)
