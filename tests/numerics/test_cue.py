"""The cue strike (numerics.cue, Scene.from_cue, the scene file's cue block): A-30 as pooltool codes it,
the conservation laws of the strike, the signs a player expects, and a clear refusal of each bad field;
its array form (cue.strikes): the scalar strike's rows to the bit, and each refusal naming its row."""

import json
import math
import random
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from numerics import cue
from numerics.scene import Params, Scene, SceneError, load, parse

ROOT = Path(__file__).resolve().parents[2]
R = 0.028575
CLOTH = {"f": 0.2, "delta": 0.0004, "epsilon": 0.0003, "R": R}
SOLID = Params(**CLOTH)
HOLLOW = Params(**CLOTH, k=0.75 * R)  # not A-30's solid ball: R and k enter through m k²
STROKE = {"V0": 2.0, "phi": 30.0, "theta": 5.0, "a": 0.2, "b": -0.3, "M": 0.567, "m": 0.170}


def _strokes(n, seed):
    rng = random.Random(seed)
    out = []
    while len(out) < n:
        a, b = rng.uniform(-0.9, 0.9), rng.uniform(-0.9, 0.9)
        if a * a + b * b < 0.95:
            out.append({"V0": rng.uniform(0.2, 8), "phi": rng.uniform(-360, 360), "theta": rng.uniform(0, 85),
                        "a": a, "b": b, "M": rng.uniform(0.3, 0.7), "m": rng.uniform(0.1, 0.25)})
    return out


# ---- Reference: pooltool's cue strike, transcribed by hand (clearly not our code) -------------------------
# pooltool/physics/resolve/stick_ball/instantaneous_point/__init__.py: InstantaneousPoint.solve turns the
# cue-frame offsets (a, b) into the ball-frame contact point, cue_strike applies A-30 with I/m = 2R²/5 and
# rotates by phi + pi/2 (ptmath.coordinate_rotation: counter-clockwise about z). Squirt and the english
# throttle (1 by default) left out. pooltool's a = +1 is the leftmost side of the ball: a_pooltool = -a here.

def _pooltool_rotation(v, angle):
    rotation = np.array([[np.cos(angle), -np.sin(angle), 0], [np.sin(angle), np.cos(angle), 0], [0, 0, 1]])
    return rotation @ v


def _pooltool_cue_strike(m, M, R, V0, phi, theta, Q):
    phi *= np.pi / 180
    theta *= np.pi / 180
    I_m = 2 / 5 * R**2
    a, c, b = Q[:]
    numerator = 2 * V0
    temp = a**2 + (b * np.cos(theta)) ** 2 + (c * np.sin(theta)) ** 2 - 2 * b * c * np.cos(theta) * np.sin(theta)
    denominator = 1 + m / M + temp / I_m
    v = numerator / denominator
    v_B = -v * np.array([0, np.cos(theta), 0])
    vec = np.array([-c * np.sin(theta) + b * np.cos(theta), a * np.sin(theta), -a * np.cos(theta)])
    w_B = v / I_m * vec
    rot_angle = phi + np.pi / 2
    return _pooltool_rotation(v_B, rot_angle), _pooltool_rotation(w_B, rot_angle)


def _pooltool_solve(m, M, R, V0, phi, theta, cue_a, cue_b):
    theta_rad = theta * np.pi / 180
    cue_c = np.sqrt(1.0 - cue_a**2 - cue_b**2)
    ball_c = np.cos(theta_rad) * cue_c - np.sin(theta_rad) * cue_b
    ball_b = np.sin(theta_rad) * cue_c + np.cos(theta_rad) * cue_b
    return _pooltool_cue_strike(m, M, R, V0, phi, theta, R * np.array([cue_a, ball_c, ball_b]))


