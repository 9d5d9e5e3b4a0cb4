"""The phase engine: one scene from its state at t = 0 to rest, each phase with the cheapest exact model.

This is the one phase layer of the simulator (design notes, "one phase
layer"): `simulate` runs it on one scene, `simulate_many` on many, each scene
with its own parameters (`begin` settles what closed forms can, `finish` what
follows a numerical slide; a batch integrates its slides side by side in
`numerics.lanes`, step for step as here).  It is plain Python on floats and NumPy arrays in
the subset numba compiles (`numerics.compiled`); interpreted, it answers one
scene from a cold start without compiling anything.  Every formula comes from
the generated `kernels` (derivation → `codegen` → kernels), none is typed here.

Phases (n°3–n°8):

* sliding — n°3's closed form when δ = 0 or for the classical model; the
  straight shots' closed form when the spin is square to the slip (θ = ±π/2,
  a centre-ball hit Ω₀ = 0 by n°6, a draw whose spin reverses and comes back
  along β = α + π/2); otherwise Dormand–Prince 8(5,3) in σ = −ln V, where the
  slide is smooth to its end (α' ∝ V^(κ−1) is not, in t), followed to
  V = V₀·END_FRACTION·tol/TOL_SAFETY and finished to first order, the slip
  leaving along β − π/2; a state inside it comes from DOP853's interpolant, or
  in a stiff stretch (near δ = fR) from substeps (`slide_state_at`);
* pure rolling — n°7's closed form, until Ω = 0 (never when δ = 0);
* pivoting — eq. (5), independent of the rest.

The numerical slide carries (t, cos α, sin α, p, q, ξ, η): the slip's unit
vector rather than its angle, so that no sine or cosine is evaluated per
step.  It runs at tol/TOL_SAFETY, a margin measured so that the rest point's
error is within the tolerance asked on the bench scenes and seeded random
fast shots.  Its error estimate is DOP853's own local estimate summed over
the steps with an ulp of rounding each, carried to the rest point (an estimate, not a bound, and
pessimistic: often above the tolerance while the error is below it; the
tests check that it is above the error, against the mpmath reference, on
every hard case).
"""

import math

import numpy as np

from numerics.kernels import (  # bare names: the compiled copy rebinds them (`numerics.compiled`)
    centre_velocity,
    classical_at,
    classical_end,
    draw_at,
    draw_end,
    follow_at,
    follow_end,
    pivot_at,
    pivot_end,
    rolling_at,
    rolling_end,
    slide_rates,
    slip_velocity,
)
from numerics.dop853_steps import (  # generated from the tables: bare names, as the kernels'
    dense_0, dense_1, dense_2, dense_3, error_terms, solution, stage_1, stage_2, stage_3, stage_4, stage_5, stage_6,
    stage_7, stage_8, stage_9, stage_10, stage_11, stage_13, stage_14, stage_15,
)
from numerics.dop853_tables import C, N_EXTENDED, N_STAGES
from numerics.lane_rows import N_Y  # the slide's state length, defined with the rows of a block of lanes
from numerics.vector_exp import exp  # the same bits here and in the lanes, where it vectorises

# How each scene slides (OUT_MODEL).
NONE, CLASSICAL, FOLLOW, DRAW, DRAW_REVERSED, NUMERICAL = range(6)
MODEL_NAMES = (
    "none (no slip at the start)",
    "closed form n°3 (no rolling couple)",
    "closed form straight shot, θ = π/2",
    "closed form straight shot, θ = −π/2",
    "closed form straight shot, θ = −π/2 then π/2 after the spin reversed",
    "numerical: DOP853 in σ = −ln V",
)
# |θ ∓ π/2| below STRAIGHT_ANGLE, and below STRAIGHT_PER_TOL · tol, is a straight shot: its closed form is then off
# by |θ ∓ π/2| times a lever of the shot (0.2 typical, 4.3 at the 99th percentile and 16.7 at worst over 400
# random near-straight shots, mostly draws): a lever up to 1000 stays within tol (100 at tol 1e-13, where the floor
# sets the angle).  With STRAIGHT_ANGLE alone, a draw 0.9e-12 rad off was 1.8× tol 1e-12 off, an estimate of 0 (an
# audit, against the mpmath reference).  Below STRAIGHT_FLOOR, a few ulps of π/2, θ₀'s own rounding: an exactly
# straight shot stays straight.
STRAIGHT_ANGLE, STRAIGHT_PER_TOL, STRAIGHT_FLOOR = 1e-12, 1e-3, 1e-15
NO_SLIP = 1e-14  # a slip below this fraction of the shot's speeds is none
# Below this fraction of its scale, Ω's error is measured against the floor, and its turn not followed (at 1e-3, 9 of
# 100,000 seeded near-straight draws with pool parameters had their error estimate at tol 1e-9 below the error:
# tests/numerics/test_batch.py; at 1e-6 none).
SPIN_FLOOR = 1e-6
# Ω's direction turns at most this much (rad) in one step (`turn_norm`): with it every near miss tried is within the
# tolerance asked; when it came it cost the bench's curved slides 4 step attempts in 789 (SPIN_FLOOR 1e-3 then).
MAX_TURN = 0.5
COS_MAX_TURN = math.cos(MAX_TURN)
END_FRACTION = 0.1  # the slide is integrated to V₀·END_FRACTION·tol, then finished to first order (error O(V²))
MAX_STEPS = 20_000  # step attempts of one slide: a bound on work, never reached by a real shot
# The slide runs at tol/TOL_SAFETY: measured on seeded random fast, high-spin shots and the bench scenes, the rest
# point's error is then within the tolerance asked (`appell bench`), and so is every state between two steps of the
# slide (DOP853's 7th-order interpolant, which no error estimate checks): midway between every two steps of the 153
# numerical slides of those scenes at tol 1e-6, 1e-9 and 1e-12, at most 0.72 tol (1.04 with 12; `bench.dense_midway`,
# tests/numerics/test_engine.py).
TOL_SAFETY = 16.0
# The reported error: the local estimates of the accepted steps summed, times this margin — on 120 seeded random
# fast, high-spin shots (numerics.bench_set.fast_scenes, other seeds) the plain sum fell 8% short of the true
# error once (at tol 1e-6); with the margin it was at least 1.85× the true error on every one, and on every
# bench scene, when it was set (before TOL_SAFETY; `appell bench`'s calibration prints today's least ratio).
# An estimate, not a bound.
ESTIMATE_MARGIN = 2.0
ROUNDING = 2.0**-52  # float64's relative precision: the rounding of a step's sum, in the estimate (`finish`)
# A closed form's rest point is exact but for rounding: the start plus the slide plus the roll, each a few
# operations, each rounded to an ulp of the coordinates' size.  Its estimate counts CLOSED_ROUNDINGS such ulps
# (`closed_estimate`; it was 0, and a start 1e8 m from the origin was 6e-10 off with an estimate of 0: a user
# audit).  Against the 40-digit reference on 520 seeded closed-form shots (centre hits, straight shots, pure
# rolling starts, the classical model; starts up to 1e8 m from the origin) the error was at most 10 of them, a
# draw that came back; most, under 6 (tests/numerics/test_engine.py, its slow test on 120).  An estimate, not a bound.
CLOSED_ROUNDINGS = 32.0
# Ω at a closed-form slide's end, Ω₀ less what the slide took, is off by a few ulps of Ω₀: where the slide takes
# nearly all of it (k ≪ R: Ω₁/Ω₀ ≈ k²/(R² + k²)) the roll carries that cancellation (k = 0.002 R, δ = 1e-13: the
# rest point 4.4e-11 off with an estimate of 1.4e-14, an audit; `closed_estimate` now weighs it, 4.2e-10).
SPIN_ROUNDINGS = 4.0
# A ball whose slide's travel (`slide_travel`) is more than this many times its distance from the start to rest
# (+ R) slides again, at the tolerance its distance asks (`finish`): a draw shot that came back within 4 cm of its
# start after 1.2 m was 12× the tolerance off.  Measured: 2 of the 163 bench and calibration scenes, 1.5% of 18,844
# general pool shots (bench.timing_states), 3% of 500 fast shots slide again.
RERUN_RATIO = 2.0
# And one whose Ω carries to its rest point more than this many times the travel per relative error of Ω (the roll's
# lever, `roll_lever`, times Ω's scale, which the slide's errors in p and q were measured against, over the travel)
# slides again, at the tolerance divided by the excess (`finish`).  A ball with little inertia (k ≪ R) and a long
# roll has such a lever: on 800 random shots over R 1 mm–1 m, k/R 0.003–0.8, f 0.001–1, g 0.1–30 m/s², tol
# 1e-12–1e-6, the rest point missed tol up to 3.7× where it was 2,400–43,000 (an audit, unwarned: the estimate stayed
# below TOL_WARNING); up to 1,700, at most 0.96× tol.  With the rule, those starting at the origin are within 0.89×
# tol, and all but 2 of the others (an ulp of their coordinates off: README, "What the roll carries").  On the 163
# bench and calibration scenes it is at most 84 (none slides again for it: their results are unchanged); 8 of 6,000
# random pool shots are above 100 (at most 131).
RERUN_SPIN_RATIO = 100.0
SAFETY, MIN_FACTOR, MAX_FACTOR = 0.9, 1 / 3, 6.0  # Hairer's DOP853 (safe, fac1, fac2)
FIRST_STEP = 0.5  # in σ (V × 0.61): the error estimates of the first steps grow or cut it

