"""Appell's model beside the classical one: the difference is the rolling couple while sliding, and only that."""

import dataclasses
import math

import pytest

from numerics import classical_vs_appell as cva


def test_without_rolling_couple_the_models_agree():
    rows = cva.compare(params=dataclasses.replace(cva.POOL, delta=0.0))
    for row in rows:
        assert row.t_slide_appell == row.t_slide_classical
        assert row.rest_appell is None and row.rest_classical is None  # δ = 0: rolls for ever in both


def test_straight_shot_sliding_time_ratio_is_the_closed_form():
    # θ = π/2: V' = −(f(1 + R²/k²) − Rδ/k²) g against −f(1 + R²/k²) g (n°3), so the slide lasts
    # 1/(1 − Rδ/(f(R² + k²))) times longer under Appell's model.
    P = cva.POOL
    row = cva.compare()[0]
    expected = 1 / (1 - P.R * P.delta / (P.f * (P.R**2 + P.k**2)))
    assert row.t_slide_appell / row.t_slide_classical == pytest.approx(expected, rel=1e-12, abs=0)


def test_table_has_every_shot():
    rows = cva.compare()
    text = cva.as_text(rows)
    assert all(name in text for name in cva.SHOTS)
    assert all(math.isfinite(r.rest_apart) and r.rest_apart > 0 for r in rows)
    assert "-0.0000" not in text


def test_each_row_measures_both_coordinates_the_turn_and_both_runs_estimates():
    """A mutation audit: the rest points' η difference dropped, the turn measured against the Appell run itself, or
    the classical run's estimate left out of the row's error, each passed (only `make test`'s README check saw the
    first two)."""
    from numerics.scene import Scene
    from numerics.simulate import simulate

    rows = {r.shot: r for r in cva.compare()}
    masse = rows[next(name for name in cva.SHOTS if name.startswith("massé"))]
    assert masse.rest_apart == pytest.approx(math.dist(masse.rest_appell, masse.rest_classical), rel=1e-12, abs=0)
    assert masse.rest_apart > 1.5 * abs(masse.rest_appell[0] - masse.rest_classical[0])  # most of it across
    assert 0.5 < abs(masse.turn_apart) < 1.5  # degrees: the massé's rolling line turned by the couple
    for name, state in cva.SHOTS.items():
        a, c = (simulate(Scene(cva.POOL, state, (), model)) for model in ("appell", "classical"))
        assert rows[name].error == max(a.error, c.error), name