@pytest.mark.parametrize("stroke", _strokes(40, seed=14))
def test_solid_ball_equals_pooltools_strike(stroke):
    s = Scene.from_cue(SOLID, **stroke).state
    v, w = _pooltool_solve(stroke["m"], stroke["M"], R, stroke["V0"], stroke["phi"], stroke["theta"], -stroke["a"], stroke["b"])
    assert v[2] == 0
    scale = math.hypot(*v[:2]) / R
    np.testing.assert_allclose([s.vxi / R, s.veta / R, s.p, s.q, s.r], [*v[:2] / R, *w], rtol=0, atol=1e-12 * scale)


# ---- Independent check: the strike's conservation laws, for a ball that is not solid ----------------------

def _frame(phi, theta):
    """Unit vectors: the cue's direction d (forward and down), the player's right, and 'up' across the cue."""
    phi, theta = math.radians(phi), math.radians(theta)
    forward = np.array([math.cos(phi), math.sin(phi), 0.0])
    d = math.cos(theta) * forward - math.sin(theta) * np.array([0, 0, 1.0])
    right = np.cross(forward, [0, 0, 1.0])
    up = np.cross(right, d)
    return d, right, up


@pytest.mark.parametrize("params", [SOLID, HOLLOW], ids=["solid", "k=0.75R"])
@pytest.mark.parametrize("stroke", _strokes(12, seed=7))
def test_elastic_impulse_along_the_cue_through_the_tip(params, stroke):
    """Before the cloth takes the vertical part: the ball's velocity lies along the cue, the cue's momentum lost
    is the ball's, no energy is lost (A-30's factor 2: e = 1), and the ball's angular momentum about the tip's
    contact point Q is zero (the impulse acts there)."""
    s = Scene.from_cue(params, **stroke).state
    M, m, V0, k = stroke["M"], stroke["m"], stroke["V0"], params.k
    d, right, up = _frame(stroke["phi"], stroke["theta"])
    horizontal = np.array([s.vxi, s.veta, 0.0])
    v = np.linalg.norm(horizontal) / math.cos(math.radians(stroke["theta"]))
    velocity = horizontal + np.array([0, 0, -v * math.sin(math.radians(stroke["theta"]))])
    omega = np.array([s.p, s.q, s.r])
    np.testing.assert_allclose(velocity, v * d, rtol=0, atol=1e-14 * v)
    V1 = V0 - m * v / M  # the cue's speed after, from the momentum along the cue
    energy = 0.5 * M * V1**2 + 0.5 * m * v**2 + 0.5 * m * k**2 * omega @ omega
    assert energy == pytest.approx(0.5 * M * V0**2, rel=1e-13, abs=0)
    c = math.sqrt(1 - stroke["a"] ** 2 - stroke["b"] ** 2)
    Q = R * (stroke["a"] * right + stroke["b"] * up - c * d)
    # about Q: m k² ω + (centre − Q) × m v = 0, the centre being at −Q from the contact
    np.testing.assert_allclose(m * k**2 * omega, np.cross(Q, m * velocity), rtol=0, atol=1e-13 * m * R * v)


# ---- What a player expects --------------------------------------------------------------------------------

def _state(params=SOLID, **changes):
    return Scene.from_cue(params, **{**STROKE, "phi": 0.0, "theta": 0.0, "a": 0.0, "b": 0.0, **changes}).state


def test_follow_gives_top_spin_and_draw_back_spin():
    assert _state(b=0.4).q > 0 and _state(b=-0.4).q < 0
    assert _state(b=0.4).p == 0 and _state(b=0.4).r == 0


def test_right_english_spins_counter_clockwise_seen_from_above():
    """A tip right of centre pushes the ball's right side forward: r > 0 (pooltool's a > 0 is the left side)."""
    assert _state(a=0.3).r > 0 and _state(a=-0.3).r < 0
    assert _state(a=0.3).r == -_state(a=-0.3).r
    assert _state(a=0.3).p == 0 and _state(a=0.3).q == 0  # a level cue: side spin only