# Status of a scene (OUT_STATUS).
OK, WORK_LIMIT, NON_FINITE = 0, 1, 2

# The result of one scene: a row of floats, so that one array holds a batch.
(OUT_T_SLIDE, OUT_T_ROLL, OUT_T_PIVOT, OUT_REST_XI, OUT_REST_ETA, OUT_END_XI, OUT_END_ETA, OUT_END_P, OUT_END_Q,
 OUT_MODEL, OUT_ERROR, OUT_STEPS, OUT_REJECTED, OUT_STATUS, OUT_DENSE, OUT_V0, OUT_CA, OUT_SA, OUT_OMEGA0,
 OUT_THETA0, OUT_T_REVERSAL, OUT_END_CA, OUT_END_SA, OUT_TOL, OUT_RUNS) = range(25)
N_OUT = 25
# What each row column is called in an error message.
OUT_NAMES = {OUT_T_SLIDE: "t_slide_end", OUT_T_ROLL: "t_roll_end", OUT_T_PIVOT: "t_pivot_end", OUT_REST_XI: "rest",
             OUT_END_XI: "slide_end", OUT_END_ETA: "slide_end", OUT_END_P: "slide_end", OUT_END_Q: "slide_end",
             OUT_ERROR: "error_estimate"}

# The slide's state in σ, and one step of its dense output: σ₀, h, y₀, the interpolant's 7 rows and the step's h·λ.
T, CA, SA, P, Q, XI, ETA = range(7)
DENSE_STIFFNESS = 2 + N_Y + 7 * N_Y
DENSE_WIDTH = DENSE_STIFFNESS + 1
# A step whose h·λ (Hairer's stiffness measure, `stiffness`) is above DENSE_STIFF is not interpolated: a state
# inside it is integrated to in substeps of h·λ at most SUBSTEP_STIFFNESS (`slide_state_at`).  Near δ = fR the
# steps run at DOP853's stability boundary (h·λ 6.6–13 where the interpolant was 2–18× tol off midway).  The
# bench's dense scenes stay below 0.4 (tested); some shots far from fR have a few steps above 2 (46 of 751 random
# ones with δ ≤ 0.9 fR, an audit), where the substeps cost a few µs a state.
DENSE_STIFF = 2.0
SUBSTEP_STIFFNESS = 1.0
# A bound on a state's work (two stretches: ~20 µs).  An accepted step's real h·λ stays near DOP853's stability
# limit (it would amplify a stiff component by ~(hλ)⁸/8! otherwise); the measure's thousands, found by an audit on
# slides with almost no spin at tol ~1e-13, are rounding in ‖Δf‖/‖Δy‖ (1 substep or 4,736 agree to 1.3e-14).
MAX_SUBSTEPS = 32
N_WORK = 11  # what `slide_numerically` leaves: the state (7), the estimate, accepted and rejected steps, dense rows


def classify(params, state, classical, tol):
    """(model, V₀, cos α₀, sin α₀, Ω₀, θ₀): how the scene slides, from its slip (eq. (2)) and rotation, at the
    tolerance ``tol`` (a shot nearer straight than STRAIGHT_ANGLE and STRAIGHT_PER_TOL · tol takes the straight
    closed form)."""
    R, delta = params[1], params[3]
    vxi, veta, p, q = state[2], state[3], state[4], state[5]
    u, v = slip_velocity(vxi, veta, p, q, R)
    V0 = math.hypot(u, v)
    Omega0 = math.hypot(p, q)
    scale = max(abs(vxi), abs(veta), R * abs(p), R * abs(q), 1e-300)
    ca, sa = (u / V0, v / V0) if V0 > 0 else (1.0, 0.0)
    theta0 = math.atan2(q, p) - math.atan2(v, u)
    theta0 = math.atan2(math.sin(theta0), math.cos(theta0))
    if V0 <= NO_SLIP * scale:
        return NONE, V0, ca, sa, Omega0, theta0
    if classical or delta == 0:
        return CLASSICAL, V0, ca, sa, Omega0, theta0
    straight = max(min(STRAIGHT_ANGLE, STRAIGHT_PER_TOL * tol), STRAIGHT_FLOOR)
    if Omega0 <= NO_SLIP * scale / R or abs(theta0 - math.pi / 2) <= straight:
        return FOLLOW, V0, ca, sa, Omega0, theta0
    if abs(theta0 + math.pi / 2) <= straight:
        return DRAW, V0, ca, sa, Omega0, theta0
    return NUMERICAL, V0, ca, sa, Omega0, theta0


def _rotate(x, y, c, s):
    return x * c - y * s, x * s + y * c


