"""Every claim of n°1–n°8 runs as a test of its own."""

import dataclasses
from functools import lru_cache

import pytest
import sympy as sp
from expectations import expected_symbolic

import derivation
from derivation import checks, n7_pure_rolling, n8_general
from derivation.newton_euler import sign_r
from derivation.symbols import Omega, R, V, delta, epsilon, f, g, k, m, r, snapshot, theta


@lru_cache(maxsize=None)
def _claims():
    return {c.id: c for c in derivation.claims()}


# The errata of n°1–n°8 and their class.  A change here is a change of what
# the package says about the paper, so it must be deliberate.
EXPECTED_ERRATA = {
    "eq2": "ocr",
    "eq4": "ocr",
    "n2.contact_derivative": "ocr",
    "n3.centre_from_slip": "ocr",
    "n3.centre_velocity": "ocr",
    "eq10": "mathematical",
    "n7.centre_acceleration": "ocr",
    "n8.V_rate_bound": "remark",
    "n8.slide_time_bound": "ocr",
    "n8.integral_rate": "ocr",
    "n8.hypothesis": "ocr",
    "eq11": "ocr",
    "n8.kinetic_energy_def": "ocr",
    "n8.product_rate": "ocr",
    "n8.theta_reason": "ocr",
}


@pytest.mark.slow  # each claim in full: appell verify checks them all in make test too
@pytest.mark.parametrize("claim_id", list(_claims()))
def test_claim(claim_id):
    claim = _claims()[claim_id]
    verdict = claim.check()
    expected = "erratum" if claim.erratum is not None else "confirmed"
    assert verdict.status == expected, verdict
    assert verdict.symbolic == expected_symbolic(claim), verdict  # proved stays proved, exact stays exact


def test_the_errata_are_the_expected_ones():
    found = {c.id: c.erratum.kind for c in _claims().values() if c.erratum is not None}
    assert found == EXPECTED_ERRATA


def test_every_numbered_equation_of_n1_to_n8_has_a_claim():
    wheres = " ".join(c.where for c in _claims().values())
    for number in (1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11):
        assert f"eq. ({number})" in wheres, number


def test_every_section_of_n2_to_n8_has_claims():
    wheres = {c.where.split(",")[0] for c in _claims().values()}
    assert {"n°2", "n°3", "n°4", "n°5", "n°6", "n°7", "n°8"} <= wheres


# Values that a sign-only claim does not pin (a mutation audit: each changed value kept its sign and passed).


def test_pure_rolling_is_rectilinear():
    """M19: n°7's "mouvement rectiligne": the velocity and the acceleration stay parallel."""
    motion = n7_pure_rolling.motion()
    velocity, acceleration = motion["velocity"], motion["acceleration"]
    assert checks.exact_zero(velocity[0] * acceleration[1] - velocity[1] * acceleration[0])


def test_the_energy_rate_is_the_work_of_the_loads():
    """M20: n8.energy_decreases checks T' < 0 only.  Its quantity is what is left once the terms in r cancel,
    d/dt(T − ½mk²r²) (Appell's second member, a referee), and the energy relation with r is n8.energy_power's."""
    claims = {c.id: c for c in n8_general.claims()}
    (row,) = claims["n8.energy_decreases"].derived
    assert checks.exact_zero(row.rhs - snapshot(-m * f * g * V - m * delta * g * Omega))
    (row,) = claims["n8.energy_power"].derived
    assert checks.exact_zero(row.rhs - snapshot(-m * f * g * V - m * delta * g * Omega - sign_r * epsilon * m * g * r))


def test_the_product_of_the_turns_is_its_value():
    """M66: n8.opposite_turns checks α'β' < 0 only."""
    value = n8_general.relations()["alpha' beta'"]
    assert checks.exact_zero(value + f * delta * R**2 * g**2 * sp.cos(theta) ** 2 / (k**4 * V * Omega))


def test_the_classical_slide_ends_at_its_value():
    """M21: n3.slide_ends checked t > 0 only; its display now pins V₀k²/(fg(R² + k²)) (the statement's value)."""
    from derivation import n3_classical

    claim = next(c for c in n3_classical.claims() if c.id == "n3.slide_ends")
    assert claim.check().status == "confirmed"
    wrong = dataclasses.replace(claim, derived=lambda: [sp.Eq(row.lhs, 2 * row.rhs) for row in claim.derived])
    assert wrong.check().status == "failed"