def test_elevated_cue_with_side_spin_spins_about_the_line_of_the_shot():
    s = _state(a=0.3, theta=40.0)
    assert s.p > 0 and s.q == 0  # along +ξ for right english: the massé component


@pytest.mark.parametrize("theta", [0.0, 30.0, 70.0])
def test_centre_hit_gives_no_spin_and_A30_speed(theta):
    s = _state(theta=theta)
    M, m, V0 = STROKE["M"], STROKE["m"], STROKE["V0"]
    assert (s.p, s.q, s.r, s.veta) == (0.0, 0.0, 0.0, 0.0)
    assert s.vxi == pytest.approx(2 * M * V0 / (M + m) * math.cos(math.radians(theta)), rel=1e-15, abs=0)


@pytest.mark.parametrize("params", [SOLID, HOLLOW], ids=["solid", "k=0.75R"])
def test_hit_at_k_squared_over_R_above_centre_rolls_at_once(params):
    """The centre of percussion: b R = k²/R (2R/5 for a solid ball) gives ξ' = qR, no slip."""
    s = _state(params, b=params.k**2 / params.R**2)
    assert s.vxi - s.q * params.R == pytest.approx(0, abs=1e-14 * s.vxi)


@pytest.mark.parametrize("phi", [30.0, 90.0, 200.0, -75.0])
def test_turning_the_cue_turns_velocity_and_p_q_together_and_keeps_r(phi):
    base, turned = _state(a=0.2, b=-0.3, theta=20.0), _state(a=0.2, b=-0.3, theta=20.0, phi=phi)
    c, s = math.cos(math.radians(phi)), math.sin(math.radians(phi))
    turn = np.array([[c, -s], [s, c]])
    np.testing.assert_allclose([turned.vxi, turned.veta], turn @ [base.vxi, base.veta], rtol=0, atol=1e-14 * base.vxi)
    np.testing.assert_allclose([turned.p, turned.q], turn @ [base.p, base.q], rtol=0, atol=1e-13 * abs(base.q))
    assert turned.r == pytest.approx(base.r, rel=1e-15, abs=0)


def test_position_is_carried_over():
    s = _state(xi=0.5, eta=-0.25)
    assert (s.xi, s.eta) == (0.5, -0.25)


# ---- The scene file's cue block and the API are one path ---------------------------------------------------

def test_cue_block_and_from_cue_give_the_same_scene():
    data = {"params": CLOTH, "cue": {**STROKE, "xi": 0.1}, "t": [0.2, 1.0], "model": "classical"}
    assert parse(data) == Scene.from_cue(SOLID, **STROKE, xi=0.1, times=(0.2, 1.0), model="classical")


def test_example_scene_file_is_a_cue_stroke():
    data = json.loads((ROOT / "numerics/scenes/cue.json").read_text())
    assert "cue" in data and "state" not in data
    scene = load(ROOT / "numerics/scenes/cue.json")
    assert scene == Scene.from_cue(scene.params, **data["cue"], times=tuple(data.get("t", [])))


def _cue_with(**changes):
    cue = {**STROKE, **changes}
    return {"params": CLOTH, "cue": {k: v for k, v in cue.items() if v is not None}}


