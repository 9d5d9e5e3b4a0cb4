"""Dormand–Prince 8(5,3), vectorised over many independent problems, each with its own step size.

The coefficients are Hairer's DOP853 (Hairer, Nørsett & Wanner, *Solving ODEs I*,
§II.5 and §II.10), as tabulated in SciPy's ``dop853_coefficients.py``
(BSD-3-Clause); the error estimate is theirs too (the 5th- and 3rd-order
embedded estimates combined).  What is ours: every lane (one scene) takes its
own accepted/rejected steps in lock-step array operations, lanes that are done
drop out, and there is no Python loop over lanes.
"""

from __future__ import annotations

import numpy as np

N_STAGES = 12
C = np.array([
    0.0, 0.526001519587677318785587544488e-01, 0.789002279381515978178381316732e-01,
    0.118350341907227396726757197510, 0.281649658092772603273242802490,
    0.333333333333333333333333333333, 0.25, 0.307692307692307692307692307692,
    0.651282051282051282051282051282, 0.6, 0.857142857142857142857142857142, 1.0, 1.0,
])
A = np.zeros((N_STAGES + 1, N_STAGES))
A[1, 0] = 5.26001519587677318785587544488e-2
A[2, :2] = [1.97250569845378994544595329183e-2, 5.91751709536136983633785987549e-2]
A[3, [0, 2]] = [2.95875854768068491816892993775e-2, 8.87627564304205475450678981324e-2]
A[4, [0, 2, 3]] = [2.41365134159266685502369798665e-1, -8.84549479328286085344864962717e-1, 9.24834003261792003115737966543e-1]
A[5, [0, 3, 4]] = [3.7037037037037037037037037037e-2, 1.70828608729473871279604482173e-1, 1.25467687566822425016691814123e-1]
A[6, [0, 3, 4, 5]] = [3.7109375e-2, 1.70252211019544039314978060272e-1, 6.02165389804559606850219397283e-2, -1.7578125e-2]
A[7, [0, 3, 4, 5, 6]] = [
    3.70920001185047927108779319836e-2, 1.70383925712239993810214054705e-1, 1.07262030446373284651809199168e-1,
    -1.53194377486244017527936158236e-2, 8.27378916381402288758473766002e-3,
]
A[8, [0, 3, 4, 5, 6, 7]] = [
    6.24110958716075717114429577812e-1, -3.36089262944694129406857109825, -8.68219346841726006818189891453e-1,
    2.75920996994467083049415600797e1, 2.01540675504778934086186788979e1, -4.34898841810699588477366255144e1,
]
A[9, [0, 3, 4, 5, 6, 7, 8]] = [
    4.77662536438264365890433908527e-1, -2.48811461997166764192642586468, -5.90290826836842996371446475743e-1,
    2.12300514481811942347288949897e1, 1.52792336328824235832596922938e1, -3.32882109689848629194453265587e1,
    -2.03312017085086261358222928593e-2,
]
A[10, [0, 3, 4, 5, 6, 7, 8, 9]] = [
    -9.3714243008598732571704021658e-1, 5.18637242884406370830023853209, 1.09143734899672957818500254654,
    -8.14978701074692612513997267357, -1.85200656599969598641566180701e1, 2.27394870993505042818970056734e1,
    2.49360555267965238987089396762, -3.0467644718982195003823669022,
]
A[11, [0, 3, 4, 5, 6, 7, 8, 9, 10]] = [
    2.27331014751653820792359768449, -1.05344954667372501984066689879e1, -2.00087205822486249909675718444,
    -1.79589318631187989172765950534e1, 2.79488845294199600508499808837e1, -2.85899827713502369474065508674,
    -8.87285693353062954433549289258, 1.23605671757943030647266201528e1, 6.43392746015763530355970484046e-1,
]
A[12, [0, 5, 6, 7, 8, 9, 10, 11]] = [  # the weights B of the 8th-order solution
    5.42937341165687622380535766363e-2, 4.45031289275240888144113950566, 1.89151789931450038304281599044,
    -5.8012039600105847814672114227, 3.1116436695781989440891606237e-1, -1.52160949662516078556178806805e-1,
    2.01365400804030348374776537501e-1, 4.47106157277725905176885569043e-2,
]
B = A[N_STAGES]
E3 = np.append(B, 0.0)
E3[[0, 8, 11]] -= [0.244094488188976377952755905512, 0.733846688281611857341361741547, 0.220588235294117647058823529412e-1]
E5 = np.zeros(N_STAGES + 1)
E5[[0, 5, 6, 7, 8, 9, 10, 11]] = [
    0.1312004499419488073250102996e-1, -0.1225156446376204440720569753e1, -0.4957589496572501915214079952,
    0.1664377182454986536961530415e1, -0.3503288487499736816886487290, 0.3341791187130174790297318841,
    0.8192320648511571246570742613e-1, -0.2235530786388629525884427845e-1,
]

