"""mpmath cross-checks of the reduction (n°10, n°11) along integrated trajectories.

Every right-hand side is lambdified from what derivation/ and reduction/
hold; only the trajectory is computed here, by `reference.solve`.
"""

from __future__ import annotations

from functools import lru_cache

import mpmath
import sympy as sp

from derivation import polar
from derivation.checks import worst_of
from derivation.claim import NumericCheck
from derivation.symbols import Omega, R, V, alpha, beta, d, delta, f, g, k, theta
from numerics.reference import solve
from reduction import n9_reduced_system, n10_special_case, n11_abel
from reduction.variables import A, C, a, b, c, h, lam, z

STATE = (V, Omega, alpha, beta)
PARAMS = (f, R, k, delta, g)
X = n10_special_case.X


@lru_cache(maxsize=None)
def _motion_rhs():
    """(7)–(8) as an mpmath function of (t, [V, Ω, α, β]) and the parameters."""
    rates = polar.rates()
    values = [rates[d(q)].subs(theta, beta - alpha) for q in STATE]
    return sp.lambdify((STATE, PARAMS), values, "mpmath")


def central_difference(values: list, h) -> mpmath.mpf:
    """f'(t) from f(t + jh), j = −m…m, by the central formula of order 2m."""
    m = (len(values) - 1) // 2
    total = 0
    for j in range(1, m + 1):
        weight = (-1) ** (j + 1) * mpmath.factorial(m) ** 2 / (j * mpmath.factorial(m - j) * mpmath.factorial(m + j))
        total += weight * (values[m + j] - values[m - j])
    return total / h


def abel_along_trajectory(digits: int = 40) -> tuple[float, int]:
    """Integrate (7)–(8) at ``digits`` digits; map to z(φ); residual of z' = z³ − z² + λz(1 − z)².

    z = y/(x + y) and θ = β − α come from the trajectory; their t-derivatives
    by a 17-point central difference of the integrated states; dφ/dθ and λ
    from n°11.  Returns the digits of the worst relative residual.
    """
    rhs = _motion_rhs()
    consts = n9_reduced_system.constants()
    dphi = sp.lambdify((theta, a, b), n11_abel.DPHI_DTHETA, "mpmath")
    lam_14 = sp.lambdify((theta, a, b, c), n11_abel.LAMBDA_FROM_14, "mpmath")
    abel = sp.lambdify((z, lam), n11_abel.chain()["z'"].subs({n11_abel.Lam: lam, n11_abel.Z: z}), "mpmath")
    to_abc = sp.lambdify(PARAMS, [consts[a], consts[b], consts[c]], "mpmath")
    worst = mpmath.mpf(0)
    cases = 0
    with mpmath.workdps(digits + 10):
        # A pool ball with a large rolling coefficient (δ = 0.3 fR), so that λ matters.
        R_ = mpmath.mpf("0.028575")
        params = (mpmath.mpf("0.2"), R_, R_ * mpmath.sqrt(mpmath.mpf(2) / 5), mpmath.mpf("0.3") * mpmath.mpf("0.2") * R_, mpmath.mpf("9.81"))
        f_, _, _, delta_, _ = params
        a_, b_, c_ = to_abc(*params)
        # V₀ = 2 m/s: the slide lasts about 0.29 s; stay well inside it.
        step, m = mpmath.mpf("2e-4"), 8
        centres = [mpmath.mpf(x) for x in ("0.03", "0.08", "0.15")]
        times = [tc + j * step for tc in centres for j in range(-m, m + 1)]
        states, _ = solve(lambda t, y: rhs(y, params), 0, [2, 30, 0, 2], times, digits)
        for i, tc in enumerate(centres):
            block = states[i * (2 * m + 1) : (i + 1) * (2 * m + 1)]
            xs = [f_ * s[0] for s in block]
            ys = [delta_ * s[1] for s in block]
            zs = [y_ / (x_ + y_) for x_, y_ in zip(xs, ys)]
            thetas = [s[3] - s[2] for s in block]
            z_t, theta_t = central_difference(zs, step), central_difference(thetas, step)
            th, zz = thetas[m], zs[m]
            z_phi = z_t / (dphi(th, a_, b_) * theta_t)
            residual = z_phi - abel(zz, lam_14(th, a_, b_, c_))
            worst = worst_of(worst, abs(residual) / abs(z_phi))
            cases += 1
    return float(-mpmath.log10(worst)), cases


