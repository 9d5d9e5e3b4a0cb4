"""Params.from_pool and Params.pool: pool simulators' u_s, u_r, u_sp and the paper's f, δ, ε, through the simulator."""

import math
import random

import pytest

from numerics.scene import Params, PoolCoefficients, Scene, SceneError, State
from numerics.simulate import simulate

R = 0.028575
# pooltool's prebuilt BallParams (pooltool/objects/ball/params.py), typed: name -> (u_s, u_r, u_sp_proportionality, R, g).
# Its u_sp is the property u_sp_proportionality * R.
POOLTOOL = {
    "POOL_GENERIC": (0.2, 0.01, 10 * 2 / 5 / 9, 0.028575, 9.81),
    "SNOOKER_GENERIC": (0.5, 0.01, 10 * 2 / 5 / 9, 0.02619375, 9.81),
    "BILLIARD_GENERIC": (0.5, 0.01, 10 * 2 / 5 / 9, 0.03048, 9.81),
}


@pytest.mark.parametrize("seed", range(5))
@pytest.mark.parametrize("k", [None, 0.5 * R, 0.8 * R])
def test_round_trip(seed, k):
    rng = random.Random(seed)
    u_s, u_sp = rng.uniform(0.05, 0.6), rng.uniform(0, 0.05)
    u_r = rng.uniform(0, 0.5) * u_s
    params = Params.from_pool(u_s, u_r, u_sp, R=R, k=k)
    assert isinstance(params.pool(), PoolCoefficients)
    assert params.pool() == pytest.approx((u_s, u_r, u_sp), rel=1e-14, abs=1e-300)
    assert Params.from_pool(*params.pool(), R=R, k=params.k).values() == pytest.approx(params.values(), rel=1e-14, abs=0)


def test_solid_ball_values():
    """Design notes: δ = 1.4 u_r R, ε = u_sp R for a solid ball."""
    params = Params.from_pool(0.2, 0.01, 0.0127, R=R)
    assert params.f == 0.2 and params.k == pytest.approx(math.sqrt(0.4) * R, rel=1e-15, abs=0)
    assert params.delta == pytest.approx(1.4 * 0.01 * R, rel=1e-14, abs=0)
    assert params.epsilon == pytest.approx(0.0127 * R, rel=1e-15, abs=0)


@pytest.mark.parametrize("k", [None, 0.5 * R, 0.8 * R], ids=["solid", "k=0.5R", "k=0.8R"])
def test_pure_rolling_decelerates_at_u_r_g(k):
    """n°7 through the simulator: a ball rolling without slip at V0 has speed V0 − u_r g t, whatever k."""
    u_r, V0, t = 0.012, 1.5, 2.0
    params = Params.from_pool(0.2, u_r, 0.01, R=R, k=k)
    motion = simulate(Scene(params, State(0, 0, V0, 0, 0, V0 / R, 0)), jit=False)
    s = motion.state_at(t)
    assert s.phase == "rolling"
    assert s.vxi == pytest.approx(V0 - u_r * params.g * t, rel=1e-12, abs=0)
    assert motion.t_roll_end == pytest.approx(V0 / (u_r * params.g), rel=1e-12, abs=0)


@pytest.mark.parametrize("k", [None, 0.5 * R], ids=["solid", "k=0.5R"])
def test_pivot_decelerates_at_pooltools_rate(k):
    """eq. (5) through the simulator: r' = −u_sp R g/k², pooltool's 5 u_sp g/(2R) for a solid ball."""
    u_sp, r0, t = 0.0127, 30.0, 0.2
    params = Params.from_pool(0.2, 0.01, u_sp, R=R, k=k)
    rate = 5 * u_sp * params.g / (2 * R) if k is None else u_sp * R * params.g / k**2
    motion = simulate(Scene(params, State(0, 0, 0, 0, 0, 0, r0)), jit=False)
    assert motion.state_at(t).r == pytest.approx(r0 - rate * t, rel=1e-12, abs=0)
    assert motion.t_pivot_end == pytest.approx(r0 / rate, rel=1e-12, abs=0)


@pytest.mark.parametrize("name", POOLTOOL)
def test_pooltools_defaults_are_a_cloth_of_the_paper(name):
    u_s, u_r, proportionality, radius, g = POOLTOOL[name]
    params = Params.from_pool(u_s, u_r, proportionality * radius, R=radius, g=g)
    assert params.delta < params.f * params.R  # eq. (9)
    assert params.epsilon == pytest.approx(proportionality * radius**2, rel=1e-15, abs=0)


@pytest.mark.parametrize(
    "args, message",
    [
        ((0.2, 0.15, 0.01), "u_r: must be < u_s R²/(R² + k²) = 0.142857"),
        ((0.0, 0.0, 0.01), "u_s: must be > 0, got 0"),
        ((0.2, -0.01, 0.01), "u_r: must be >= 0"),
        ((0.2, 0.01, -1), "u_sp: must be >= 0"),
        ((0.2, float("nan"), 0.01), "u_r: must be finite"),
        (("0.2", 0.01, 0.01), "u_s: must be a number"),
        # Mapped to δ and ε, a float64 underflow or overflow is the user's u_r or u_sp (δ = 0 passed silently).
        ((0.2, 5e-324, 0.01), "u_r: too small: delta = u_r (R² + k²)/R underflows to 0 in float64, got 5e-324"),
        ((0.2, 0.01, 5e-324), "u_sp: too small: epsilon = u_sp R underflows to 0 in float64, got 5e-324"),
        ((0.2, 1e-320, 0.01), "u_r: gives delta = u_r (R² + k²)/R = 4.00193e-322, which must be 0 or between 1e-100"),
        ((0.2, 0.01, 1e308), "u_sp: gives epsilon = u_sp R = 2.8575e+306, which must be 0 or between 1e-100 and 1e+100"),
    ],
)
def test_bad_coefficients_are_refused_naming_them(args, message):
    with pytest.raises(SceneError) as error:
        Params.from_pool(*args, R=R)
    assert str(error.value).startswith(message) and "\n" not in str(error.value)


def test_bad_ball_is_refused_as_params_are():
    with pytest.raises(SceneError, match=r"^params.R: must be > 0"):
        Params.from_pool(0.2, 0.01, 0.01, R=-1)
    with pytest.raises(SceneError, match=r"^params.k: must be <= R"):
        Params.from_pool(0.2, 0.01, 0.01, R=R, k=R)