@pytest.mark.parametrize(
    "data, message",
    [
        (_cue_with(V0=-1), "cue.V0: must be > 0, got -1"),
        (_cue_with(V0=0), "cue.V0: must be > 0, got 0"),
        (_cue_with(M=0), "cue.M: must be > 0"),
        (_cue_with(m=-0.17), "cue.m: must be > 0"),
        (_cue_with(theta=90), "cue.theta: must be >= 0 and < 90"),
        (_cue_with(theta=-5), "cue.theta: must be >= 0 and < 90"),
        (_cue_with(a=0.8, b=0.7), "cue.a, cue.b: a² + b² must be < 1"),
        (_cue_with(b=-1), "cue.a, cue.b: a² + b² must be < 1"),
        (_cue_with(a=0.6, b=0.8), "cue.a, cue.b: a² + b² must be < 1"),  # exactly 1 in float64: a grazing miss
        (_cue_with(a=1e200), "cue.a, cue.b: a² + b² must be < 1"),  # its square overflows: still this line
        (_cue_with(b=-1e155), "cue.a, cue.b: a² + b² must be < 1"),
        (_cue_with(V0="fast"), "cue.V0: must be a number"),
        (_cue_with(phi=True), "cue.phi: must be a number"),
        (_cue_with(V0=None), "cue.V0: missing"),
        (_cue_with(spin=3), "cue.spin: unknown field"),
        ({"params": CLOTH, "cue": [2.0]}, "cue: must be an object"),
        ({"params": CLOTH}, "scene.state: missing (or a cue block"),
        ({**_cue_with(), "state": {"xi": 0, "eta": 0, "vxi": 1, "veta": 0, "p": 0, "q": 0, "r": 0}}, "scene.cue: give a state or a cue block, not both"),
    ],
)
def test_bad_cue_fields_are_one_line_naming_the_field(data, message):
    with pytest.raises(SceneError) as error:
        parse(data)
    assert str(error.value).startswith(message) and "\n" not in str(error.value)


def test_a_turn_of_the_cue_is_reduced_exactly_before_its_angle_is_taken():
    """φ = 1e300 degrees went through radians() unreduced: the shot left 131° astray of 1e300 mod 360 = 0°, with no
    error said (an audit).  A whole number of turns is no turn; any φ gives φ mod 360's strike to the bit."""
    for phi in (1e300, 1e15, 1e9 + 30, -720.0 + 45):
        reduced = Scene.from_cue(SOLID, **{**STROKE, "phi": math.fmod(phi, 360.0)})
        assert Scene.from_cue(SOLID, **{**STROKE, "phi": phi}).state == reduced.state
    assert Scene.from_cue(SOLID, **{**STROKE, "phi": 1e300}).state.veta == 0.0  # 1e300 is a multiple of 360
    rows = cue.strikes(R, SOLID.k, **{**GOOD, "phi": [30.0, 390.0, 30.0 + 3600.0, 30.0]})
    assert (rows[1:] == rows[0]).all()
    with pytest.raises(SceneError, match=r"^cue\.V0: too fast for this ball"):  # the API and the file as strikes
        Scene.from_cue(SOLID, **{**STROKE, "V0": 1e307})


def test_api_refuses_as_the_file_does():
    with pytest.raises(SceneError, match=r"^cue.V0: must be > 0, got -1$"):
        Scene.from_cue(SOLID, **{**STROKE, "V0": -1})
    with pytest.raises(SceneError, match=r"^cue.V0: must be finite, got nan$"):
        Scene.from_cue(SOLID, **{**STROKE, "V0": float("nan")})
    with pytest.raises(SceneError, match=r"^scene.params: must be a Params"):
        Scene.from_cue(CLOTH, **STROKE)


@pytest.mark.parametrize("changes, field", [
    ({"M": 1e-300}, "cue.M, cue.m: a ball 1.7e+299 times as heavy as the cue: the stroke leaves the ball at "),
    ({"m": 1e300}, "cue.M, cue.m: a ball 1.76e+300 times as heavy as the cue: the stroke leaves the ball at "),
    ({"V0": 1e-300}, "cue.V0: the stroke leaves the ball at "),
    ({"V0": 1e150}, "cue.V0: the stroke leaves the ball at "),
    ({"xi": 1e200}, "cue.xi: the motion's distance bound would be 1e+200"),
])
def test_a_stroke_whose_ball_float64_cannot_follow_names_the_cue(changes, field):
    """The state a stroke made was refused by its fields (state.vxi, state.veta, …), which the user never gave:
    a cue 1e-300 kg light (an audit).  The cue's fields are named, with the speed it gave."""
    with pytest.raises(SceneError) as error:
        Scene.from_cue(SOLID, **{**STROKE, **changes})
    assert str(error.value).startswith(field) and "state." not in str(error.value), error.value