SPECIAL_CASES = (  # (θ₀, θ₁, x₀, A, h): x stays positive, θ in (−π/2, π/2)
    ("0", "0.6", "2", "0.5", "1.5"),
    ("-0.8", "0.3", "1", "-0.4", "2.2"),
    ("0.2", "1.1", "3", "1.3", "1.1"),
)


def special_case_along_trajectory(digits: int = 30) -> tuple[float, int]:
    """Integrate (14) with a = c; the printed x(x + A) cos θ tan^h(θ/2 + π/4) must keep its value."""
    sol = n10_special_case.special_case()
    rate = sp.lambdify((theta, X, A, h), sol["dx/dtheta"].subs(n10_special_case.x, X), "mpmath")
    K = sp.lambdify((theta, X, A, h), sol["K"].subs(n10_special_case.x, X), "mpmath")
    worst = mpmath.mpf(0)
    with mpmath.workdps(digits + 10):
        for th0, th1, x0, A_, h_ in SPECIAL_CASES:
            th0, th1, x0, A_, h_ = map(mpmath.mpf, (th0, th1, x0, A_, h_))
            (end,), _ = solve(lambda th, xs: [rate(th, xs[0], A_, h_)], th0, [x0], [th1], digits)
            start_K, end_K = K(th0, x0, A_, h_), K(th1, end[0], A_, h_)
            worst = worst_of(worst, abs(end_K - start_K) / abs(start_K))
    return float(-mpmath.log10(worst)) if worst else float(digits + 10), len(SPECIAL_CASES)


def recovery_along_trajectory(digits: int = 30) -> tuple[float, int]:
    """Integrate (14) with a = c; x and y = x + A at four values of θ against n°10's recovery from y − x and xy.

    C comes from the start (x(x + A) cos θ tan^h(θ/2 + π/4) at θ₀); x and y are then n°10's roots at θ.
    """
    sol, rec = n10_special_case.special_case(), n10_special_case.recovery()
    rate = sp.lambdify((theta, X, A, h), sol["dx/dtheta"].subs(n10_special_case.x, X), "mpmath")
    K = sp.lambdify((theta, X, A, h), sol["K"].subs(n10_special_case.x, X), "mpmath")
    roots = sp.lambdify((theta, A, h, C), [rec["x"], rec["y"]], "mpmath")
    worst, cases = mpmath.mpf(0), 0
    with mpmath.workdps(digits + 10):
        for th0, th1, x0, A_, h_ in SPECIAL_CASES:
            th0, th1, x0, A_, h_ = map(mpmath.mpf, (th0, th1, x0, A_, h_))
            C_ = K(th0, x0, A_, h_)
            thetas = [th0 + (th1 - th0) * mpmath.mpf(j) / 4 for j in range(1, 5)]
            states, _ = solve(lambda th, xs: [rate(th, xs[0], A_, h_)], th0, [x0], thetas, digits)
            for th, (x_,) in zip(thetas, states):
                x_root, y_root = roots(th, A_, h_, C_)
                worst = worst_of(worst, abs(x_root - x_) / x_, abs(y_root - (x_ + A_)) / (x_ + A_))
                cases += 1
    return (float(-mpmath.log10(worst)) if worst else float(digits + 10)), cases


def claims():
    return [
        NumericCheck(
            "n10.closed_form_mpmath",
            "n°10",
            "The closed form of n°10 against (14) with a = c integrated at 30 digits (Gragg–Bulirsch–Stoer, "
            "40 working digits): x(x + A) cos θ tan^h(θ/2 + π/4) keeps its value.",
            r"x(x + A) = \frac{C}{\cos \theta \left[ \tan \left( \frac{\theta}{2} + \frac{\pi}{4} \right) \right]^h}.",
            special_case_along_trajectory,
            required_digits=30,
        ),
        NumericCheck(
            "n10.recovery_mpmath",
            "n°10",
            "x and y recovered from y − x = A and xy = C/(cos θ tan^h(θ/2 + π/4)) (the root with x + y > 0) against "
            "(14) with a = c integrated at 30 digits, C taken from the start.",
            r"et l'on peut calculer $x$ et $y$ en fonction de $\theta$",
            recovery_along_trajectory,
            required_digits=30,
        ),
        NumericCheck(
            "n11.trajectory",
            "n°11",
            "A trajectory of (7)–(8), integrated to 40 digits (50 working digits: the residual can come out "
            "smaller than 10^-40), mapped to z = y/(x + y) and φ, solves "
            "z' = z³ − z² + λz(1 − z)² (derivatives of the trajectory by 17-point central differences).",
            r"z' = z^3 - z^2 + \lambda z(1 - z)^2.",
            abel_along_trajectory,
            required_digits=25,
        ),
    ]