def closed_slide_at(model, tau, V0, Omega0, theta0, t_reversal, params):
    """A closed-form slide in the slip frame at time τ: (V, p, q, ξ, η, ξ', η')."""
    f, R, k, delta, epsilon, g = params[0], params[1], params[2], params[3], params[4], params[5]
    if model == CLASSICAL:
        return classical_at(tau, V0, Omega0, theta0, f, R, k, delta, epsilon, g)
    if model == FOLLOW:
        return follow_at(tau, V0, Omega0, f, R, k, delta, epsilon, g)
    if model == DRAW or tau <= t_reversal:
        return draw_at(tau, V0, Omega0, f, R, k, delta, epsilon, g)
    # DRAW_REVERSED after the reversal: Ω comes back along β = α + π/2 (n°6), the follow law.
    mid = draw_at(t_reversal, V0, Omega0, f, R, k, delta, epsilon, g)
    after = follow_at(tau - t_reversal, mid[0], 0.0, f, R, k, delta, epsilon, g)
    return (after[0], after[1], after[2], mid[3] + after[3], mid[4] + after[4], after[5], after[6])


def _closed_slide(model, V0, Omega0, theta0, params):
    """(model, duration, reversal time) of a closed-form slide."""
    f, R, k, delta, epsilon, g = params[0], params[1], params[2], params[3], params[4], params[5]
    if model == CLASSICAL:
        return model, classical_end(V0, Omega0, theta0, f, R, k, delta, epsilon, g), 0.0
    if model == FOLLOW:
        return model, follow_end(V0, Omega0, f, R, k, delta, epsilon, g)[0], 0.0
    slip_end, spin_end = draw_end(V0, Omega0, f, R, k, delta, epsilon, g)
    if slip_end <= spin_end:
        return DRAW, slip_end, 0.0
    V_mid = draw_at(spin_end, V0, Omega0, f, R, k, delta, epsilon, g)[0]
    return DRAW_REVERSED, spin_end + follow_end(V_mid, 0.0, f, R, k, delta, epsilon, g)[0], spin_end


def unit_rotation(ca, sa, p, q):
    """(cos β, sin β); where Ω = 0, the direction it leaves zero along, β = α + π/2 (n°6)."""
    spin = math.sqrt(p * p + q * q)
    return (p / spin if spin != 0.0 else -sa), (q / spin if spin != 0.0 else ca)  # selects: lanes vectorise


def rates_in_sigma(sigma, y, params):
    """d/dσ of (t, cos α, sin α, p, q, ξ, η), σ = −ln V: V' < −fg(1 − δ/(fR)) < 0 under (9), so σ grows with t."""
    return rates_at(exp(-sigma), y[CA], y[SA], y[P], y[Q],
                    params[0], params[1], params[2], params[3], params[4], params[5])


def rates_at(V, ca, sa, p, q, f, R, k, delta, epsilon, g):
    """`rates_in_sigma` at the slip V (= e^−σ) on scalars: what a lane evaluates (`numerics.lanes`)."""
    norm = 1.0 / math.sqrt(ca * ca + sa * sa)  # the unit vector drifts by the integration's error only
    ca, sa = ca * norm, sa * norm
    cb, sb = unit_rotation(ca, sa, p, q)
    dV, V_dalpha, dp, dq, dxi, deta = slide_rates(V, ca, sa, p, q, cb, sb, f, R, k, delta, epsilon, g)
    per_V = -1.0 / dV
    per_sigma = V * per_V
    dalpha = V_dalpha * per_V
    return (per_sigma, -sa * dalpha, ca * dalpha, per_sigma * dp, per_sigma * dq, per_sigma * dxi, per_sigma * deta)


def _store(K, s, rates):
    for i in range(N_Y):
        K[s, i] = rates[i]


def _stages(K, sigma, y, h, params, ytmp):
    """Stages 1–11 of one DOP853 step (stage 0, the rates at its start, is already in K[0])."""
    stage_1(y, K, h, ytmp)
    _store(K, 1, rates_in_sigma(sigma + C[1] * h, ytmp, params))
    stage_2(y, K, h, ytmp)
    _store(K, 2, rates_in_sigma(sigma + C[2] * h, ytmp, params))
    stage_3(y, K, h, ytmp)
    _store(K, 3, rates_in_sigma(sigma + C[3] * h, ytmp, params))
    stage_4(y, K, h, ytmp)
    _store(K, 4, rates_in_sigma(sigma + C[4] * h, ytmp, params))
    stage_5(y, K, h, ytmp)
    _store(K, 5, rates_in_sigma(sigma + C[5] * h, ytmp, params))
    stage_6(y, K, h, ytmp)
    _store(K, 6, rates_in_sigma(sigma + C[6] * h, ytmp, params))
    stage_7(y, K, h, ytmp)
    _store(K, 7, rates_in_sigma(sigma + C[7] * h, ytmp, params))
    stage_8(y, K, h, ytmp)
    _store(K, 8, rates_in_sigma(sigma + C[8] * h, ytmp, params))
    stage_9(y, K, h, ytmp)
    _store(K, 9, rates_in_sigma(sigma + C[9] * h, ytmp, params))
    stage_10(y, K, h, ytmp)
    _store(K, 10, rates_in_sigma(sigma + C[10] * h, ytmp, params))
    stage_11(y, K, h, ytmp)
    _store(K, 11, rates_in_sigma(sigma + C[11] * h, ytmp, params))


def slide_numerically(V0, ca0, sa0, p0, q0, vxi0, veta0, params, tol, dense, work):
    """The curved slide to V = 0: fills work[0:7] with (t, cos α, sin α, p, q, ξ − ξ₀, η − η₀) at
    V₀·END_FRACTION·tol, work[7] the error estimate carried to the rest point's scale, work[8:11] accepted steps,
    rejected, dense rows.  The centre's displacement from its start is integrated, not its coordinates: far from
    the origin an ulp of the coordinates at every step added up (6 ulps of a start 4.9 km out over 77 steps, 5.2×
    tol 2.9e-10 on a 3.6 mm travel: an audit); `finish` adds the start once.

    ``dense`` (rows of DENSE_WIDTH; zero rows: none kept) receives each accepted step's interpolant.
    Returns a status.  `lanes.slide_lanes` is the same loop on many scenes at once, step for step.
    """
    K = np.empty((N_EXTENDED, N_Y))
    y = np.empty(N_Y)
    err_acc = np.zeros((N_Y, 1))
    base = np.empty((N_Y, 1))
    y[T], y[CA], y[SA], y[P], y[Q], y[XI], y[ETA] = 0.0, ca0, sa0, p0, q0, 0.0, 0.0
    sigma, sigma_end, spin_scale = slide_start(V0, vxi0, veta0, p0, q0, params, tol, base, 0)
    _store(K, 0, rates_in_sigma(sigma, y, params))
    return slide_on(K, y, err_acc, base, sigma, sigma_end, spin_scale, FIRST_STEP, 0, 0, False, 0, params, tol, dense,
                    work)