SAFETY, MIN_FACTOR, MAX_FACTOR = 0.9, 0.2, 10.0
# The nonzero weights of each combination: element-wise sums, not BLAS (whose own threads
# would fight the worker processes, and whose summation order depends on the array shape).
_NONZERO = [[(j, A[s, j]) for j in range(s) if A[s, j] != 0] for s in range(N_STAGES + 1)]
_E5 = [(j, w) for j, w in enumerate(E5) if w != 0]
_E3 = [(j, w) for j, w in enumerate(E3) if w != 0]


def _combine(weights, k):
    total = weights[0][1] * k[weights[0][0]]
    for j, w in weights[1:]:
        total += w * k[j]
    return total


# A bound on the work of one call: step attempts of the slowest lane (a slide takes tens to hundreds).
MAX_ITERATIONS = 20_000


def integrate(rhs, x0, y0, x_end, h0, scale, tol, stats=None):
    """Integrate y' = rhs(x, y) for many lanes at once, each from x0 to x_end (arrays of shape (n,)).

    ``y0`` has shape (m, n); ``scale`` (m, n) is each component's size, or a
    function (y_old, y_new, lanes) -> sizes: a step is accepted when its
    error is below ``tol`` times that size.
    ``rhs(x, y, lanes)`` evaluates the lanes ``lanes`` (an index array).
    Returns y at x_end, shape (m, n).  A lane whose state or error becomes
    non-finite, or that is not done after `MAX_ITERATIONS` step attempts,
    stops there with y = NaN: the caller names the scene, nothing loops on.
    """
    y = np.array(y0, dtype=float)
    x, x_end, h = (np.array(a, dtype=float, copy=True) for a in (x0, x_end, h0))
    lanes = np.flatnonzero(x < x_end)
    K = np.empty((N_STAGES + 1, y.shape[0], y.shape[1]))
    for _ in range(MAX_ITERATIONS):
        if lanes.size == 0:
            return y
        xs, ys = x[lanes], y[:, lanes]
        hs = np.minimum(h[lanes], x_end[lanes] - xs)
        k = K[:, :, : lanes.size]
        k[0] = rhs(xs, ys, lanes)
        for s in range(1, N_STAGES):
            k[s] = rhs(xs + C[s] * hs, ys + _combine(_NONZERO[s], k) * hs, lanes)
        y_new = ys + hs * _combine(_NONZERO[N_STAGES], k)
        k[N_STAGES] = rhs(xs + hs, y_new, lanes)
        sc = scale(ys, y_new, lanes) if callable(scale) else scale[:, lanes]
        err5 = _combine(_E5, k) / sc
        err3 = _combine(_E3, k) / sc
        e5, e3 = np.sum(err5**2, axis=0), np.sum(err3**2, axis=0)
        denom = e5 + 0.01 * e3
        norm = np.where(denom > 0, hs * e5 / np.sqrt(np.where(denom > 0, denom, 1.0) * y.shape[0]), 0.0) / tol
        broken = ~np.isfinite(norm) | ~np.isfinite(y_new).all(axis=0) | ~(hs > 0)
        if broken.any():  # NaN or overflow: this lane is over, its result NaN
            y[:, lanes[broken]] = np.nan
            x[lanes[broken]] = x_end[lanes[broken]]
            norm = np.where(broken, np.inf, norm)
        ok = norm <= 1
        if stats is not None:
            stats["steps"] += int(ok.sum())
            stats["rejected"] += int((~ok).sum())
            stats["evaluations"] += 13 * lanes.size
        factor = np.where(norm == 0, MAX_FACTOR, SAFETY * np.where(norm > 0, norm, 1.0) ** (-1 / 8))
        factor = np.clip(factor, MIN_FACTOR, np.where(ok, MAX_FACTOR, 1.0))
        done_lanes = lanes[ok]
        y[:, done_lanes] = y_new[:, ok]
        landed = hs >= x_end[lanes] - xs  # land exactly: xs + hs may round short of x_end
        x[done_lanes] = np.where(landed, x_end[lanes], xs + hs)[ok]
        h[lanes] = hs * factor
        lanes = lanes[x[lanes] < x_end[lanes]]
    y[:, lanes] = np.nan  # the bound on work reached: these lanes have no result
    return y