def test_cli_simulates_a_cue_stroke_and_refuses_a_bad_one(tmp_path):
    run = [sys.executable, "-m", "paper", "simulate"]
    good = subprocess.run(run + ["numerics/scenes/cue.json", "--json"], cwd=ROOT, capture_output=True, text=True)
    assert good.returncode == 0, good.stderr
    first = json.loads(good.stdout)
    assert first["t_slide_end"] > 0 and first["rest"] is not None
    bad = tmp_path / "bad_cue.json"
    bad.write_text(json.dumps(_cue_with(V0=-1)))
    refused = subprocess.run(run + [str(bad)], cwd=ROOT, capture_output=True, text=True)
    assert refused.returncode == 2 and refused.stdout == ""
    assert refused.stderr.strip().splitlines() == [refused.stderr.strip()] and "cue.V0: must be > 0, got -1" in refused.stderr


# ---- Many strokes at once: cue.strikes ---------------------------------------------------------------------

def _columns(strokes):
    return {name: np.array([stroke[name] for stroke in strokes]) for name in strokes[0]}


@pytest.mark.parametrize("params", [SOLID, HOLLOW], ids=["solid", "k=0.75R"])
def test_strikes_are_from_cues_states_to_the_bit(params):
    """Row by row, == on floats: elevated cues (θ up to 85°), side spin and draw, every direction, anywhere."""
    rng = random.Random(30)
    strokes = [{**stroke, "xi": rng.uniform(-1, 1), "eta": rng.uniform(-1, 1)} for stroke in _strokes(300, seed=30)]
    states = cue.strikes(params.R, params.k, **_columns(strokes))
    assert states.shape == (300, 7) and states.dtype == np.float64 and states.flags.c_contiguous
    assert states.tolist() == [list(Scene.from_cue(params, **stroke).state.row()) for stroke in strokes]


def test_numbers_and_arrays_broadcast_together():
    V0 = np.array([0.5, 2.0, 6.0])
    one = {**STROKE, "xi": 0.1}
    states = cue.strikes(R, SOLID.k, **{**one, "V0": V0, "b": [-0.3]})  # a list of one: every row's, as in NumPy
    each = [list(Scene.from_cue(SOLID, **{**one, "V0": v}).state.row()) for v in V0]
    assert states.tolist() == each
    assert cue.strikes(R, SOLID.k, **one).tolist() == [list(Scene.from_cue(SOLID, **one).state.row())]  # numbers: one row


class Column:
    """What a pandas Series or an xarray DataArray offers NumPy (neither is a dependency): ``__array__``."""

    def __init__(self, values):
        self.values = values

    def __array__(self, dtype=None, copy=None):
        return np.asarray(self.values, dtype=dtype)


def test_a_column_of_a_table_is_read_as_its_array():
    V0 = [0.5, 2.0, 6.0]
    assert cue.strikes(R, SOLID.k, **{**STROKE, "V0": Column(V0)}).tolist() == cue.strikes(R, SOLID.k, **{**STROKE, "V0": V0}).tolist()
    with pytest.raises(SceneError, match=r"cue\.M\[1\]: must be > 0"):
        cue.strikes(R, SOLID.k, **{**STROKE, "V0": Column(V0), "M": Column([0.17, -1.0, 0.17])})


@pytest.mark.parametrize("empty", [np.array([]), [], np.zeros(0, dtype=int)], ids=["float64", "list", "int"])
def test_no_strokes_is_no_rows(empty):
    assert cue.strikes(R, SOLID.k, **{**STROKE, "phi": empty}).shape == (0, 7)
    assert cue.strikes(R, SOLID.k, **{**STROKE, "phi": empty, "V0": [2.0]}).shape == (0, 7)