def slide_on(K, y, err_acc, base, sigma, sigma_end, spin_scale, h, accepted, rejected, just_rejected, steps, params,
             tol, dense, work):
    """`slide_numerically`'s steps from σ with the next step h, after ``steps`` attempts (K[0]: the rates at y;
    err_acc and base: one lane's columns).  A block of lanes hands its last scene to it (`lanes.slide_lanes`)."""
    ynew = np.empty(N_Y)
    ytmp = np.empty(N_Y)
    # The step control is the lanes' (`numerics.lanes`): this scene is lane 0 of (component, lane) views.
    K_lane, y_lane, ynew_lane = K.reshape((N_EXTENDED, N_Y, 1)), y.reshape((N_Y, 1)), ynew.reshape((N_Y, 1))
    rows = 0
    status = WORK_LIMIT
    for _ in range(MAX_STEPS - steps):  # σ_end > σ₀: END_FRACTION·tol < 1
        h = min(h, sigma_end - sigma)
        _stages(K, sigma, y, h, params, ytmp)
        solution(y, K, h, ynew)
        _store(K, N_STAGES, rates_in_sigma(sigma + h, ynew, params))
        norm, spin = step_norm(K_lane, y_lane, ynew_lane, h, base, spin_scale, tol, 0)
        if not (norm == norm) or not math.isfinite(ynew[T]):
            status = NON_FINITE
            break
        if norm <= 1.0:
            accepted += 1
            if rows < dense.shape[0]:
                _dense_row(dense[rows], K, sigma, h, y, ynew, params, ytmp, base)
                rows += 1
            accept(K_lane, y_lane, ynew_lane, err_acc, base, spin, norm * tol, 0)
            sigma = sigma + h if h < sigma_end - sigma else sigma_end
        else:
            rejected += 1
        h *= step_factor(norm, just_rejected)
        just_rejected = norm > 1.0
        if sigma >= sigma_end:
            status = OK
            break
    record_slide(work, status, y_lane, err_acc, params, 0, accepted, rejected, rows)
    return status


def record_slide(work, status, Y, err_acc, params, l, accepted, rejected, rows):
    """Lane l's ended slide into ``work`` (the layout of `slide_numerically`): its step counts and dense rows, and
    when it ended OK, its state at V₀·END_FRACTION·tol and the error estimate (`slide_estimate`)."""
    work[8], work[9], work[10] = accepted, rejected, rows
    if status == OK:
        for i in range(N_Y):
            work[i] = Y[i, l]
        work[7] = slide_estimate(Y, err_acc, params, l)


def slide_start(V0, vxi0, veta0, p0, q0, params, tol, base, l):
    """(σ₀, σ_end, Ω's scale) of a numerical slide from V₀ (the slip's speed) and the centre's velocity, and
    base[:, l], the scale each component's error is measured against (Ω's own where it is larger than a floor:
    `step_norm`)."""
    f, R, g = params[0], params[1], params[5]
    t_scale = V0 / (f * g)
    spin_scale = math.sqrt(p0 * p0 + q0 * q0) + V0 / R
    base[T, l], base[CA, l], base[SA, l], base[P, l], base[Q, l] = t_scale, 1.0, 1.0, spin_scale, spin_scale
    distance = slide_travel(V0, vxi0, veta0, params)
    base[XI, l], base[ETA, l] = distance, distance
    return -math.log(V0), -math.log(V0 * END_FRACTION * tol), spin_scale


def slide_travel(V0, vxi0, veta0, params):
    """The scale of ξ's and η's errors in a numerical slide: the centre's travel while it slides, plus R, as the
    rest point's error is measured (against its distance from the start plus R, `finish`).  The slide lasts
    about t₁ = V₀/(fg(1 + R²/k²)) (n°3, exact without the rolling couple); the centre starts at |v₀| and
    friction changes its speed by fg at most.  The slip's own distance V₀²/(fg), the scale before, was 40× the
    travel of a ball with much spin (its states between steps 4.3× the tolerance off), and it vanished with the
    slip while the centre rolls on (a ball all but rolling took 20,000 steps)."""
    f, R, k, g = params[0], params[1], params[2], params[5]
    t1 = V0 / (f * g * (1.0 + (R / k) * (R / k)))
    return (math.sqrt(vxi0 * vxi0 + veta0 * veta0) + 0.5 * f * g * t1) * t1 + R


def step_norm(K, Y, Y_new, h, base, spin_scale, tol, l):
    """(DOP853's error of lane l's step from Y to Y_new over tol, ≤ 1 when accepted, and no more than Ω's turn
    allows: `turn_norm`; Ω's scale for it).  Error against each component's size: Ω against itself where it is
    small (its direction, and so the rolling couple's, turns fast near zero), down to a floor.  Square roots, not
    hypot (a library call, and no overflow to guard against: every scale is below 1e100, `validation.SCALE_LIMIT`)."""
    spin = min(math.sqrt(Y[P, l] * Y[P, l] + Y[Q, l] * Y[Q, l]),
               math.sqrt(Y_new[P, l] * Y_new[P, l] + Y_new[Q, l] * Y_new[Q, l]))
    spin = max(spin, SPIN_FLOOR * spin_scale)
    e5, e3 = 0.0, 0.0
    for i in range(N_Y):
        sc = spin if i == P or i == Q else base[i, l]
        a5, a3 = error_terms(K, i, l)
        x5, x3 = a5 / sc, a3 / sc
        e5 += x5 * x5  # `lanes._lane_norms` does the same, in the same order
        e3 += x3 * x3
    denom = e5 + 0.01 * e3
    norm = abs(h) * e5 / math.sqrt(denom * N_Y) / tol if denom > 0 else 0.0
    return max(norm, turn_norm(Y[P, l], Y[Q, l], Y_new[P, l], Y_new[Q, l], SPIN_FLOOR * spin_scale)), spin


def turn_norm(p, q, p_new, q_new, floor):
    """How far Ω's direction turns in a step from (p, q) to (p_new, q_new), as a norm: ≤ 1 when by at most
    MAX_TURN.  Through a near miss β turns by π in a short while, and the rates (through δ) all but jump: DOP853's
    estimate does not see a jump inside a step (a step across the pass was accepted at 0.15 of its tolerance, and
    the rest point came out 14× the tolerance off).  ((1 − cos turn)/(1 − cos MAX_TURN))⁴ grows as h⁸, as the
    error's norm does, so that `step_factor` shrinks the step in proportion.  Not followed below the floor."""
    ends = math.sqrt(p * p + q * q) * math.sqrt(p_new * p_new + q_new * q_new)  # each below 1e100: no overflow
    if not ends > floor * floor:
        return 0.0
    x = (1.0 - (p * p_new + q * q_new) / ends) / (1.0 - COS_MAX_TURN)
    x = x * x
    return x * x


def accept(K, Y, Y_new, err_acc, base, spin, error, l):
    """Lane l takes its step: Y = Y_new, its rates the next step's first stage, its error (× each scale) summed."""
    for i in range(N_Y):
        sc = spin if i == P or i == Q else base[i, l]
        err_acc[i, l] += error * sc
        Y[i, l] = Y_new[i, l]
        K[0, i, l] = K[N_STAGES, i, l]


