"""The high-precision reference integrator: Gragg–Bulirsch–Stoer in mpmath.

For the smooth phases of the billiard ball (sliding with δ > 0 is analytic
until V = 0), extrapolation of the modified midpoint rule reaches 30–50
digits with a handful of large steps, much faster than mpmath's Taylor
`odefun` on these right-hand sides.  The step is accepted when the last two
diagonal entries of the extrapolation table agree to the tolerance, so each
step carries its own error estimate.

Reference: Hairer, Nørsett & Wanner, *Solving ODEs I*, §II.9 (ODEX).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable, Sequence

import mpmath

Vector = list  # of mpf
RHS = Callable[[mpmath.mpf, Vector], Vector]

MAX_COLUMNS = 18  # up to order 36


@dataclass
class Stats:
    steps: int = 0
    rejected: int = 0
    evaluations: int = 0


def _axpy(a, x: Vector, y: Vector) -> Vector:
    return [a * xi + yi for xi, yi in zip(x, y)]


def _midpoint(rhs: RHS, t, y: Vector, H, n: int, f0: Vector, stats: Stats) -> Vector:
    """Gragg's modified midpoint rule with n substeps, smoothed at the end."""
    h = H / n
    z_prev, z = y, _axpy(h, f0, y)
    for i in range(1, n):
        z_prev, z = z, _axpy(2 * h, rhs(t + i * h, z), z_prev)
    f_end = rhs(t + H, z)
    stats.evaluations += n
    return [(zi + zpi + h * fi) / 2 for zi, zpi, fi in zip(z, z_prev, f_end)]


def _error(a: Vector, b: Vector, tol) -> mpmath.mpf:
    return max(abs(ai - bi) / (tol * (1 + abs(ai))) for ai, bi in zip(a, b))


def step(rhs: RHS, t, y: Vector, H, tol, stats: Stats) -> tuple[Vector | None, mpmath.mpf, int]:
    """One extrapolated step of size H: (new state or None if rejected, error ratio, columns used)."""
    f0 = rhs(t, y)
    stats.evaluations += 1
    table: list[Vector] = []
    sizes = []
    err = mpmath.inf
    for j in range(MAX_COLUMNS):
        n = 2 * (j + 1)
        sizes.append(n)
        row = [_midpoint(rhs, t, y, H, n, f0, stats)]
        for k in range(1, j + 1):
            ratio = (mpmath.mpf(sizes[j]) / sizes[j - k]) ** 2 - 1
            row.append([r + (r - p) / ratio for r, p in zip(row[k - 1], table[j - 1][k - 1])])
        table.append(row)
        if j >= 2:
            err = _error(row[j], row[j - 1], tol)
            if err <= 1:
                return row[j], err, j
    return None, err, MAX_COLUMNS


def solve(rhs: RHS, t0, y0: Sequence, times: Sequence, digits: int = 30, first_step=None) -> tuple[list[Vector], Stats]:
    """The state at each of ``times`` (increasing, ≥ t0), relative accuracy about 10^-digits per step.

    Work is done at ``digits + 10`` decimal digits; steps land exactly on each
    requested time.
    """
    stats = Stats()
    out = []
    with mpmath.workdps(digits + 10):
        tol = mpmath.mpf(10) ** (-digits - 2)
        t, y = mpmath.mpf(t0), [mpmath.mpf(v) for v in y0]
        H = mpmath.mpf(first_step) if first_step is not None else None
        for target in times:
            target = mpmath.mpf(target)
            if H is None:
                H = (target - t) / 4 if target > t else mpmath.mpf("0.01")
            while t < target:
                h = min(H, target - t)
                new, err, cols = step(rhs, t, y, h, tol, stats)
                if new is None:
                    stats.rejected += 1
                    H = h / 4
                    continue
                stats.steps += 1
                t, y = t + h, new
                # Grow or shrink by the error of the converged column (order 2*cols + 1).
                factor = mpmath.mpf("0.9") * (1 / max(err, mpmath.mpf(10) ** -6)) ** (mpmath.mpf(1) / (2 * cols + 1))
                factor *= 1.5 if cols < 8 else 1  # converging early: try bigger steps
                proposed = h * min(4, max(mpmath.mpf("0.2"), factor))
                H = max(H, proposed) if h < H else proposed  # a step cut short to land is no evidence
            out.append(list(y))
    return out, stats
