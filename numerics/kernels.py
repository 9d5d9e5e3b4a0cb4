"""The simulator's formulas, generated from the derivation by `numerics.codegen`: do not edit.

Regenerate with ``python -m numerics.codegen`` (``--check`` fails when this
file is stale).  Plain Python on floats, ``math`` only: the interpreted
engine runs it as it is, and numba compiles it unchanged (`numerics.compiled`).
Parameters always come in the order f, R, k, delta, epsilon, g (SI units).
"""

import math

def slide_rates(V, cos_alpha, sin_alpha, p, q, cos_beta, sin_beta, f, R, k, delta, epsilon, g):
    """V', V alpha', p', q', xi', eta' while sliding (eqs. (4)-(8), n°2), from V, the slip's unit vector (cos alpha, sin alpha), p, q and the rotation's unit vector (cos beta, sin beta)."""
    x0 = (1/(k*k))
    x1 = cos_beta*delta
    x2 = g*x0
    x3 = R*f
    return (g*(-(R*R)*f*x0 + R*cos_alpha*delta*sin_beta*x0 - R*sin_alpha*x0*x1 - f), -R*delta*x2*(cos_alpha*cos_beta + sin_alpha*sin_beta), -x2*(sin_alpha*x3 + x1), x2*(cos_alpha*x3 - delta*sin_beta), R*q + V*cos_alpha, -R*p + V*sin_alpha)


def slip_velocity(xi_dot, eta_dot, p, q, R):
    """(u, v), the slip of the contact point, from the centre's velocity and the rotation: eq. (2)."""
    return (-R*q + xi_dot, R*p + eta_dot)


def centre_velocity(V, cos_alpha, sin_alpha, p, q, R):
    """(xi', eta') from the slip V (cos alpha, sin alpha) and the rotation (p, q): eq. (2) solved for the centre."""
    return (R*q + V*cos_alpha, -R*p + V*sin_alpha)


def classical_at(tau, V0, Omega0, beta0, f, R, k, delta, epsilon, g):
    """(V, p, q, xi, eta, xi', eta') in the slip frame at tau after the start of n°3 (delta = 0, or the classical model)."""
    x0 = (k*k)
    x1 = f*g*tau
    x2 = x1/x0
    x3 = Omega0*math.cos(beta0)
    x4 = Omega0*math.sin(beta0)
    x5 = R*x4 + V0
    x6 = R*x3
    return (V0 - x2*((R*R) + x0), x3, R*x2 + x4, tau*(-1/2*x1 + x5), -tau*x6, -x1 + x5, -x6)


def classical_end(V0, Omega0, beta0, f, R, k, delta, epsilon, g):
    """the duration of n°3 (delta = 0, or the classical model)."""
    x0 = (k*k)
    return V0*x0/(f*g*((R*R) + x0))


def follow_at(tau, V0, Omega0, f, R, k, delta, epsilon, g):
    """(V, p, q, xi, eta, xi', eta') in the slip frame at tau after the start of the straight shot theta = +pi/2."""
    x0 = (k*k)
    x1 = g*tau
    x2 = x1/x0
    x3 = V0 - x2*((R*R)*f - R*delta + f*x0)
    x4 = Omega0 + x2*(R*f - delta)
    return (x3, 0.0, x4, tau*(Omega0*R + V0 - 1/2*f*x1), 0.0, R*x4 + x3, 0.0)


def follow_end(V0, Omega0, f, R, k, delta, epsilon, g):
    """(slip end, spin end) of the straight shot theta = +pi/2."""
    x0 = (k*k)
    x1 = x0/g
    return (V0*x1/((R*R)*f - R*delta + f*x0), -Omega0*x1/(R*f - delta))


def draw_at(tau, V0, Omega0, f, R, k, delta, epsilon, g):
    """(V, p, q, xi, eta, xi', eta') in the slip frame at tau after the start of the straight shot theta = -pi/2."""
    x0 = (k*k)
    x1 = 1/x0
    x2 = g*tau
    x3 = x1*x2*((R*R)*f + R*delta + f*x0)
    x4 = Omega0 - g*tau*x1*(R*f + delta)
    x5 = -V0
    return (V0 - x3, 0.0, -x4, -tau*(Omega0*R + (1/2)*f*x2 + x5), 0.0, -R*x4 - x3 - x5, 0.0)


def draw_end(V0, Omega0, f, R, k, delta, epsilon, g):
    """(slip end, spin end) of the straight shot theta = -pi/2."""
    x0 = (k*k)
    x1 = x0/g
    return (V0*x1/((R*R)*f + R*delta + f*x0), Omega0*x1/(R*f + delta))


def rolling_at(tau, Omega0, beta0, f, R, k, delta, epsilon, g):
    """(V, p, q, xi, eta, xi', eta') in the slip frame at tau after the start of n°7, pure rolling."""
    x0 = math.cos(beta0)
    x1 = delta*g*tau/((R*R) + (k*k))
    x2 = Omega0 - x1
    x3 = x0*x2
    x4 = math.sin(beta0)
    x5 = x2*x4
    x6 = Omega0 - 1/2*x1
    x7 = R*tau
    return (0.0, x3, x5, x4*x6*x7, -x0*x6*x7, R*x5, -R*x3)


def rolling_end(Omega0, beta0, f, R, k, delta, epsilon, g):
    """the duration of n°7, pure rolling."""
    return Omega0*((R*R) + (k*k))/(delta*g)


def pivot_at(tau, r0, f, R, k, delta, epsilon, g):
    """r at tau after the start of eq. (5), the pivot."""
    return -epsilon*g*tau/(k*k) + r0


def pivot_end(r0, f, R, k, delta, epsilon, g):
    """the duration of eq. (5), the pivot."""
    return (k*k)*r0/(epsilon*g)