def step_factor(norm, just_rejected):
    """The next step over this one (Hairer's DOP853; norm^(−1/8) as three square roots, not a library pow): no
    growth right after a rejection (it would be rejected again)."""
    if norm > 1.0:
        return max(MIN_FACTOR, SAFETY / math.sqrt(math.sqrt(math.sqrt(norm))))
    factor = MAX_FACTOR if norm == 0.0 else min(MAX_FACTOR,
                                                max(MIN_FACTOR, SAFETY / math.sqrt(math.sqrt(math.sqrt(norm)))))
    return min(factor, 1.0) if just_rejected else factor


def roll_lever(p, q, params):
    """How far the rest point moves per unit of Ω at the end of sliding: the distance rolled, R Ω² (R² + k²)/(2δg)
    (n°7), moves by R Ω (R² + k²)/(δg) per unit of Ω."""
    R, k, delta, g = params[1], params[2], params[3], params[5]
    return R * math.hypot(p, q) * (R * R + k * k) / (delta * g)


def slide_estimate(Y, err_acc, params, l):
    """The error estimate at the rest point: the centre's own error, and Ω's carried through the rolling that
    follows (`roll_lever`)."""
    lever = roll_lever(Y[P, l], Y[Q, l], params)
    return ESTIMATE_MARGIN * (math.hypot(err_acc[XI, l], err_acc[ETA, l])
                              + lever * math.hypot(err_acc[P, l], err_acc[Q, l]))


def stiffness(K, h, ynew, ytmp, base):
    """h·λ of the step just taken, Hairer's measure of stiffness (Hairer & Wanner, Solving ODEs II, IV.2; his
    DOP853 tests it): h ‖f(y_new) − f(stage 12)‖ / ‖y_new − stage 12‖ over the direction of slip and Ω, each
    against its error scale.  DOP853 is stable up to about 6 along the negative axis."""
    num, den = 0.0, 0.0
    for i in (CA, SA, P, Q):
        dk, dy = (K[N_STAGES, i] - K[N_STAGES - 1, i]) / base[i, 0], (ynew[i] - ytmp[i]) / base[i, 0]
        num += dk * dk
        den += dy * dy
    return h * math.sqrt(num / den) if den > 0 else 0.0


def _dense_row(row, K, sigma, h, y, ynew, params, ytmp, base):
    """DOP853's 7th-order interpolant of the step just accepted (its three extra stages), and its h·λ (while
    ytmp still holds the last stage), into ``row``."""
    row[DENSE_STIFFNESS] = stiffness(K, h, ynew, ytmp, base)
    stage_13(y, K, h, ytmp)
    _store(K, 13, rates_in_sigma(sigma + C[13] * h, ytmp, params))
    stage_14(y, K, h, ytmp)
    _store(K, 14, rates_in_sigma(sigma + C[14] * h, ytmp, params))
    stage_15(y, K, h, ytmp)
    _store(K, 15, rates_in_sigma(sigma + C[15] * h, ytmp, params))
    row[0], row[1] = sigma, h
    for i in range(N_Y):
        row[2 + i] = y[i]
        dy = ynew[i] - y[i]
        F0, F1, F2 = dy, h * K[0, i] - dy, 2.0 * dy - h * (K[N_STAGES, i] + K[0, i])
        base = 2 + N_Y + 7 * i
        row[base], row[base + 1], row[base + 2] = F0, F1, F2
        row[base + 3], row[base + 4] = h * dense_0(K, i), h * dense_1(K, i)
        row[base + 5], row[base + 6] = h * dense_2(K, i), h * dense_3(K, i)


def dense_value(row, x, i):
    """Component i of the interpolant of one step at x ∈ [0, 1] (SciPy's Horner form of DOP853's)."""
    return dense_value_slope(row, x, i)[0]


def dense_value_slope(row, x, i):
    """(value, d value/dx) of component i of the interpolant at x: the Horner loop differentiated along."""
    base = 2 + N_Y + 7 * i
    value, slope = 0.0, 0.0
    for m in range(6, -1, -1):
        value += row[base + m]
        if (6 - m) % 2 == 0:
            slope, value = slope * x + value, value * x
        else:
            slope, value = slope * (1.0 - x) - value, value * (1.0 - x)
    return value + row[2 + i], slope


def first_order_end(y, sigma, params):
    """The last stretch, from V = e^−σ to 0, to first order in t: (dt, p, q, ξ, η)."""
    f, R, k, delta, epsilon, g = params[0], params[1], params[2], params[3], params[4], params[5]
    V = math.exp(-sigma)
    norm = math.hypot(y[CA], y[SA])
    ca, sa = y[CA] / norm, y[SA] / norm
    cb, sb = unit_rotation(ca, sa, y[P], y[Q])
    dV, _, dp, dq, dxi, deta = slide_rates(V, ca, sa, y[P], y[Q], cb, sb, f, R, k, delta, epsilon, g)
    dt = V / -dV
    return dt, y[P] + dp * dt, y[Q] + dq * dt, y[XI] + dxi * dt, y[ETA] + deta * dt


def roll(t0, xi, eta, p, q, params):
    """n°7 from the end of sliding: (t_roll_end, rest ξ, rest η); ∞ and NaN when δ = 0 and Ω ≠ 0."""
    f, R, k, delta, epsilon, g = params[0], params[1], params[2], params[3], params[4], params[5]
    spin = math.hypot(p, q)
    if spin == 0.0:
        return t0, xi, eta
    if delta == 0.0:
        return math.inf, math.nan, math.nan
    beta = math.atan2(q, p)
    duration = rolling_end(spin, beta, f, R, k, delta, epsilon, g)
    local = rolling_at(duration, spin, beta, f, R, k, delta, epsilon, g)
    return t0 + duration, xi + local[3], eta + local[4]


def pivot_duration(r0, params):
    """Eq. (5): when r reaches 0 (∞ when ε = 0 and r ≠ 0)."""
    f, R, k, delta, epsilon, g = params[0], params[1], params[2], params[3], params[4], params[5]
    if r0 == 0.0:
        return 0.0
    if epsilon == 0.0:
        return math.inf
    return pivot_end(abs(r0), f, R, k, delta, epsilon, g)


def r_at(t, r0, params):
    """r at time t (eq. (5), odd in r; exactly 0 from its end on)."""
    f, R, k, delta, epsilon, g = params[0], params[1], params[2], params[3], params[4], params[5]
    if r0 == 0.0 or t >= pivot_duration(r0, params):
        return 0.0 if r0 == 0.0 or epsilon > 0.0 else r0
    sign = 1.0 if r0 > 0 else -1.0
    return sign * pivot_at(t, abs(r0), f, R, k, delta, epsilon, g)


def solve(params, state, classical, tol, out, dense):
    """Fill ``out`` (N_OUT floats) with the motion of one scene; ``dense`` keeps the numerical slide's steps."""
    if begin(params, state, classical, tol, out):
        work = np.zeros(N_WORK)
        while finish(params, state, slide(params, state, out, dense, work), work, out):
            pass  # once more, at the tolerance the ball's travel asks (`finish`)


def slide(params, state, out, dense, work):
    """`slide_numerically` from the row `begin` filled (its status; ``work`` receives the rest)."""
    return slide_numerically(out[OUT_V0], out[OUT_CA], out[OUT_SA], state[4], state[5], state[2],
                             state[3], params, out[OUT_TOL], dense, work)