GOOD = {name: np.full(4, value) for name, value in STROKE.items()}


@pytest.mark.parametrize(
    "changes, message",
    [
        ({"V0": [2, 1, 0.5, -1]}, "cue.V0[3]: must be > 0, got -1"),
        ({"V0": np.array([2, 0, 1, 0])}, "cue.V0[1]: must be > 0, got 0"),  # integers
        ({"M": [0.5, 0.0, 0.5, 0.5]}, "cue.M[1]: must be > 0, got 0"),
        ({"m": -0.17}, "cue.m: must be > 0, got -0.17"),  # a number breaks it in every row: named as given
        ({"theta": [5, 90, 91, 5]}, "cue.theta[1]: must be >= 0 and < 90 (degrees of elevation), got 90"),
        ({"theta": [-5.0]}, "cue.theta[0]: must be >= 0 and < 90"),
        ({"a": [0.2, 0.2, 0.8, 0.2], "b": [0.0, -0.3, 0.7, 0.0]}, "cue.a[2], cue.b[2]: a² + b² must be < 1 (the cue's axis must meet the ball), got a = 0.8, b = 0.7"),
        ({"a": 0.6, "b": [0.0, 0.0, -0.8, 0.0]}, "cue.a, cue.b[2]: a² + b² must be < 1"),  # exactly 1 in float64
        ({"a": [0.8], "b": [0.0, 0.0, 0.7, 0.0]}, "cue.a[0], cue.b[2]: a² + b² must be < 1 (the cue's axis must meet the ball), got a = 0.8, b = 0.7"),
        ({"a": [0, 1e200, 0, 0]}, "cue.a[1], cue.b[1]: a² + b² must be < 1"),  # its square overflows: still this rule
        ({"b": np.array([0, 0, 0, -1e155])}, "cue.a[3], cue.b[3]: a² + b² must be < 1"),
        ({"phi": [0, 30, float("nan"), 0]}, "cue.phi[2]: must be finite, got nan"),
        ({"xi": np.array([0, -np.inf, 0, 0])}, "cue.xi[1]: must be finite, got -inf"),
        ({"eta": np.array([0, 1, np.inf, 0], dtype=np.float32)}, "cue.eta[2]: must be finite, got inf"),
        ({"V0": [2.0, "fast", 2.0, 2.0]}, "cue.V0[1]: must be a number, got 'fast'"),
        ({"V0": "fast"}, "cue.V0: must be a number, got 'fast'"),  # `real`'s words for a number
        ({"phi": [0.0, None, 0.0, 0.0]}, "cue.phi[1]: must be a number, got None"),
        ({"phi": None}, "cue.phi: must be a number, got None"),
        ({"phi": [True, 0.5, 0.5, 0.5]}, "cue.phi[0]: must be a number, got True"),  # NumPy would read 1.0
        ({"phi": np.array([False, True, True, True])}, "cue.phi[0]: must be a number, got np.False_"),
        ({"phi": True}, "cue.phi: must be a number, got True"),
        ({"a": np.array([0.1j])}, "cue.a[0]: must be a real number"),
        ({"M": [0.5, 10**400, 0.5, 0.5]}, "cue.M[1]: must be within float64's range"),
        ({"M": np.array(["0.5", "1e400", "0.5", "0.5"], dtype=np.longdouble)}, "cue.M[1]: must be finite, got inf"),  # as `real`
        ({"V0": np.array(-1.0)}, "cue.V0: must be > 0, got -1"),  # a 0-d array is a number
        ({"V0": np.ma.array([1.0, 2.0, 3.0, 4.0], mask=[0, 0, 1, 0])}, "cue.V0[2]: must be a number, got a masked value"),
        ({"V0": np.ones((4, 1))}, "cue.V0: must be a number or a 1-D array, got an array of shape (4, 1)"),
        ({"b": [[0.1, 0.2]]}, "cue.b: must be a number or a 1-D array, got an array of shape (1, 2)"),
        ({"phi": np.zeros(5)}, "cue.phi: must have 4 rows as cue.V0 has (or 1, or be a number), got 5"),
        ({"V0": 2.0, "phi": np.zeros(3)}, "cue.M: must have 3 rows as cue.phi has (or 1, or be a number), got 4"),
        ({"R": 0}, "R: must be > 0, got 0"),
        ({"k": float("inf")}, "k: must be finite, got inf"),
        ({"k": "0.018"}, "k: must be a number, got '0.018'"),
        # A ball's rules for R and k (an audit: k = 1e-200 divided by zero, k = 1 m on a 28 mm ball passed).
        ({"k": 1e-200}, "k: must be between 1e-100 and 1e+100"),
        ({"k": 1.0}, "k: must be <= R √(2/3)"),
        # A stroke float64 cannot hold: V0 = 1e307 gave NaN spins with a warning (an audit).
        ({"V0": [2, 1e307, 2, 2]}, "cue.V0[1]: too fast for this ball: the speed and spin it gives (V0 R/k²) overflow float64, got 1e+307"),
    ],
)
@pytest.mark.filterwarnings("error")  # one SceneError, no warning on the way (overflow: 1e200², a longdouble's cast)
def test_strikes_refuse_a_bad_field_naming_its_row(changes, message):
    given = {"R": R, "k": SOLID.k, **GOOD, **changes}
    with pytest.raises(SceneError) as error:
        cue.strikes(**given)
    assert str(error.value).startswith(message) and "\n" not in str(error.value)


