"""The table of symbols: every symbol a display of the appendix uses, defined once.

The paper's symbols are defined here in words (their meaning, with the
paper's section); the quantities the package names for a check (labels,
`derivation.symbols.label`) define themselves by their label's text.  A
displayed symbol with no definition stops the generation (`undefined`), so
the table cannot fall behind the displays.  Where the paper uses one letter
for two things (t₁ in n°2 and n°7) the entry says so.
"""

from __future__ import annotations

import re

import sympy as sp

from derivation.symbols import LABEL_TEX
from paper.latex_text import tex_text

# (SymPy names, accents stripped; Unicode prose, set by `tex_text`), in the paper's order.
MEANINGS = [
    (("R",), "radius of the ball (n°2)"),
    (("k",), "radius of gyration: mk² is the moment of inertia about a diameter (n°2); k² = 2R²/5 for a solid ball"),
    (("m",), "mass of the ball (in Δ_{m,n}, normal.tau_series, m and n count the terms of F₁'s double series)"),
    (("g",), "acceleration of gravity"),
    (("f",), "coefficient of sliding friction: the friction force is fmg while the ball slides (n°2)"),
    (("delta",), "coefficient of rolling friction, a length: the rolling couple is δmg, opposite Ω (n°2); (9) is δ < fR"),
    (("epsilon",), "coefficient of pivoting friction, a length: the pivot couple is εmg, opposite r (n°2)"),
    (("t",), "time"),
    (("xi", "eta"), "coordinates of the centre G on the cloth, the plane ξOη; Oζ points up (n°2)"),
    (("p", "q", "r"), "components of the rotation ω of the ball along axes through G parallel to Oξ, Oη, Oζ (n°2); "
                      "r is the pivoting"),
    (("r_0",), "r at t = 0"),
    (("s_r",), "the sign of r (±1): the paper's ± in (5), and in its dT, is −s_r"),
    (("u", "v", "w"), "velocity of the ball's material point at the contact A (eqs. (1), (2)); in the normal form "
                      "(beyond n°11) u is the new unknown of z = P u + Q, and w = (1 + sin θ)/2 the variable of τ's "
                      "F₁ form"),
    (("V", "alpha"), "speed V ≥ 0 and direction α (from Oξ) of the slip: u = V cos α, v = V sin α (eq. (1))"),
    (("Omega", "beta"), "size Ω ≥ 0 and direction β (from Oξ) of the horizontal projection of the rotation: "
                        "p = Ω cos β, q = Ω sin β (eq. (3))"),
    (("theta",), "θ = β − α, the angle of the rotation from the slip (n°9)"),
    (("V_0", "Omega_0", "alpha_0", "beta_0"), "the values at t = 0 (in n°7, at the start of pure rolling)"),
    (("n",), "normal reaction of the cloth (n°2); in Δ_{m,n} an index of F₁'s double series"),
    (("X", "Y", "Z"), "components of the sliding friction force F (n°2)"),
    (("L", "M", "N"), "components of the rolling couple H (n°2)"),
    (("f_1",), "friction of repose f₁mg, f₁ ≤ f: the friction force that rolling without sliding needs (n°7, eq. (10)); "
               "in inv.general, one of the coefficients f₃, f₂, f₁, f₀"),
    (("delta_1",), "couple of repose δ₁mg, δ₁ ≤ δ: the rolling couple that sliding without rolling would need (n°6)"),
    (("t_1",), "t₁ means two things in the paper: in n°2 the end of the pivot, t₁ = k²r₀/(εg); in n°7 the end of "
               "pure rolling, t₁ = Ω₀(R² + k²)/(δg), counted from its start"),
    (("rho",), "ρ = √(R² + k²) in the symmetry of n°2 (in n°7's printed form, ρ is the transcription's misreading of p)"),
    (("x", "y"), "x = fV, y = δΩ (n°9); in n°11, functions of φ"),
    (("x_0", "y_0"), "x and y at t = 0"),
    (("a", "b", "c"), "a = f²(1 + R²/k²)g, b = fRδg/k², c = δ²g/k²: constants, a > b > c > 0 under (9) (n°9)"),
    (("h",), "h = a/b (n°10)"),
    (("A", "C"), "the constants of n°10's integral y − x = A and closed form (this A is not the contact point A, "
                 "nor one of the Aᵢ; C is not c, nor C_τ)"),
    (("lambda",), "in n°11 the ratio y'/x', a known function of φ: λ = (b sin θ − c)/(b sin θ − a)"),
    (("z",), "z = x'/x = y/(x + y) = δΩ/(fV + δΩ), the unknown of the Abel equation (n°11)"),
    (("s",), "s = sin θ (not s_r, the sign of r, nor s₃ and s₅, the invariants)"),
    (("A_3",), "A₃, A₂, A₁, A₀: coefficients of the Abel equation dz/dθ = A₃z³ + A₂z² + A₁z + A₀ "
               "(n11.abel_theta); A₀ = 0"),
    (("f_3", "f_2", "f_0"), "with f₁, the coefficients of any Abel equation dz/dχ = f₃z³ + f₂z² + f₁z + f₀, "
                            "functions of χ (inv.general; f₁ is not the friction of repose there)"),
    (("P",), "z = P u + Q brings the Abel equation to its normal form du/dτ = u³ + I, with Q = −A₂/(3A₃), "
             "P = (1 + sin θ)^e₁ (1 − sin θ)^e₂ (a + c − 2b sin θ)^e₃ and dτ = A₃P² dθ"),
    (("s_3",), "s₃, s₅: the relative invariants of an Abel equation, defined from its coefficients in "
               "inv.general; J = s₅³/s₃⁵ its absolute invariant [Appell 1889, Cheb-Terrab & Roche 2000]"),
    (("gamma", "beta_1", "beta_2", "mu", "C_tau"), "the parameters of τ's F₁ form (normal.tau_F1): γ = 2e₁, "
                                                   "β₁ = 1 − 2e₂, β₂ = −1 − 2e₃ (F₁'s α, β, β′: α and β are the "
                                                   "paper's angles), μ = 4b/(a + c + 2b), and its constant C_τ"),
    (("tau",), "the variable of the normal form du/dτ = u³ + I (normal.form); in inv.general, the new variable "
               "of any change z = P u + Q, dτ = τ′ dχ, τ′ its rate"),
    (("chi",), "the variable of the Abel equations of inv.general (any functions of χ) and inv.general_numeric "
               "(seeded polynomials in χ)"),
]
# What no SymPy symbol of a display carries: notation, and the transcription's glyphs in the printed forms.
GENERAL = [
    (r"X',\ X''", "derivatives with respect to t, the paper's accents (in n°11, with respect to φ)"),
    (r"\varphi", "the variable of n°11: dφ = (tan θ − a/(b cos θ)) dθ"),
    (r"\left(x\right)_{n}", "the rising factorial x(x + 1)⋯(x + n − 1) (Pochhammer's symbol)"),
    (r"I", "the coefficient of the normal form du/dτ = u³ + I (beyond n°11)"),
    (r"\tilde s_3,\ \tilde s_5", "s₃ and s₅ of the Abel equation after a change z = P u + Q, dτ = τ′ dχ (inv.general)"),
    (r"\mathcal{F}", "the right-hand side of the Abel equation, dz/dθ = 𝓕(z) (inv.mirror)"),
    (r"F_1", "Appell's hypergeometric function of two variables [Appell 1880], in which τ(θ) is written"),
    (r"\nu,\ J_0,\ J_1,\ J_2", "ν = b/a = Rδ/(f(R² + k²)), small with δ; J = J₀ + J₁ν + J₂ν² + O(ν³) (inv.small_delta)"),
    (r"\sigma", "σ = −ln V, the variable the slide is integrated in (numerics)"),
    (r"T,\ G", "kinetic energy; the centre of the ball, Ġ its velocity, e_α the unit vector of angle α (not the exponents e₁, e₂, e₃ of P)"),
    (r"\partial,\ \hat c,\ \zeta,\ \rho,\ U,\ \dot\xi",
     "in a printed form: glyphs the transcription misread for δ, δ, ξ, p, V and ξ (see the errata)"),
]
LABEL_WIDTH = 45.0  # points: labels longer than this are expressions that read for themselves, not symbols


