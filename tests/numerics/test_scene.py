"""Scene files: defaults, and one clear line for every rule a scene can break."""

import json
import math

import pytest

from numerics.scene import SceneError, load, parse

GOOD = {
    "params": {"f": 0.2, "delta": 0.0004, "epsilon": 0.0003, "R": 0.028575},
    "state": {"xi": 0, "eta": 0, "vxi": 2.0, "veta": 0.0, "p": 10.0, "q": -40.0, "r": 5.0},
}


def _with(part, name, value):
    data = json.loads(json.dumps(GOOD))
    if value is None:
        del data[part][name]
    else:
        data[part][name] = value
    return data


def test_defaults_solid_ball_and_standard_gravity():
    scene = parse(GOOD)
    assert scene.params.k == pytest.approx(math.sqrt(0.4) * 0.028575, rel=1e-15, abs=0)
    assert scene.params.g == 9.81
    assert scene.times == () and scene.model == "appell"


@pytest.mark.parametrize(
    "data, field, rule",
    [
        (_with("params", "R", 0), "params.R", "> 0"),
        (_with("params", "R", -1), "params.R", "> 0"),
        (_with("params", "f", 0), "params.f", "> 0"),
        (_with("params", "k", 0), "params.k", "> 0"),
        (_with("params", "g", -9.81), "params.g", "> 0"),
        (_with("params", "delta", -1e-4), "params.delta", ">= 0"),
        (_with("params", "epsilon", -1e-4), "params.epsilon", ">= 0"),
        (_with("params", "delta", 0.2 * 0.028575), "params.delta", "< f R"),
        (_with("params", "delta", None), "params.delta", "missing"),
        (_with("params", "mu", 0.1), "params.mu", "unknown field"),
        (_with("state", "p", None), "state.p", "missing"),
        (_with("state", "w", 1.0), "state.w", "unknown field"),
        (_with("state", "vxi", "fast"), "state.vxi", "must be a number"),
        (_with("state", "vxi", True), "state.vxi", "must be a number"),
        ({**GOOD, "t": [0.1, -1]}, "t[1]", ">= 0"),
        (_with("params", "k", 0.028575 * math.sqrt(2 / 3) * (1 + 1e-9)), "params.k", "R √(2/3)"),  # just above a shell
        ({**GOOD, "t": 0.1}, "t", "list"),
        ({**GOOD, "model": "pooltool"}, "model", "must be one of"),
        ({**GOOD, "colour": "red"}, "scene.colour", "unknown field"),
        ({"state": GOOD["state"]}, "scene.params", "missing"),
        ([1, 2], "scene", "JSON object"),
    ],
)
def test_each_rule_is_one_line_naming_field_and_rule(data, field, rule):
    with pytest.raises(SceneError) as error:
        parse(data)
    message = str(error.value)
    assert "\n" not in message
    assert message.startswith(field) and rule in message


@pytest.mark.parametrize("text, rule", [("NaN", "finite"), ("Infinity", "finite"), ("-Infinity", "finite")])
def test_non_finite_numbers_from_json(tmp_path, text, rule):
    path = tmp_path / "scene.json"
    path.write_text(json.dumps(GOOD).replace('"vxi": 2.0', f'"vxi": {text}'))
    with pytest.raises(SceneError, match=rf"^state.vxi: must be {rule}"):
        load(path)


def test_unreadable_and_invalid_json(tmp_path):
    with pytest.raises(SceneError, match="cannot read"):
        load(tmp_path / "missing.json")
    path = tmp_path / "broken.json"
    path.write_text('{"params": ')
    with pytest.raises(SceneError, match="not valid JSON"):
        load(path)
    path.write_text(" \n")
    with pytest.raises(SceneError, match="broken.json: empty: no JSON in it"):
        load(path)


def test_a_time_of_zero_is_asked_like_any_other():
    """t = 0 is the start: its state is the scene's own (a mutation refusing t = 0 went unnoticed)."""
    from numerics.simulate import simulate

    scene = parse({**GOOD, "t": [0, 0.5]})
    assert scene.times == (0.0, 0.5)
    start = simulate(scene).state_at(0.0)
    # to rounding: the slide's state is carried in the slip's frame (V, α) and rotated back
    assert (start.xi, start.eta, start.vxi, start.veta, start.p, start.q, start.r) == pytest.approx(
        tuple(GOOD["state"].values()), rel=1e-15, abs=1e-15)
    shell = parse(_with("params", "k", 0.028575 * math.sqrt(2 / 3)))  # a thin shell, the largest k: allowed
    assert shell.params.k == 0.028575 * math.sqrt(2 / 3)