@pytest.mark.parametrize("field, bad", [("V0", -2.0), ("M", 0.0), ("m", 0.0), ("theta", 95.0), ("a", 1.0), ("phi", np.nan)])
def test_the_first_bad_row_among_good_ones_is_named(field, bad):
    strokes = _columns(_strokes(2000, seed=31))
    good = strokes[field][1234]
    strokes[field][[1234, 1700]] = bad
    with pytest.raises(SceneError) as error:
        cue.strikes(R, SOLID.k, **strokes)
    named = "cue.a[{0}], cue.b[{0}]" if field == "a" else f"cue.{field}[{{0}}]"
    assert error.value.field == named.format(1234)
    strokes[field][1234] = good  # that row mended: the next one is named
    with pytest.raises(SceneError) as error:
        cue.strikes(R, SOLID.k, **strokes)
    assert error.value.field == named.format(1700)


def test_rules_are_checked_in_cues_order_then_by_row():
    """As one Cue would be checked: V0's rule before θ's, whichever row breaks each."""
    with pytest.raises(SceneError, match=r"^cue\.V0\[3\]: "):
        cue.strikes(R, SOLID.k, **{**GOOD, "V0": [2, 2, 2, -1], "theta": [5, 95, 5, 5]})


def test_a_mass_ratio_beyond_float64_is_refused_not_a_ball_left_still():
    """An audit: m = 1e308 on a 0.5 kg cue (or M = 1e-310) made 1 + m/M infinite and the ball's speed exactly 0,
    simulated with exit 0; the ratio's rule names both masses, and the row of an array."""
    with pytest.raises(SceneError, match=r"^cue.M, cue.m: the ball would be m/M times as heavy as the cue.*m = 1e\+308$"):
        cue.Cue(V0=2.0, phi=0.0, M=0.5, m=1e308)
    with pytest.raises(SceneError, match=r"^cue.M\[2\], cue.m: the ball would be m/M"):
        cue.strikes(0.028575, 0.0180724, V0=2.0, phi=0.0, M=[0.5, 0.5, 1e-310], m=0.17)
    assert cue.strikes(0.028575, 0.0180724, V0=2.0, phi=0.0, M=[0.5, 1e-300], m=0.17)[1, 2] > 0  # huge, finite: moves
