"""Abel equations of the first kind, their normal form and their invariants — in general.

An Abel equation dy/dt = f₃y³ + f₂y² + f₁y + f₀ keeps its form under
y = P u + Q together with a change of variable t ↦ τ.  Choosing
Q = −f₂/(3f₃), P = exp ∫(f₁ − f₂²/(3f₃)) dt and dτ = f₃P² dt gives the
normal form of R. Liouville and Appell (J. Math. Pures Appl. (4) 5, 1889):

    du/dτ = u³ + I(τ),   I = s₃ / (f₃ P)³,

where s₃ and s₅ = f₃ s₃' − 3(f₃' + f₁f₃ − f₂²/3) s₃ are relative invariants
(weights 3 and 5): under y = P u + Q, τ' = T', they are multiplied by
(P/T')³ and (P/T')⁵.  Hence J = s₅³/s₃⁵ is an absolute invariant
(Cheb-Terrab & Roche, Comput. Phys. Commun. 130 (2000) 204).  When J is
constant (or s₃ ≡ 0) the normal form is u' = u³ + K τ^(−3/2) (or u' = u³),
integrable by quadrature.

The coefficients are held as functions of a parameter x, with the
independent variable t = t(x) given by its rate dt/dx, so that a change of
variable never needs the new variable in closed form.
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp


@dataclass(frozen=True)
class Abel:
    """dy/dt = f3 y³ + f2 y² + f1 y + f0, coefficients as functions of ``x``, dt/dx = ``rate``."""

    f3: sp.Expr
    f2: sp.Expr
    f1: sp.Expr
    f0: sp.Expr
    x: sp.Symbol
    rate: sp.Expr = sp.Integer(1)

    @property
    def coefficients(self) -> tuple[sp.Expr, sp.Expr, sp.Expr, sp.Expr]:
        return self.f3, self.f2, self.f1, self.f0

    def rhs(self, y: sp.Expr) -> sp.Expr:
        return self.f3 * y**3 + self.f2 * y**2 + self.f1 * y + self.f0

    def d(self, expr: sp.Expr) -> sp.Expr:
        """d/dt of a function of x."""
        return sp.diff(expr, self.x) / self.rate

    def s3(self) -> sp.Expr:
        f3, f2, f1, f0 = self.coefficients
        return f0 * f3**2 - f1 * f2 * f3 / 3 + sp.Rational(2, 27) * f2**3 + (f3 * self.d(f2) - f2 * self.d(f3)) / 3

    def s5(self, s3: sp.Expr | None = None) -> sp.Expr:
        f3, f2, f1, _ = self.coefficients
        s3 = self.s3() if s3 is None else s3
        return f3 * self.d(s3) - 3 * (self.d(f3) + f1 * f3 - f2**2 / 3) * s3

    def J(self) -> sp.Expr:
        s3 = self.s3()
        return self.s5(s3) ** 3 / s3**5

    def transformed(self, P: sp.Expr, Q: sp.Expr, dtau_dt: sp.Expr) -> "Abel":
        """The equation for u, where y = P u + Q and the new variable τ has dτ/dt = ``dtau_dt``."""
        f3, f2, f1, f0 = self.coefficients
        new = (
            f3 * P**2,
            P * (3 * f3 * Q + f2),
            3 * f3 * Q**2 + 2 * f2 * Q + f1 - self.d(P) / P,
            (f3 * Q**3 + f2 * Q**2 + f1 * Q + f0 - self.d(Q)) / P,
        )
        return Abel(*(coef / dtau_dt for coef in new), x=self.x, rate=self.rate * dtau_dt)

    def normal_form_shift(self) -> sp.Expr:
        """Q = −f₂/(3f₃): removes the u² term."""
        return -self.f2 / (3 * self.f3)

    def normal_form_log_scale_rate(self) -> sp.Expr:
        """d(ln P)/dt = f₁ − f₂²/(3f₃): removes the u term."""
        return self.f1 - self.f2**2 / (3 * self.f3)

    def normal_form(self, P: sp.Expr) -> "Abel":
        """The normal form du/dτ = u³ + I, given P with d(ln P)/dt = f₁ − f₂²/(3f₃).

        P is asked for, not computed: it is the one integral of the reduction.
        """
        return self.transformed(P, self.normal_form_shift(), self.f3 * P**2)

    def invariant_I(self, P: sp.Expr) -> sp.Expr:
        """I = s₃/(f₃P)³: the normal form's coefficient through the invariant s₃."""
        return self.s3() / (self.f3 * P) ** 3
