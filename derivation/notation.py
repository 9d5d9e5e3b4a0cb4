"""The paper's notation in LaTeX: the one printer every generated equation goes through.

Accents are primes (ξ', Ω''), as in the paper; Greek names print as Greek
letters (ε as the paper's \varepsilon); sin and cos take no parentheses around
a single symbol (sin α).
"""

from __future__ import annotations

import sympy as sp
from sympy.printing.latex import LatexPrinter

from derivation.symbols import LABEL_TEX, OCR_GLYPH_TEX

# By symbol name (a glyph function's snapshot symbol carries the function's name); ζ and ρ are letters anyway.
GLYPH_TEX = {getattr(g, "name", None) or g.func.__name__: tex for g, tex in OCR_GLYPH_TEX.items() if tex.startswith(("\\dot", "\\hat", "\\partial"))}


class PaperPrinter(LatexPrinter):
    def _print_Symbol(self, expr: sp.Symbol, style: str = "plain") -> str:
        name = expr.name
        if name in LABEL_TEX:
            return LABEL_TEX[name]
        base = name.rstrip("'")
        if base == "epsilon":  # the paper's glyph, ε, not ϵ
            return r"\varepsilon" + name[len(base) :]
        primes = name[len(base) :]
        if base in GLYPH_TEX:  # an OCR glyph prints as the transcription has it (∂, ĉ, ξ̇)
            return GLYPH_TEX[base] + primes
        if not primes:
            return super()._print_Symbol(expr, style)
        return super()._print_Symbol(sp.Symbol(base), style) + primes

    def _print_Function(self, expr, exp=None) -> str:
        # sin α rather than sin(α) when the argument is a single symbol.
        if expr.func in (sp.sin, sp.cos, sp.tan) and expr.args[0].is_Symbol:
            name = f"\\{expr.func.__name__}"
            if exp is not None:
                name += f"^{{{exp}}}"
            return f"{name} {self._print(expr.args[0])}"
        return super()._print_Function(expr, exp)


    def _print_appellf1(self, expr, exp=None) -> str:
        # Appell's own notation F₁(α; β, β′; γ; x, y), not SymPy's appellf1 with six commas.
        p = [self._print(arg) for arg in expr.args]
        tex = rf"F_1\left({p[0]}; {p[1]}, {p[2]}; {p[3]}; {p[4]}, {p[5]}\right)"
        return tex if exp is None else rf"\left[{tex}\right]^{{{exp}}}"

    def _print_RisingFactorial(self, expr, exp=None) -> str:
        # Pochhammer's (x)ₙ: SymPy's x^{(n)} reads as a power or a derivative.
        x, n = (self._print(arg) for arg in expr.args)
        tex = rf"\left({x}\right)_{{{n}}}"
        return tex if exp is None else rf"\left[{tex}\right]^{{{exp}}}"


_PRINTER = PaperPrinter({"mul_symbol": None})


def latex(expr) -> str:
    """LaTeX of a SymPy object, an equation or a list of them, in the paper's notation."""
    if isinstance(expr, (list, tuple)):
        return ", \\quad ".join(latex(e) for e in expr)
    return _PRINTER.doprint(expr)
