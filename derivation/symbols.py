"""The paper's symbols, with the assumptions the paper makes about them (n°2, n°5).

Two kinds of names live here:

* constants of a shot: R, k, m, g, f, delta, epsilon and initial values;
* functions of the time t (xi, eta, p, q, r, V, Omega, alpha, beta, ...),
  used while deriving.  A claim never holds functions: `snapshot` turns
  every f(t) and every derivative f'(t), f''(t) into a plain symbol named
  ``f``, ``f'``, ``f''`` so that claims can be sampled at random points.
"""

from __future__ import annotations

import sympy as sp

# The same time symbol as sympy.physics.mechanics (dynamicsymbols._t), so both routes share it.
t = sp.Symbol("t")

# Constants of the ball and the cloth (n°2): radius, radius of gyration,
# mass, gravity, sliding coefficient f, rolling and pivoting lengths.
R, k, m, g, f = sp.symbols("R k m g f", positive=True)
delta, epsilon = sp.symbols("delta epsilon", positive=True)
# delta_1, f_1: the rolling couple and the friction force of "repose" (n°6, n°7).
delta_1, f_1 = sp.symbols("delta_1 f_1", nonnegative=True)

# Initial values (subscript 0 as in the paper).
V_0, Omega_0 = sp.symbols("V_0 Omega_0", positive=True)
alpha_0, beta_0 = sp.symbols("alpha_0 beta_0", real=True)
r_0 = sp.Symbol("r_0", positive=True)

# Functions of t.  The sliding speed V and the horizontal rotation Omega are
# magnitudes, positive while the phase of n°8 lasts.
xi, eta, zeta = (sp.Function(n, real=True)(t) for n in ("xi", "eta", "zeta"))
p, q, r = (sp.Function(n, real=True)(t) for n in ("p", "q", "r"))
u, v, w = (sp.Function(n, real=True)(t) for n in ("u", "v", "w"))
V, Omega = (sp.Function(n, positive=True)(t) for n in ("V", "Omega"))
alpha, beta = (sp.Function(n, real=True)(t) for n in ("alpha", "beta"))

# theta = beta - alpha (n°9) appears as soon as (7) and (8) are written.
theta = sp.Symbol("theta", real=True)

TIME_FUNCTIONS = (xi, eta, zeta, p, q, r, u, v, w, V, Omega, alpha, beta)


# The LaTeX of each label, by symbol name (the printer in `notation` reads it).
LABEL_TEX: dict[str, str] = {}


def label(text: str, tex: str) -> sp.Symbol:
    """A named quantity that is not one of the paper's symbols ("[dT/dt]").

    It stands on the left of a claim whose right-hand side is a computed value;
    ``tex`` is how the appendix writes it.
    """
    name = f"[{text}]"
    if LABEL_TEX.setdefault(name, tex) != tex:
        raise ValueError(f"label {text!r} already written {LABEL_TEX[name]!r}")
    return sp.Symbol(name, real=True)


def d(expr: sp.Expr, n: int = 1) -> sp.Expr:
    """The paper's accent: ``d(xi)`` is xi', ``d(xi, 2)`` is xi''."""
    return sp.diff(expr, t, n)


def snapshot_symbol(fn: sp.Expr, order: int = 0) -> sp.Symbol:
    """The plain symbol standing for ``fn`` differentiated ``order`` times.

    Only the function itself keeps its sign (V > 0); a derivative has none a priori.
    """
    name = fn.func.__name__ + "'" * order
    if order == 0 and fn.is_positive:
        return sp.Symbol(name, positive=True)
    return sp.Symbol(name, real=True)


def accent(fn: sp.Expr, n: int = 1) -> sp.Symbol:
    """The paper's fn', fn'' as the symbol a claim holds, for forms built unevaluated (a claim's
    display), where `d` cannot run: differentiating needs evaluation."""
    return snapshot_symbol(fn, n)


def snapshot(expr):
    """Replace every function of one variable, and every derivative of one, by a plain symbol.

    Works on expressions, matrices and relations.  Derivatives go first, so
    that xi'' becomes the symbol ``xi''`` and not the derivative of a symbol.
    The accent means the derivative in the function's own variable: t in
    n°2–n°9, φ in n°11, as in the paper.
    """
    expr = sp.sympify(expr)
    rep = {}
    for dv in expr.atoms(sp.Derivative):
        (var, n), = dv.variable_count
        if not _is_function_of_one_symbol(dv.expr) or dv.expr.args != (var,):
            raise ValueError(f"cannot snapshot {dv}")
        rep[dv] = snapshot_symbol(dv.expr, n)
    expr = expr.xreplace(rep)
    return expr.xreplace({fn: snapshot_symbol(fn) for fn in expr.atoms(sp.Function) if _is_function_of_one_symbol(fn)})


def _is_function_of_one_symbol(fn: sp.Expr) -> bool:
    return isinstance(fn.func, sp.core.function.UndefinedFunction) and len(fn.args) == 1 and fn.args[0].is_Symbol


# Glyphs the OCR put in place of the paper's letters (design notes).  A printed
# form is read literally, with these in it, so that its erratum shows; the
# erratum then maps each glyph back to the letter meant.
ocr_dot_xi, ocr_dot_eta = (sp.Function(n, real=True)(t) for n in ("dotxi", "doteta"))
ocr_rho = sp.Function("rho", real=True)(t)  # ρ' printed for p'
ocr_U = sp.Function("U", positive=True)(t)  # U printed for V
ocr_partial = sp.Symbol("partial", positive=True)  # ∂ printed for δ
ocr_hat_c = sp.Symbol("hat_c", positive=True)  # ĉ printed for δ

# How each glyph stands in the transcription, so that a correction can be
# shown as the printed LaTeX with the glyph replaced, and nothing else.
OCR_GLYPH_TEX = {
    ocr_dot_xi: r"\dot{\xi}",
    ocr_dot_eta: r"\dot{\eta}",
    zeta: r"\zeta",
    ocr_rho: r"\rho",
    ocr_U: "U",
    ocr_partial: r"\partial",
    ocr_hat_c: r"\hat{c}",
}
