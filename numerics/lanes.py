"""Many curved slides at once, in lanes: `slide_numerically`'s loop run on a block of scenes side by side.

A batch (`solve_many`) first settles every scene it can in closed form
(`engine.begin`), then integrates the remaining slides in lanes: each lane
holds one scene, and every stage of DOP853 is computed for all lanes in one
loop over them, which the compiler turns into vector instructions (8 lanes
per AVX-512 instruction; one scene's stage is a chain of dependent divisions
and square roots that leaves the core mostly idle: in a long batch a scene
costs about a third of its time alone).  Each lane keeps its own step size and accepts or rejects its own
steps with the single-scene loop's own functions (`engine.step_norm`,
`accept`, `step_factor`), so a scene takes exactly the steps it takes alone;
a finished lane takes the next scene.  A block of lanes costs the same however
few of its lanes are busy, so when no scene waits and at most HANDOFF lanes
are busy, each goes on alone from where it is (`engine.slide_on`, the
single-scene loop): the long slides at a batch's end no longer keep a whole
block running.  Measured: `appell bench`.

The compiled engine uses NumPy's error model (`numerics.compiled`: a division
by zero gives ∞ or NaN, caught by the status checks) because Python's — a
test and a raise at every division — keeps the loops over lanes from being
vectorised.
"""

import math

import numpy as np

from numerics.dop853_steps import (  # generated from the tables: bare names, as the engine's
    lanes_solution, lanes_stage_1, lanes_stage_2, lanes_stage_3, lanes_stage_4, lanes_stage_5, lanes_stage_6,
    lanes_stage_7, lanes_stage_8, lanes_stage_9, lanes_stage_10, lanes_stage_11,
)
from numerics.dop853_tables import C, N_EXTENDED, N_STAGES
from numerics.vector_exp import exp
from numerics.engine import (
    DENSE_WIDTH, FIRST_STEP, MAX_STEPS, N_WORK, N_Y, NON_FINITE, OK, OUT_CA, OUT_SA, OUT_TOL, OUT_V0, T, WORK_LIMIT,
    accept, begin, finish, rates_at, rates_in_sigma, record_slide, slide, slide_on, slide_start, step_factor, step_norm,
)

# Scenes side by side: measured fastest from 32 to 64.  The compiler's vector loops take 32 lanes at a time
# (8 per instruction, 4 instructions interleaved) and do the rest one by one, slower than the single-scene loop:
# a block is always LANES wide, idle lanes computing on (a batch of 10 curved slides runs 22 idle lanes).
LANES = 32
# Busy lanes below which a block costs more than its scenes alone (a block step ~ 6 single-scene steps on this
# machine; 4 and 8 measured alike): with no scene waiting, they go on one by one, as do batches this small.
HANDOFF = 6


def solve_many(params, states, classical, tol, out):
    """`engine.solve` on every row (params and states one row per scene), the numerical slides in lanes (more
    than HANDOFF of them) or one by one; no dense output.  `batch.simulate_many` runs it on chunks in threads (compiled, it releases the GIL)."""
    n = states.shape[0]
    pending = np.empty(n, np.int64)
    m = 0
    for i in range(n):
        if begin(params[i], states[i], classical[i], tol, out[i]):
            pending[m] = i
            m += 1
    if m == 0:
        return
    work = np.zeros((m, N_WORK))
    status = np.zeros(m, np.int64)
    if m > HANDOFF:
        slide_lanes(pending[:m], params, states, out, work, status)
    else:  # a few: one by one is faster (the same steps, the same bits)
        for j in range(m):
            i = pending[j]
            status[j] = slide(params[i], states[i], out[i], np.empty((0, DENSE_WIDTH)), work[j])
    for j in range(m):
        i = pending[j]
        finish(params[i], states[i], status[j], work[j], out[i])


