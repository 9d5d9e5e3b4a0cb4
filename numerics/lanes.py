"""Many curved slides at once, in lanes: `slide_numerically`'s loop run on a block of scenes side by side.

A batch (`solve_many`) first settles every scene it can in closed form
(`engine.begin`), then integrates the remaining slides in lanes: each lane
holds one scene, and every stage of DOP853 is computed for all lanes in one
loop over them, which the compiler turns into vector instructions (8 lanes
per AVX-512 instruction, 4 per AVX2; one scene's stage is a chain of dependent divisions
and square roots that leaves the core mostly idle: in a long batch a scene
costs about a quarter of its time alone).  Each lane keeps its own step size
and accepts or rejects its own steps with the single-scene loop's step
control (`engine.accept` and `step_factor` themselves; `engine.step_norm`'s
operations, in its order, as one more loop over lanes: `_lane_norms`), so a
scene takes exactly the steps it takes alone, bit for bit.

A free lane takes the next scene; once none waits, the busy lanes close up
(the last into each that ends) and the loops run over them only, rounded up
to 4 (8 lanes an instruction, then 4: `VECTOR`): a block's cost follows its
busy lanes, so a batch of ten slides, or the long slides at a batch's end, no
longer pay for 32.  The block lives in one buffer (`numerics.lane_rows`),
which is what lets the compiler vectorise a loop of 8 lanes at all.  The last
busy lane goes on alone (`engine.slide_on`, the single-scene loop, from where
it is).  Measured: `appell bench`.

The compiled engine uses NumPy's error model (`numerics.compiled`: a division
by zero gives ∞ or NaN, caught by the status checks) because Python's — a
test and a raise at every division — keeps the loops over lanes from being
vectorised.
"""

import math

import numpy as np

from numerics.dop853_steps import (  # generated from the tables: bare names, as the engine's
    lanes_error_terms, lanes_solution, lanes_stage_1, lanes_stage_2, lanes_stage_3, lanes_stage_4, lanes_stage_5, lanes_stage_6,
    lanes_stage_7, lanes_stage_8, lanes_stage_9, lanes_stage_10, lanes_stage_11,
)
from numerics.dop853_tables import C, N_EXTENDED, N_STAGES
from numerics.lane_rows import (
    LANES, N_ROWS, N_Y, NEWEST, ROW_BASE, ROW_ERR, ROW_H, ROW_K, ROW_NORM, ROW_PAR, ROW_SIGMA, ROW_SIGMA_END,
    ROW_SPIN, ROW_SPIN_SCALE, ROW_TOL, ROW_Y, ROW_Y_NEW, ROW_Y_STAGE,
)
from numerics.vector_exp import exp
from numerics.engine import (
    CA, DENSE_WIDTH, ETA, FIRST_STEP, MAX_STEPS, N_WORK, NON_FINITE, OK, OUT_CA, OUT_SA, OUT_TOL, OUT_V0, P, Q, SA,
    SPIN_FLOOR, T, WORK_LIMIT, XI, accept, begin, finish, rates_at, rates_in_sigma, record_slide, slide, slide_on,
    slide_start, step_factor, turn_norm,
)

# A block's loops run over its busy lanes rounded up to this: the compiler's vector loop takes 8 lanes an
# instruction (float64, AVX-512) and what is left 4 at a time (its vector epilogue, `compiled.EPILOGUE`), so
# ten busy lanes cost an 8 and a 4, not two 8s (measured: the lanes 9–16% faster at ten scenes a call, alike
# on large batches).
VECTOR = 4
# A single busy lane goes on alone (`engine.slide_on`), as does a batch of one curved slide (measured: a scene
# alone in a block 20 µs, in the single-scene loop 15; two scenes 10 µs each in lanes, 15 one by one).
HANDOFF = 1