def begin(params, state, classical, tol, out):
    """Classify the scene and, unless its slide is to be integrated, fill ``out`` with its whole motion.
    True when the slide is numerical: then `finish` completes ``out`` from the integrator's ``work``."""
    for i in range(N_OUT):
        out[i] = math.nan
    xi0, eta0 = state[0], state[1]
    model, V0, ca, sa, Omega0, theta0 = classify(params, state, classical, tol)
    out[OUT_V0], out[OUT_CA], out[OUT_SA], out[OUT_OMEGA0], out[OUT_THETA0] = V0, ca, sa, Omega0, theta0
    out[OUT_T_REVERSAL], out[OUT_TOL], out[OUT_DENSE], out[OUT_RUNS] = 0.0, tol, 0.0, 0.0
    out[OUT_STEPS], out[OUT_REJECTED], out[OUT_ERROR], out[OUT_STATUS] = 0.0, 0.0, 0.0, 0.0
    out[OUT_END_CA], out[OUT_END_SA] = ca, sa
    if model == NUMERICAL:
        out[OUT_TOL] = tol / TOL_SAFETY
        return True
    t1, xi1, eta1, p1, q1 = 0.0, xi0, eta0, state[4], state[5]
    if model != NONE:
        model, t1, t_reversal = _closed_slide(model, V0, Omega0, theta0, params)
        out[OUT_T_REVERSAL] = t_reversal
        local = closed_slide_at(model, t1, V0, Omega0, theta0, t_reversal, params)
        dx, dy = _rotate(local[3], local[4], ca, sa)
        xi1, eta1 = xi0 + dx, eta0 + dy
        p1, q1 = _rotate(local[1], local[2], ca, sa)
    _after_slide(params, state, model, t1, xi1, eta1, p1, q1, out)
    return False


def finish(params, state, status, work, out):
    """Complete ``out`` after a numerical slide (`slide_numerically`'s ``work`` and status).  True when the slide
    is to be run again, at the tolerance in ``out`` (once at most): the ball came to rest much nearer its start
    than the slide's travel, the scale its steps were measured against (`slide_travel`), and the rest point's
    error is measured against its distance from the start; or Ω's errors, measured against Ω's scale, move the
    rest point by much more than that distance (RERUN_SPIN_RATIO)."""
    out[OUT_RUNS] += 1
    out[OUT_STEPS], out[OUT_REJECTED], out[OUT_DENSE] = out[OUT_STEPS] + work[8], out[OUT_REJECTED] + work[9], work[10]
    if status != OK:
        out[OUT_STATUS] = status
        return False
    dt, p1, q1, dxi, deta = first_order_end(work[:7], -math.log(out[OUT_V0] * END_FRACTION * out[OUT_TOL]), params)
    t1, xi1, eta1 = work[T] + dt, state[0] + dxi, state[1] + deta  # the start added once (`slide_numerically`)
    _, rest_xi, rest_eta = roll(t1, xi1, eta1, p1, q1, params)  # δ > 0 here: the ball rests
    travel = math.hypot(rest_xi - state[0], rest_eta - state[1]) + params[1]
    scale = slide_travel(out[OUT_V0], state[2], state[3], params)  # what ξ's and η's errors were measured against
    ratio = scale / travel
    spin_scale = math.hypot(state[4], state[5]) + out[OUT_V0] / params[1]  # `slide_start`'s
    tighter = max(ratio if ratio > RERUN_RATIO else 1.0,
                  roll_lever(p1, q1, params) * spin_scale / travel / RERUN_SPIN_RATIO)
    if tighter > 1.0 and out[OUT_RUNS] == 1:
        out[OUT_TOL] /= tighter
        return True
    # Rounding, which no local estimate sees: each accepted step adds to the displacement an error of about an ulp
    # of its size, and to Ω one that the roll carries (the lever of `slide_estimate`, at most twice the distance
    # rolled per relative error); then the start plus the slide plus the roll are rounded as a closed form's are
    # (`closed_estimate`).  It matters only where the tolerance nears float64's (a rerun at 1e-17, a start 10 km
    # from the origin: the estimate was below the error there).
    size = scale + 2.0 * math.hypot(rest_xi - xi1, rest_eta - eta1)
    out[OUT_ERROR] = ((work[7] + ESTIMATE_MARGIN * ROUNDING * work[8] * size) / travel  # relative to the travel
                      + closed_estimate(state, out[OUT_V0], xi1, eta1, rest_xi, rest_eta, params))
    spin_end = math.hypot(p1, q1)
    # The slip's final direction is β − π/2 (n°8), not the slowly converging α itself.
    if spin_end > 0:
        out[OUT_END_CA], out[OUT_END_SA] = q1 / spin_end, -p1 / spin_end
    _after_slide(params, state, NUMERICAL, t1, xi1, eta1, p1, q1, out)
    return False


def _after_slide(params, state, model, t1, xi1, eta1, p1, q1, out):
    """The slide's end (t1, ξ, η, p, q), the rolling and the pivot that follow, and the check of the whole row."""
    out[OUT_MODEL] = model
    out[OUT_T_SLIDE], out[OUT_END_XI], out[OUT_END_ETA], out[OUT_END_P], out[OUT_END_Q] = t1, xi1, eta1, p1, q1
    out[OUT_T_ROLL], out[OUT_REST_XI], out[OUT_REST_ETA] = roll(t1, xi1, eta1, p1, q1, params)
    out[OUT_T_PIVOT] = pivot_duration(state[6], params)
    if model != NUMERICAL and math.isfinite(out[OUT_REST_XI]) and math.isfinite(out[OUT_REST_ETA]):
        spin_end = math.hypot(p1, q1)
        lever = out[OUT_OMEGA0] / spin_end if spin_end > 0.0 else 1.0  # (no roll without spin: no lever to weigh)
        out[OUT_ERROR] = closed_estimate(state, out[OUT_V0], xi1, eta1, out[OUT_REST_XI], out[OUT_REST_ETA], params,
                                         max(lever, 1.0))
    if out[OUT_STATUS] == OK and first_non_finite(out) >= 0:
        out[OUT_STATUS] = NON_FINITE


def closed_estimate(state, V0, xi1, eta1, rest_xi, rest_eta, params, spin_lever=1.0):
    """The rest point's relative error when no step was integrated (a closed form, or no slide; and a numerical
    slide's share once its steps are counted, `finish`): its rounding, CLOSED_ROUNDINGS ulps of the coordinates'
    size, relative to the travel.  The size: the start's, the slide's path (`slide_travel`: a draw that comes
    back has slid further than its rest is from its start) and twice the roll's.  And the roll's share of the
    slide's cancellation: Ω at the end of sliding is Ω₀ less what the slide took, so off by SPIN_ROUNDINGS ulps of
    Ω₀, a relative error ``spin_lever`` = Ω₀/Ω₁ times larger, which the roll (∝ Ω₁²) doubles."""
    rolled = math.hypot(rest_xi - xi1, rest_eta - eta1)
    travel = math.hypot(rest_xi - state[0], rest_eta - state[1]) + params[1]
    size = abs(state[0]) + abs(state[1]) + slide_travel(V0, state[2], state[3], params) + 2.0 * rolled
    return ROUNDING * (CLOSED_ROUNDINGS * size + 2.0 * SPIN_ROUNDINGS * spin_lever * rolled) / travel