def _base(name: str) -> str:
    return name.rstrip("'")


def undefined(symbols: set[sp.Symbol]) -> list[str]:
    """The displayed symbols the table does not define (labels define themselves)."""
    defined = {name for names, _ in MEANINGS for name in names}
    return sorted({_base(s.name) for s in symbols if s.name not in LABEL_TEX} - defined)


def _label_entries(symbols) -> list[tuple[str, str]]:
    """The named quantities among ``symbols``, in their order (the appendix's: `appendix.displayed_symbols`)."""
    from paper.display import tex_width

    entries = {}
    for symbol in symbols:
        tex = LABEL_TEX.get(symbol.name)
        text = symbol.name[1:-1]
        # An expression (a − b, ∂q'/∂s_r) reads for itself; a bare name (J0) says nothing more.
        if tex is None or tex_width(tex) > LABEL_WIDTH or " " not in text or re.search(r"[-+=<>/]|\\(equiv|left|frac|cdot)", tex):
            continue
        entries.setdefault(tex, re.sub(r"^[^ ,]{1,6}, ", "", text))  # "2T, twice the kinetic energy": the symbol is shown
    return list(entries.items())


def notation_tex(symbols, heading, cite) -> str:
    """The table, under ``heading``: the paper's symbols the displays use, then the named quantities in the order
    of ``symbols`` (a set: sorted by name)."""
    symbols = sorted(symbols, key=str) if isinstance(symbols, (set, frozenset)) else list(symbols)
    from derivation.notation import latex

    missing = undefined(symbols)
    if missing:
        raise ValueError(f"symbols displayed without a definition in the notation table: {', '.join(missing)}")
    used = {_base(s.name) for s in symbols}
    items = [
        (",\\ ".join(latex(sp.Symbol(n)) for n in names), _with_citations(meaning, cite))
        for names, meaning in MEANINGS
        if used & set(names)
    ]
    items += [(tex, _with_citations(meaning, cite)) for tex, meaning in GENERAL]
    # A label written as one of the paper's symbols (τ, the variable of the normal form) is that symbol's
    # entry, not a second one (a referee found τ twice).
    listed = {tex for tex, _ in items}
    items += [(tex, tex_text(text)) for tex, text in _label_entries(symbols) if tex not in listed]
    body = "\n".join(rf"\item[${tex}$] {meaning}" for tex, meaning in items)
    intro = (
        "Symbols of the paper keep its letters; an entry gives the section where the paper defines it. "
        "Quantities the appendix names for a check are listed after them.\n"
    )
    return heading("Notation", "notation") + intro + "\\begin{appellnotation}\n" + body + "\n\\end{appellnotation}\n"


def _with_citations(meaning: str, cite) -> str:
    """Prose with [Appell 1889]-style references turned into the appendix's citations."""
    keys = {"Appell 1889": "appell1889", "Cheb-Terrab & Roche 2000": "chebterrab2000", "Appell 1880": "appell1880"}
    parts = re.split(r"\[([^\]]+)\]", meaning)
    out = []
    for i, part in enumerate(parts):
        if i % 2:
            out.append(", ".join(cite(keys[ref.strip()]) for ref in part.split(",")))
        else:
            out.append(tex_text(part))
    return "".join(out)