def solve_many(params, states, classical, tol, out):
    """`engine.solve` on every row (params and states one row per scene), the numerical slides in lanes (more
    than HANDOFF of them) or one by one; no dense output.  `batch.simulate_many` runs it on chunks in threads
    (compiled, it releases the GIL)."""
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
    else:  # alone: the same steps, the same bits
        for j in range(m):
            i = pending[j]
            status[j] = slide(params[i], states[i], out[i], np.empty((0, DENSE_WIDTH)), work[j])
    for j in range(m):
        i = pending[j]
        while finish(params[i], states[i], status[j], work[j], out[i]):  # once more, at a tighter tolerance: alone
            status[j] = slide(params[i], states[i], out[i], np.empty((0, DENSE_WIDTH)), work[j])  # (rare), as `solve`


def _rows(L, first, count):
    """Rows first … first + count − 1 of the block L as a (row, lane) view."""
    return L[first * LANES : (first + count) * LANES].reshape((count, LANES))


def slide_lanes(scenes, params, states, out, work, status):
    """`engine.slide_numerically` (without dense output) for the rows ``scenes`` of a batch, whose ``out`` rows
    `begin` filled; row j of ``work`` and ``status`` receive scene ``scenes[j]``'s.

    The busy lanes are lanes 0 … busy − 1: a free lane takes the next scene, and once none waits, the last busy
    lane takes the place of each that ends.  The loops over lanes run over the busy ones rounded up to VECTOR
    (the lanes above compute on with h = 0: finite, and never read)."""
    m = scenes.shape[0]
    L = _aligned_zeros(N_ROWS * LANES)  # what the vectorised loops read and write (`numerics.lane_rows`)
    PAR = _rows(L, ROW_PAR, 6)
    PAR[:, :] = 1.0
    # (component, lane) views of it for the step control (scalar code).
    K = L[ROW_K * LANES : (ROW_K + (N_STAGES + 1) * N_Y) * LANES].reshape((N_STAGES + 1, N_Y, LANES))
    Y, Y_new = _rows(L, ROW_Y, N_Y), _rows(L, ROW_Y_NEW, N_Y)
    Y[CA, :] = 1.0  # a lane never given a scene computes on a unit slip direction, parameters 1: finite
    sigma, H = _rows(L, ROW_SIGMA, 1)[0], _rows(L, ROW_H, 1)[0]
    base, spin_scale, tol = _rows(L, ROW_BASE, N_Y), _rows(L, ROW_SPIN_SCALE, 1)[0], _rows(L, ROW_TOL, 1)[0]
    base[:, :], spin_scale[:], tol[:] = 1.0, 1.0, 1.0  # (as the parameters: a lane never given a scene stays finite)
    norm, spin = _rows(L, ROW_NORM, 1)[0], _rows(L, ROW_SPIN, 1)[0]  # each step's error over its tolerance, Ω's scale
    err_acc, sigma_end = _rows(L, ROW_ERR, N_Y), _rows(L, ROW_SIGMA_END, 1)[0]  # the errors summed, σ at the end
    job = np.full(LANES, -1)  # which of ``scenes`` each lane holds (-1: none)
    steps, accepted, rejected = np.zeros(LANES, np.int64), np.zeros(LANES, np.int64), np.zeros(LANES, np.int64)
    just_rejected = np.zeros(LANES, np.bool_)
    start = np.empty(N_Y)
    taken, busy = 0, 0
    while True:
        for l in range(LANES):  # a free lane takes the next scene
            if job[l] < 0 and taken < m:
                j, i = taken, scenes[taken]
                taken += 1
                job[l] = j
                busy += 1
                for c in range(6):
                    PAR[c, l] = params[i, c]
                start[T], start[1], start[2] = 0.0, out[i, OUT_CA], out[i, OUT_SA]
                start[3], start[4], start[5], start[6] = states[i, 4], states[i, 5], 0.0, 0.0  # the displacement
                tol[l] = out[i, OUT_TOL]
                sigma[l], sigma_end[l], spin_scale[l] = slide_start(out[i, OUT_V0], states[i, 2], states[i, 3], start[3],
                                                                    start[4], params[i], tol[l], base, l)
                rates = rates_in_sigma(sigma[l], start, params[i])
                for c in range(N_Y):
                    Y[c, l], K[0, c, l], err_acc[c, l] = start[c], rates[c], 0.0
                H[l], steps[l], accepted[l], rejected[l], just_rejected[l] = FIRST_STEP, 0, 0, 0, False
        if taken == m:  # no scene waits: the busy lanes close up, the last one into each free lane below it
            last = LANES - 1
            for l in range(busy):
                if job[l] < 0:
                    while job[last] < 0:
                        last -= 1
                    _move(L, last, l)
                    job[l], steps[l], accepted[l], rejected[l] = job[last], steps[last], accepted[last], rejected[last]
                    just_rejected[l] = just_rejected[last]
                    job[last] = -1
            if busy <= HANDOFF:  # the last scene goes on alone, from where it is
                for l in range(busy):
                    j = job[l]
                    status[j] = _hand_off(K, Y, err_acc, base, sigma[l], sigma_end[l], spin_scale[l], H[l],
                                          accepted[l], rejected[l], just_rejected[l], steps[l], params[scenes[j]],
                                          tol[l], work[j], l)
                return
        width = min(LANES, -(-busy // VECTOR) * VECTOR)
        for l in range(width):
            H[l] = min(H[l], sigma_end[l] - sigma[l]) if job[l] >= 0 else 0.0
        _lane_stages(L, width)
        lanes_solution(L, width)
        _lane_rates_new(L, width)
        _lane_norms(L, width)
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


def _aligned_zeros(n):
    """n zeros from a 64-byte boundary, a cache line (numba aligns its arrays to 32 bytes): every row of a block
    of 32 lanes starts a line, and no AVX-512 load of 64 bytes straddles two."""
    buffer = np.zeros(n + 8)
    skip = (-buffer.ctypes.data % 64) // 8
    return buffer[skip : skip + n]


def _move(L, source, target):
    """Lane ``source``'s every row of the block into lane ``target``."""
    for r in range(N_ROWS):
        L[r * LANES + target] = L[r * LANES + source]


def _hand_off(K, Y, err_acc, base, sigma, sigma_end, spin_scale, h, accepted, rejected, just_rejected, steps, params,
              tol, work, l):
    """Lane l's slide on to its end alone (`engine.slide_on` from lane l's state and step control); its status."""
    k, y, e, b = np.empty((N_EXTENDED, N_Y)), np.empty(N_Y), np.empty((N_Y, 1)), np.empty((N_Y, 1))
    for c in range(N_Y):
        k[0, c], y[c], e[c, 0], b[c, 0] = K[0, c, l], Y[c, l], err_acc[c, l], base[c, l]
    return slide_on(k, y, e, b, sigma, sigma_end, spin_scale, h, accepted, rejected, just_rejected, steps, params, tol,
                    np.empty((0, DENSE_WIDTH)), work)


def _lane_norms(L, width):
    """Rows NORM and SPIN = `engine.step_norm` in every lane, its operations in its order (the same bits), as one
    loop the compiler vectorises (the shared function inlined into a loop over lanes was left scalar code)."""
    for l in range(width):
        p, q = L[(ROW_Y + P) * LANES + l], L[(ROW_Y + Q) * LANES + l]
        p_new, q_new = L[(ROW_Y_NEW + P) * LANES + l], L[(ROW_Y_NEW + Q) * LANES + l]
        spin = min(math.sqrt(p * p + q * q), math.sqrt(p_new * p_new + q_new * q_new))
        spin = max(spin, SPIN_FLOOR * L[ROW_SPIN_SCALE * LANES + l])
        e5, e3 = _norm_terms(L, T, L[(ROW_BASE + T) * LANES + l], l, 0.0, 0.0)
        e5, e3 = _norm_terms(L, CA, L[(ROW_BASE + CA) * LANES + l], l, e5, e3)
        e5, e3 = _norm_terms(L, SA, L[(ROW_BASE + SA) * LANES + l], l, e5, e3)
        e5, e3 = _norm_terms(L, P, spin, l, e5, e3)
        e5, e3 = _norm_terms(L, Q, spin, l, e5, e3)
        e5, e3 = _norm_terms(L, XI, L[(ROW_BASE + XI) * LANES + l], l, e5, e3)
        e5, e3 = _norm_terms(L, ETA, L[(ROW_BASE + ETA) * LANES + l], l, e5, e3)
        denom = e5 + 0.01 * e3
        h, tol = L[ROW_H * LANES + l], L[ROW_TOL * LANES + l]
        norm = abs(h) * e5 / math.sqrt(denom * N_Y) / tol if denom > 0 else 0.0
        L[ROW_NORM * LANES + l] = max(norm, turn_norm(p, q, p_new, q_new, SPIN_FLOOR * L[ROW_SPIN_SCALE * LANES + l]))
        L[ROW_SPIN * LANES + l] = spin


def _norm_terms(L, i, scale, l, e5, e3):
    """(e5, e3) with component i's error terms over its scale added, squared (inlined: i a constant)."""
    a5, a3 = lanes_error_terms(L, i, l)
    x5, x3 = a5 / scale, a3 / scale
    return e5 + x5 * x5, e3 + x3 * x3


def _rates_from(L, row_y, c, width):
    """Block NEWEST of L = the rates at σ + c h and the rows row_y … of L, in lanes [0, width) (`engine.rates_at`,
    V = e^−σ by `vector_exp.exp`): one loop the compiler vectorises.  Inlined into its two callers, which
    give row_y as a constant (the compiler vectorises only constant rows: `numerics.lane_rows`)."""
    k = (ROW_K + NEWEST * N_Y) * LANES
    for l in range(width):
        rates = rates_at(exp(-(L[ROW_SIGMA * LANES + l] + c * L[ROW_H * LANES + l])), L[(row_y + 1) * LANES + l],
                         L[(row_y + 2) * LANES + l], L[(row_y + 3) * LANES + l], L[(row_y + 4) * LANES + l],
                         L[ROW_PAR * LANES + l], L[(ROW_PAR + 1) * LANES + l], L[(ROW_PAR + 2) * LANES + l],
                         L[(ROW_PAR + 3) * LANES + l], L[(ROW_PAR + 4) * LANES + l], L[(ROW_PAR + 5) * LANES + l])
        L[k + l], L[k + LANES + l], L[k + 2 * LANES + l], L[k + 3 * LANES + l] = rates[0], rates[1], rates[2], rates[3]
        L[k + 4 * LANES + l], L[k + 5 * LANES + l], L[k + 6 * LANES + l] = rates[4], rates[5], rates[6]


def _lane_rates(L, c, width):
    """The rates at a stage's input (rows ROW_Y_STAGE), σ + c h."""
    _rates_from(L, ROW_Y_STAGE, c, width)


def _lane_rates_new(L, width):
    """The rates at the step's end (rows ROW_Y_NEW), σ + h: the next step's first stage."""
    _rates_from(L, ROW_Y_NEW, 1.0, width)


def _lane_stages(L, width):
    """Stages 1–11 of one DOP853 step in lanes [0, width) (stage 0, the rates at the start, is already in K[0])."""
    lanes_stage_1(L, width)
    _lane_rates(L, C[1], width)
    lanes_stage_2(L, width)
    _lane_rates(L, C[2], width)
    lanes_stage_3(L, width)
    _lane_rates(L, C[3], width)
    lanes_stage_4(L, width)
    _lane_rates(L, C[4], width)
    lanes_stage_5(L, width)
    _lane_rates(L, C[5], width)
    lanes_stage_6(L, width)
    _lane_rates(L, C[6], width)
    lanes_stage_7(L, width)
    _lane_rates(L, C[7], width)
    lanes_stage_8(L, width)
    _lane_rates(L, C[8], width)
    lanes_stage_9(L, width)
    _lane_rates(L, C[9], width)
    lanes_stage_10(L, width)
    _lane_rates(L, C[10], width)
    lanes_stage_11(L, width)
    _lane_rates(L, C[11], width)