def first_non_finite(out):
    """The first quantity of a solved row that is not what it must be (-1: none): finite, or ∞ for a time
    that never comes (the end of rolling when δ = 0, of the pivot when ε = 0), the rest point then NaN."""
    for i in (OUT_T_SLIDE, OUT_END_XI, OUT_END_ETA, OUT_END_P, OUT_END_Q):
        if not math.isfinite(out[i]):
            return i
    for i in (OUT_T_ROLL, OUT_T_PIVOT):
        if out[i] != out[i] or out[i] == -math.inf:
            return i
    if math.isfinite(out[OUT_T_ROLL]) and not (math.isfinite(out[OUT_REST_XI]) and math.isfinite(out[OUT_REST_ETA])):
        return OUT_REST_XI
    if not math.isfinite(out[OUT_ERROR]):  # last: it is computed from the others
        return OUT_ERROR
    return -1


# The scales of a motion bounded before any work (`motion_scales`), its columns in this order; `scene.unrepresentable`
# names them (`scene.SCALE_NAMES`) and blames a field for each (`scene.blamed_field`).
SPEED, SPIN, SLIDE_TIME, ROLL_TIME, PIVOT_TIME, DURATION, DISTANCE, DECELERATION, INVERSE_SPEED = range(9)
SCALES = INVERSE_SPEED + 1  # the columns named above


def motion_scales(params, states, horizon, out):
    """Per row, upper bounds in order of magnitude of its motion's scales (no work done), into ``out`` (n, SCALES):
    the speed |ξ'| + |η'| + R(|p| + |q|) (bounds the slip V₀ and RΩ₀), the spin |r|, the slide's duration
    V₀/(fg) (V' < −fg, n°8), pure rolling's Ω(R² + k²)/(δg) (n°7, Ω growing while sliding by at most
    R V₀/k²), the pivot's k²|r|/(εg) (eq. (5)), the whole duration (with ``horizon``, the last time asked),
    a distance (travelled until rest, or until ``horizon`` when δ = 0), the slide's deceleration g(f(1 + R²/k²) + δR/k²) (eqs. (4), (5): with f = R = g = 1e99 its
    products overflowed in the formulas and a wrong motion came out finite), and 1/speed (0 at rest): a speed
    near 1e-160, whose square is not a normal float64, left valid slides at the bound of MAX_STEPS.  Overflow
    gives ∞ and 0·∞ NaN, never an exception: the caller refuses what is not below its limit.  ``params``: (n, 6)
    rows (f, R, k, δ, ε, g); ``states``: (n, 7), finite."""
    for n in range(states.shape[0]):
        f, R, k, delta, epsilon, g = params[n, 0], params[n, 1], params[n, 2], params[n, 3], params[n, 4], params[n, 5]
        xi, eta, vxi, veta = abs(states[n, 0]), abs(states[n, 1]), abs(states[n, 2]), abs(states[n, 3])
        p, q, r = abs(states[n, 4]), abs(states[n, 5]), abs(states[n, 6])
        speed = vxi + veta + R * (p + q)
        spin = speed / R * (1 + (R / k) * (R / k))
        t_slide = speed / (f * g) if speed > 0 else 0.0
        t_roll = spin * (R * R + k * k) / (delta * g) if spin > 0 and delta > 0 else 0.0
        t_pivot = r * k * k / (epsilon * g) if r > 0 and epsilon > 0 else 0.0
        duration = t_slide + t_roll + horizon
        # The centre moves until rest: with δ > 0 the times asked after it add no distance (--at 1e99 on a ball at
        # rest from 12 s was refused for a distance of 1e100, an audit); with δ = 0 it rolls for ever.
        moving = t_slide + t_roll if delta > 0 else duration
        out[n, SPEED], out[n, SPIN], out[n, SLIDE_TIME], out[n, ROLL_TIME] = speed, r, t_slide, t_roll
        out[n, PIVOT_TIME], out[n, DURATION] = t_pivot, duration
        out[n, DISTANCE] = xi + eta + (speed + R * spin) * moving
        out[n, DECELERATION] = g * (f * (1 + (R / k) * (R / k)) + delta * (R / k) / k)
        out[n, INVERSE_SPEED] = 1.0 / speed if speed > 0 else 0.0


def all_within(params, states, limit):
    """True when every row's state is finite and every scale of its motion (`motion_scales`, no times asked)
    is below ``limit``: a batch's common case, decided in one pass (`batch.bad_rows`, which otherwise names
    each bad row and why)."""
    scales = np.empty((1, SCALES))
    for n in range(states.shape[0]):
        for c in range(states.shape[1]):
            if not math.isfinite(states[n, c]):
                return False
        motion_scales(params[n : n + 1], states[n : n + 1], 0.0, scales)
        for c in range(SCALES):
            if not scales[0, c] < limit:  # NaN too
                return False
    return True


def slide_state_at(t, dense, out, params, refined, xi0, eta0):
    """(ξ, η, ξ', η', p, q) at time t inside a numerical slide from (ξ₀, η₀), from its dense output (of the
    displacement, `slide_numerically`; t between two nodes: the step's σ found by Newton on the interpolated t,
    which is monotone).  ``refined``: `_node_after_stiff`'s keep (no rows: none kept)."""
    rows = dense.shape[0]
    lo, hi = 0, rows - 1
    while lo < hi:  # the last step whose start is at or before t
        mid = (lo + hi + 1) // 2
        if dense[mid, 2 + T] <= t:
            lo = mid
        else:
            hi = mid - 1
    row = dense[lo]
    t_step_end = dense_value(row, 1.0, T)
    if t >= t_step_end and lo == rows - 1:
        return _end_stretch_at(t, row, out, params, xi0, eta0)
    x = (t - row[2 + T]) / (t_step_end - row[2 + T]) if t_step_end > row[2 + T] else 0.0
    for _ in range(20):  # Newton on the interpolated t (smooth, increasing): a few iterations to rounding
        value, slope = dense_value_slope(row, x, T)
        step = (value - t) / slope if slope > 0 else 0.0
        x = min(1.0, max(0.0, x - step))
        if abs(step) <= 1e-15:
            break
    # A stiff step's interpolant is not trusted, nor a node a stiff step ended at (its error along the stiff
    # direction is not damped: up to 1.24 tol, an audit found); substeps are, from the node before (`_substeps`).
    after_stiff = lo > 0 and dense[lo - 1, DENSE_STIFFNESS] > DENSE_STIFF
    if x < 1.0 and (after_stiff or (x > 0.0 and row[DENSE_STIFFNESS] > DENSE_STIFF)):
        y = np.empty(N_Y)
        if after_stiff:
            sigma = _node_after_stiff(y, dense, lo, params, refined)
        else:
            for i in range(N_Y):
                y[i] = row[2 + i]
            sigma = row[0]
        if x > 0.0:
            sigma = _substeps(y, sigma, x * row[1], x * row[DENSE_STIFFNESS], params)
        rates = rates_in_sigma(sigma, y, params)
        dsigma = (t - y[T]) / rates[T]  # from the interpolated time to t (a rounding-sized gap): first order
        return _state_from(sigma + dsigma, y[CA] + dsigma * rates[CA], y[SA] + dsigma * rates[SA],
                           y[P] + dsigma * rates[P], y[Q] + dsigma * rates[Q], xi0 + (y[XI] + dsigma * rates[XI]),
                           eta0 + (y[ETA] + dsigma * rates[ETA]), params)
    return _state_from_row(row, x, params, xi0, eta0)


