"""A scene: one ball, its parameters, its initial state (SI units, the paper's names).

    {"params": {"f": 0.2, "delta": 0.0004, "epsilon": 0.0003, "R": 0.028575, "k": 0.018072, "g": 9.81},
     "state": {"xi": 0, "eta": 0, "vxi": 2.0, "veta": 0.0, "p": 10.0, "q": -40.0, "r": 5.0},
     "t": [0.1, 0.5], "model": "appell"}

``k`` defaults to √(2/5) R (solid ball), ``g`` to 9.81, ``t`` to none,
``model`` to "appell" ("classical": no rolling couple while sliding).
Anything else is refused with one line naming the field and the rule.
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass, field
from pathlib import Path

from numerics.equations import Params

PARAM_FIELDS = ("f", "delta", "epsilon", "R", "k", "g")
STATE_FIELDS = ("xi", "eta", "vxi", "veta", "p", "q", "r")
MODELS = ("appell", "classical")


class SceneError(ValueError):
    """A scene that breaks a rule: the message is the one line shown to the user."""


@dataclass(frozen=True)
class State:
    xi: float
    eta: float
    vxi: float
    veta: float
    p: float
    q: float
    r: float


@dataclass(frozen=True)
class Scene:
    params: Params
    state: State
    times: tuple = field(default_factory=tuple)
    model: str = "appell"


def _number(value, where: str) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise SceneError(f"{where}: must be a number, got {json.dumps(value)}")
    if not math.isfinite(value):
        raise SceneError(f"{where}: must be finite, got {value}")
    return float(value)


def _fields(obj, where: str, required: tuple, optional: tuple = ()) -> dict:
    if not isinstance(obj, dict):
        raise SceneError(f"{where}: must be an object")
    unknown = sorted(set(obj) - set(required) - set(optional))
    if unknown:
        raise SceneError(f"{where}.{unknown[0]}: unknown field (allowed: {', '.join(required + optional)})")
    missing = [name for name in required if name not in obj]
    if missing:
        raise SceneError(f"{where}.{missing[0]}: missing")
    return {name: _number(obj[name], f"{where}.{name}") for name in required + optional if name in obj}


def parse(data) -> Scene:
    """A Scene from decoded JSON, or SceneError."""
    if not isinstance(data, dict):
        raise SceneError("scene: must be a JSON object")
    unknown = sorted(set(data) - {"params", "state", "t", "model"})
    if unknown:
        raise SceneError(f"scene.{unknown[0]}: unknown field (allowed: params, state, t, model)")
    for name in ("params", "state"):
        if name not in data:
            raise SceneError(f"scene.{name}: missing")
    pr = _fields(data["params"], "params", ("f", "delta", "epsilon", "R"), ("k", "g"))
    for name, rule, ok in (
        ("R", "> 0", pr["R"] > 0),
        ("f", "> 0", pr["f"] > 0),
        ("delta", ">= 0", pr["delta"] >= 0),
        ("epsilon", ">= 0", pr["epsilon"] >= 0),
        ("k", "> 0", pr.get("k", 1) > 0),
        ("g", "> 0", pr.get("g", 1) > 0),
    ):
        if not ok:
            raise SceneError(f"params.{name}: must be {rule}, got {pr[name]}")
    if pr["delta"] >= pr["f"] * pr["R"]:
        raise SceneError(
            f"params.delta: must be < f R (eq. (9), the paper's whole analysis assumes it), "
            f"got delta = {pr['delta']} >= f R = {pr['f'] * pr['R']}"
        )
    params = Params(
        f=pr["f"], delta=pr["delta"], epsilon=pr["epsilon"], R=pr["R"],
        k=pr.get("k", math.sqrt(2 / 5) * pr["R"]), g=pr.get("g", 9.81),
    )
    state = State(**_fields(data["state"], "state", STATE_FIELDS))
    times = data.get("t", [])
    if not isinstance(times, list):
        raise SceneError("t: must be a list of times")
    times = tuple(_number(x, f"t[{i}]") for i, x in enumerate(times))
    for i, x in enumerate(times):
        if x < 0:
            raise SceneError(f"t[{i}]: must be >= 0, got {x}")
    model = data.get("model", "appell")
    if model not in MODELS:
        raise SceneError(f"model: must be one of {', '.join(MODELS)}, got {json.dumps(model)}")
    return Scene(params, state, times, model)


def with_model(scene: Scene, model: str) -> Scene:
    if model not in MODELS:
        raise SceneError(f"model: must be one of {', '.join(MODELS)}, got {json.dumps(model)}")
    return Scene(scene.params, scene.state, scene.times, model)


def load(path: str | Path) -> Scene:
    """Read and check a scene file."""
    try:
        text = Path(path).read_text(encoding="utf-8")
    except OSError as error:
        raise SceneError(f"{path}: cannot read ({error.strerror})") from None
    try:
        data = json.loads(text)
    except json.JSONDecodeError as error:
        raise SceneError(f"{path}: not valid JSON ({error.msg} at line {error.lineno})") from None
    return parse(data)