def slide_lanes(scenes, params, states, out, work, status):
    """`engine.slide_numerically` (without dense output) for the rows ``scenes`` of a batch, whose ``out`` rows
    `begin` filled; row j of ``work`` and ``status`` receive scene ``scenes[j]``'s."""
    m = scenes.shape[0]
    width = LANES
    Y, Y_new, Y_stage = np.zeros((N_Y, width)), np.zeros((N_Y, width)), np.zeros((N_Y, width))
    K = np.zeros((N_EXTENDED, N_Y, width))
    PAR = np.ones((6, width))
    base, err_acc = np.ones((N_Y, width)), np.zeros((N_Y, width))
    sigma, sigma_end, H, spin_scale, tol = (np.zeros(width), np.zeros(width), np.zeros(width), np.ones(width),
                                            np.ones(width))
    norm, spin = np.zeros(width), np.zeros(width)  # each lane's step error over its tolerance, Ω's scale
    job = np.full(width, -1)  # which of ``scenes`` each lane holds (-1: none)
    steps, accepted, rejected = np.zeros(width, np.int64), np.zeros(width, np.int64), np.zeros(width, np.int64)
    just_rejected = np.zeros(width, np.bool_)
    start = np.empty(N_Y)
    taken, busy = 0, 0
    while True:
        for l in range(width):  # a free lane takes the next scene
            if job[l] < 0 and taken < m:
                j, i = taken, scenes[taken]
                taken += 1
                job[l] = j
                busy += 1
                for c in range(6):
                    PAR[c, l] = params[i, c]
                start[T], start[1], start[2] = 0.0, out[i, OUT_CA], out[i, OUT_SA]
                start[3], start[4], start[5], start[6] = states[i, 4], states[i, 5], states[i, 0], states[i, 1]
                tol[l] = out[i, OUT_TOL]
                sigma[l], sigma_end[l], spin_scale[l] = slide_start(out[i, OUT_V0], start[3], start[4], params[i],
                                                                    tol[l], base, l)
                rates = rates_in_sigma(sigma[l], start, params[i])
                for c in range(N_Y):
                    Y[c, l], K[0, c, l], err_acc[c, l] = start[c], rates[c], 0.0
                H[l], steps[l], accepted[l], rejected[l], just_rejected[l] = FIRST_STEP, 0, 0, 0, False
        if taken == m and busy <= HANDOFF:  # the last few scenes go on alone, from where they are
            for l in range(width):
                if job[l] >= 0:
                    j = job[l]
                    status[j] = _hand_off(K, Y, err_acc, base, sigma[l], sigma_end[l], spin_scale[l], H[l],
                                          accepted[l], rejected[l], just_rejected[l], steps[l], params[scenes[j]],
                                          tol[l], work[j], l)
            return
        for l in range(width):  # an idle lane computes on with h = 0: finite, and never read
            H[l] = min(H[l], sigma_end[l] - sigma[l]) if job[l] >= 0 else 0.0
        _lane_stages(K, sigma, Y, H, PAR, Y_stage)
        lanes_solution(Y, K, H, Y_new)
        _lane_rates(K[N_STAGES], sigma, 1.0, H, Y_new, PAR)
        for l in range(width):  # not vectorised by the compiler (scalar code, ~50 ns a lane): idle lanes skipped
            if job[l] >= 0:
                norm[l], spin[l] = step_norm(K, Y, Y_new, H[l], base, spin_scale[l], tol[l], l)
        for l in range(width):
            j = job[l]
            if j < 0:
                continue
            steps[l] += 1
            done = -1
            if not (norm[l] == norm[l]) or not math.isfinite(Y_new[T, l]):
                done = NON_FINITE
            else:
                if norm[l] <= 1.0:
                    accepted[l] += 1
                    accept(K, Y, Y_new, err_acc, base, spin[l], norm[l] * tol[l], l)
                    sigma[l] = sigma[l] + H[l] if H[l] < sigma_end[l] - sigma[l] else sigma_end[l]
                else:
                    rejected[l] += 1
                H[l] *= step_factor(norm[l], just_rejected[l])
                just_rejected[l] = norm[l] > 1.0
                if sigma[l] >= sigma_end[l]:
                    done = OK
                elif steps[l] >= MAX_STEPS:
                    done = WORK_LIMIT
            if done >= 0:
                status[j] = done
                record_slide(work[j], done, Y, err_acc, PAR[:, l], l, accepted[l], rejected[l], 0)
                job[l] = -1
                busy -= 1