def _node_after_stiff(y, dense, lo, params, refined):
    """y (in place) at node ``lo``, integrated to across the whole stiff step before it in substeps from the node
    before that (the true flow damps that node's error along the stiff direction); returns its σ.  Kept in row
    ``lo`` of ``refined`` (σ, then y; NaN: not yet) when it has that row: the next state in the same step starts
    from it, the same bits (a state midway in a stiff step after another cost twice the substeps)."""
    if lo < refined.shape[0] and not math.isnan(refined[lo, 0]):
        for i in range(N_Y):
            y[i] = refined[lo, 1 + i]
        return refined[lo, 0]
    first = dense[lo - 1]
    for i in range(N_Y):
        y[i] = first[2 + i]
    sigma = _substeps(y, first[0], first[1], first[DENSE_STIFFNESS], params)
    if lo < refined.shape[0]:
        for i in range(N_Y):
            refined[lo, 1 + i] = y[i]
        refined[lo, 0] = sigma
    return sigma


def _substeps(y, sigma, length, stiffness, params):
    """y (in place) from σ to σ + length, the stretch's h·λ ``stiffness``, by DOP853 steps of equal length whose
    h·λ is at most SUBSTEP_STIFFNESS (well inside the stability region, ~6), at most MAX_SUBSTEPS of them; returns
    the σ reached.  Each has 1/m of the step's length, so at most its error over m⁸."""
    m = max(1, math.ceil(min(stiffness / SUBSTEP_STIFFNESS, MAX_SUBSTEPS)))  # h·λ may be ∞ (a vanishing y_new − stage)
    K = np.empty((N_EXTENDED, N_Y))
    ynew, ytmp = np.empty(N_Y), np.empty(N_Y)
    h = length / m
    for _ in range(m):
        _store(K, 0, rates_in_sigma(sigma, y, params))
        _stages(K, sigma, y, h, params, ytmp)
        solution(y, K, h, ynew)
        for i in range(N_Y):
            y[i] = ynew[i]
        sigma += h
    return sigma


def _state_from_row(row, x, params, xi0, eta0):
    return _state_from(row[0] + x * row[1], dense_value(row, x, CA), dense_value(row, x, SA), dense_value(row, x, P),
                       dense_value(row, x, Q), xi0 + dense_value(row, x, XI), eta0 + dense_value(row, x, ETA), params)


def _state_from(sigma, ca, sa, p, q, xi, eta, params):
    """(ξ, η, ξ', η', p, q) from the slide's variables at σ (the direction of slip renormalised)."""
    V = math.exp(-sigma)
    norm = math.hypot(ca, sa)
    ca, sa = ca / norm, sa / norm
    vxi, veta = centre_velocity(V, ca, sa, p, q, params[1])
    return xi, eta, vxi, veta, p, q


def _end_stretch_at(t, last_row, out, params, xi0, eta0):
    """Between the last node and the end of sliding: the first-order stretch, linear in t."""
    xi_a, eta_a, vxi_a, veta_a, p_a, q_a = _state_from_row(last_row, 1.0, params, xi0, eta0)
    vxi_b, veta_b = centre_velocity(0.0, 1.0, 0.0, out[OUT_END_P], out[OUT_END_Q], params[1])  # V = 0
    t_a, t_b = dense_value(last_row, 1.0, T), out[OUT_T_SLIDE]
    w = 1.0 if t_b <= t_a else min(1.0, (t - t_a) / (t_b - t_a))
    return (
        xi_a + w * (out[OUT_END_XI] - xi_a), eta_a + w * (out[OUT_END_ETA] - eta_a),
        vxi_a + w * (vxi_b - vxi_a), veta_a + w * (veta_b - veta_a),
        p_a + w * (out[OUT_END_P] - p_a), q_a + w * (out[OUT_END_Q] - q_a),
    )


def state_at(t, params, state, out, dense, refined):
    """(phase, ξ, η, ξ', η', p, q, r) at time t ≥ 0 of a solved scene; phase 0 sliding, 1 rolling, 2 rest
    (``refined``: as `slide_state_at`'s)."""
    r = r_at(t, state[6], params)
    model = int(out[OUT_MODEL])
    spin = math.hypot(out[OUT_END_P], out[OUT_END_Q])
    if t == 0.0 and (model != NONE or spin > 0):  # the start itself, as given, sliding or in pure rolling (the
        # round trip through the polar variables, or through Ω and β, moved it by an ulp)
        return (0 if model != NONE else 1), state[0], state[1], state[2], state[3], state[4], state[5], r
    if model != NONE and t <= out[OUT_T_SLIDE]:
        if model == NUMERICAL:
            xi, eta, vxi, veta, p, q = slide_state_at(t, dense, out, params, refined, state[0], state[1])
            return 0, xi, eta, vxi, veta, p, q, r
        local = closed_slide_at(model, t, out[OUT_V0], out[OUT_OMEGA0], out[OUT_THETA0], out[OUT_T_REVERSAL], params)
        ca, sa = out[OUT_CA], out[OUT_SA]
        dx, dy = _rotate(local[3], local[4], ca, sa)
        vxi, veta = _rotate(local[5], local[6], ca, sa)
        p, q = _rotate(local[1], local[2], ca, sa)
        return 0, state[0] + dx, state[1] + dy, vxi, veta, p, q, r
    if spin > 0 and t <= out[OUT_T_ROLL]:
        f, R, k, delta, epsilon, g = params[0], params[1], params[2], params[3], params[4], params[5]
        beta = math.atan2(out[OUT_END_Q], out[OUT_END_P])
        local = rolling_at(t - out[OUT_T_SLIDE], spin, beta, f, R, k, delta, epsilon, g)
        return 1, out[OUT_END_XI] + local[3], out[OUT_END_ETA] + local[4], local[5], local[6], local[1], local[2], r
    return 2, out[OUT_REST_XI], out[OUT_REST_ETA], 0.0, 0.0, 0.0, 0.0, r


def states_at(ts, params, state, out, dense, result):
    """`state_at` for every time of ``ts`` into the rows of ``result`` (phase, ξ, η, ξ', η', p, q, r); the nodes
    after stiff steps, once integrated to, kept for the other times of this call (`_node_after_stiff`)."""
    refined = np.full((dense.shape[0], N_Y + 1), np.nan)
    for n in range(ts.shape[0]):
        phase, xi, eta, vxi, veta, p, q, r = state_at(ts[n], params, state, out, dense, refined)
        result[n, 0], result[n, 1], result[n, 2], result[n, 3] = phase, xi, eta, vxi
        result[n, 4], result[n, 5], result[n, 6], result[n, 7] = veta, p, q, r