def _hand_off(K, Y, err_acc, base, sigma, sigma_end, spin_scale, h, accepted, rejected, just_rejected, steps, params,
              tol, work, l):
    """Lane l's slide on to its end alone (`engine.slide_on` from lane l's state and step control); its status."""
    k, y, e, b = np.empty((N_EXTENDED, N_Y)), np.empty(N_Y), np.empty((N_Y, 1)), np.empty((N_Y, 1))
    for c in range(N_Y):
        k[0, c], y[c], e[c, 0], b[c, 0] = K[0, c, l], Y[c, l], err_acc[c, l], base[c, l]
    return slide_on(k, y, e, b, sigma, sigma_end, spin_scale, h, accepted, rejected, just_rejected, steps, params, tol,
                    np.empty((0, DENSE_WIDTH)), work)


def _lane_rates(K, sigma, c, H, Y, PAR):
    """K[:, l] (a stage's rates) = the rates at σ_l + c h_l, Y[:, l] for every lane (`engine.rates_at`, V = e^−σ by
    `vector_exp.exp`): one loop the compiler vectorises.  (K[s], not K and s: an integer
    constant would compile one copy of this per stage.)"""
    for l in range(Y.shape[1]):
        rates = rates_at(exp(-(sigma[l] + c * H[l])), Y[1, l], Y[2, l], Y[3, l], Y[4, l], PAR[0, l], PAR[1, l],
                         PAR[2, l], PAR[3, l], PAR[4, l], PAR[5, l])
        K[0, l], K[1, l], K[2, l], K[3, l] = rates[0], rates[1], rates[2], rates[3]
        K[4, l], K[5, l], K[6, l] = rates[4], rates[5], rates[6]


def _lane_stages(K, sigma, Y, H, PAR, Y_stage):
    """Stages 1–11 of one DOP853 step in every lane (stage 0, the rates at the start, is already in K[0])."""
    lanes_stage_1(Y, K, H, Y_stage)
    _lane_rates(K[1], sigma, C[1], H, Y_stage, PAR)
    lanes_stage_2(Y, K, H, Y_stage)
    _lane_rates(K[2], sigma, C[2], H, Y_stage, PAR)
    lanes_stage_3(Y, K, H, Y_stage)
    _lane_rates(K[3], sigma, C[3], H, Y_stage, PAR)
    lanes_stage_4(Y, K, H, Y_stage)
    _lane_rates(K[4], sigma, C[4], H, Y_stage, PAR)
    lanes_stage_5(Y, K, H, Y_stage)
    _lane_rates(K[5], sigma, C[5], H, Y_stage, PAR)
    lanes_stage_6(Y, K, H, Y_stage)
    _lane_rates(K[6], sigma, C[6], H, Y_stage, PAR)
    lanes_stage_7(Y, K, H, Y_stage)
    _lane_rates(K[7], sigma, C[7], H, Y_stage, PAR)
    lanes_stage_8(Y, K, H, Y_stage)
    _lane_rates(K[8], sigma, C[8], H, Y_stage, PAR)
    lanes_stage_9(Y, K, H, Y_stage)
    _lane_rates(K[9], sigma, C[9], H, Y_stage, PAR)
    lanes_stage_10(Y, K, H, Y_stage)
    _lane_rates(K[10], sigma, C[10], H, Y_stage, PAR)
    lanes_stage_11(Y, K, H, Y_stage)
    _lane_rates(K[11], sigma, C[11], H, Y_stage, PAR)
