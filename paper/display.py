"""A derived form in the paper's arrangement, laid out to fit a journal's column.

SymPy orders the terms of a sum and the factors of a product canonically: it
prints sin(α − β) where Appell writes sin(β − α), "n = gm" for "n = mg",
"η''m = Y" for "mη'' = Y".  The appendix shows every derived form as the paper
would write it, without changing what it is:

* `arrange` turns a derived SymPy form into an unevaluated tree in the paper's
  order, read off the printed LaTeX of the claim (quoted from the
  transcription): an angle difference the paper writes β − α is written so,
  sin(α − β) becoming −sin(β − α) (cos is even); the terms of a sum and the
  factors of a product follow where their symbols first occur in the printed
  LaTeX (numbers first).  Without printed LaTeX SymPy's order is kept.  Only
  the order changes, so the tree is the derived form itself.
* A claim may instead give an explicit ``display`` (`derivation.claim.Claim`),
  built unevaluated in the arrangement of choice; the claim's check proves it
  equal to the derived form.
* `DisplayPrinter` prints such a tree in its stored order (never re-evaluating
  it), through the paper's notation (`derivation.notation`).
* `layout` breaks a displayed relation into lines no wider than a column of a
  two-column journal (`COLUMN`), or of a one-column page (`ONE_COLUMN`), at
  the top-level terms of a sum (or of the one sum inside a product); what
  cannot be broken to fit a narrow column is reported as too long (the
  appendix then points to the machine-readable supplement).

Widths are estimated from the LaTeX (`tex_width`, in points at 10 pt type),
calibrated against TeX's own measurements of the appendix's displays; the
compiled host documents (`paper.latex_hosts`) fail on any overfull line, so an
estimate that is too small cannot go unnoticed.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass

import sympy as sp

from derivation.notation import PaperPrinter
from derivation.symbols import LABEL_TEX

# The narrowest column the appendix is compiled in (article, twocolumn, a4paper: 221 pt, 20 em at 11 pt type), less
# room for a tag and for the estimate (196 left a display 4 pt too wide at 11 pt); a continuation line is indented
# by \quad.
COLUMN = 190.0
# A line of a one-column page: at least 32 em (\appellwidewidth in the style file, 320 pt at 10 pt type; article's
# 345 pt, 11 pt's 360), less room for the estimate (one estimated within 320 pt was set 329 pt wide).  A display
# whose lines differ at the two widths is written at both, and the line it stands on picks (\appellwideornarrow).
ONE_COLUMN = 290.0
TAG_ROOM = 28.0
INDENT = 10.0
# Displays longer than this many lines go to the supplement rather than fill a column.
MAX_LINES = 8

# ---------------------------------------------------------------------------------------------
# Where the paper's glyphs stand in its printed LaTeX.

_IGNORED_COMMANDS = {
    "frac", "left", "right", "quad", "qquad", "cdot", "leq", "geq", "sqrt", "dfrac", "tfrac", "ldots", "dots",
    "infty", "cos", "sin", "tan", "log", "ln", "exp", "limits", "pi", "dot", "hat", "pm", "mp", "big", "Big",
}
_GROUPS = re.compile(r"\\(begin|end|operatorname|text|mathrm)\{[^{}]*\}")
_GLYPH = re.compile(r"(\\[a-zA-Z]+|[a-zA-Z])((?:_(?:\{[^{}]*\}|\\?[a-zA-Z0-9]))?)('*)")
_SAME = {"\\epsilon": "\\varepsilon", "\\phi": "\\varphi"}


def _normal(base: str, sub: str, primes: str) -> str:
    sub = sub.replace("{", "").replace("}", "").replace(" ", "")
    return _SAME.get(base, base) + sub + primes


def _glyphs(tex: str) -> list[tuple[int, str, str]]:
    """(position, glyph with subscript and primes, bare glyph) for each letter of a LaTeX formula."""
    tex = _GROUPS.sub(lambda m: " " * len(m.group(0)), tex)
    found = []
    for m in _GLYPH.finditer(tex):
        base = m.group(1)
        if base.startswith("\\") and base[1:] in _IGNORED_COMMANDS:
            continue
        found.append((m.start(), _normal(base, m.group(2), m.group(3)), _SAME.get(base, base)))
    return found


def _math_of(printed_tex: str) -> str:
    """The formulas of a printed text: all of it, or for a sentence of the paper its $…$ parts
    (the words blanked, so that positions stay those of the printed text)."""
    from derivation import transcription

    if "$" not in printed_tex and not transcription.is_prose(printed_tex):
        return printed_tex
    parts = re.split(r"(\$[^$]*\$)", printed_tex)
    return "".join(p if p.startswith("$") else " " * len(p) for p in parts)


@dataclass(frozen=True)
class Arrangement:
    """How the printed LaTeX orders the paper's glyphs: the first position of each, and the
    differences it writes (β − α: the pair ("\\beta", "\\alpha"))."""

    tex: str  # the printed formulas, words blanked
    first: dict
    bare: dict
    differences: frozenset
    neighbours: frozenset  # (g₁, g₂): the paper writes g₁ immediately before g₂ in a product

    @classmethod
    def of(cls, printed_tex: str | None) -> "Arrangement | None":
        if not printed_tex:
            return None
        tex = _math_of(printed_tex)
        first, bare, neighbours = {}, {}, set()
        found = _glyphs(tex)
        for position, glyph, base in found:
            first.setdefault(glyph, position)
            bare.setdefault(base, position)
        for (p1, g1, b1), (p2, g2, b2) in zip(found, found[1:]):
            between = tex[p1:p2]
            if re.fullmatch(r"(\\[a-zA-Z]+|[a-zA-Z])(_(\{[^{}]*\}|\\?\w))?'*(\^(\{[^{}]*\}|\w))?\s*", between):
                neighbours.add((b1, b2))
        pairs = set()
        term = r"(\\[a-zA-Z]+|[a-zA-Z])((?:_(?:\{[^{}]*\}|[a-zA-Z0-9]))?)('*)"
        for m in re.finditer(r"(?<![a-zA-Z\\}'])" + term + r"\s*-\s*" + term + r"(?![a-zA-Z\\{^_'])", tex):
            left, right = _normal(*m.group(1, 2, 3)), _normal(*m.group(4, 5, 6))
            if not set(m.group(1, 4)) & {"\\" + c for c in _IGNORED_COMMANDS}:
                pairs.add((left, right))
        return cls(tex, first, bare, frozenset(pairs), frozenset(neighbours))

    def number_position(self, number_tex: str) -> float:
        """Where a number (as the display prints it: 1, \\frac{\\pi}{4}) stands alone in the printed LaTeX."""
        compact = lambda tex: re.sub(r"\s+", "", tex)  # noqa: E731
        printed, number = compact(self.tex), compact(number_tex)
        for m in re.finditer(re.escape(number), printed):
            if not re.match(r"[\w{^]", printed[m.end() : m.end() + 1]) and not re.search(r"[\w^_]$", printed[: m.start()]):
                return m.start()
        return math.inf

    def position(self, symbol: sp.Symbol) -> float:
        """Where the symbol's glyph first stands in the printed LaTeX (its bare letter if it is not
        there with its accents); infinity when the paper does not write it here."""
        glyph = glyph_of(symbol)
        if glyph in self.first:
            return self.first[glyph]
        return self.bare.get(_bare(glyph), math.inf)


_PAPER = PaperPrinter({"mul_symbol": None})


def _bare(glyph: str) -> str:
    return re.sub(r"('+|_.*)$", "", glyph)


def glyph_of(symbol: sp.Symbol) -> str:
    """A symbol's glyph as `Arrangement` names them (\\Omega_0, V', s_r); a label by its first glyph."""
    tex = LABEL_TEX.get(symbol.name) or _PAPER.doprint(symbol)
    found = _glyphs(tex)
    return found[0][1] if found else tex


# ---------------------------------------------------------------------------------------------
# Arranging a derived form.

_ODD = (sp.sin, sp.tan)
_EVEN = (sp.cos,)


def arrange(form: sp.Basic, arrangement: Arrangement | None) -> sp.Basic:
    """The form as an unevaluated tree in the paper's order (SymPy's when ``arrangement`` is None)."""
    if isinstance(form, sp.Rel):
        lhs, rhs = (_signed(*_arrange(side, arrangement)) for side in (form.lhs, form.rhs))
        return form.func(lhs, rhs, evaluate=False)
    return _signed(*_arrange(form, arrangement))


def _signed(sign: int, node: sp.Basic) -> sp.Basic:
    return node if sign > 0 else sp.Mul(sp.Integer(-1), node, evaluate=False)


def _arrange(expr: sp.Basic, arr: Arrangement | None) -> tuple[int, sp.Basic]:
    """(sign, tree) with expr = sign · tree; the sign comes out of an angle difference turned round."""
    if not expr.args or isinstance(expr, sp.Number):
        return 1, expr
    if isinstance(expr, sp.Add):
        flipped = _difference(expr, arr)
        if flipped is not None:
            return flipped
        terms = _ordered(expr.as_ordered_terms(), arr, _term_key)
        return 1, sp.Add(*[_signed(*_arrange(t, arr)) for t in terms], evaluate=False)
    if isinstance(expr, sp.Mul):
        coefficient, rest = expr.as_coeff_Mul()
        sign, factors = 1, []
        for factor in _ordered(list(sp.Mul.make_args(rest)), arr, _factor_key, _adjacent):
            s, node = _arrange(factor, arr)
            sign *= s
            factors.append(node)
        coefficient = coefficient * sign  # numbers: evaluated, whatever the tree around them
        if coefficient == 1 and len(factors) == 1:
            return 1, factors[0]
        lead = [] if coefficient == 1 else [sp.Integer(-1)] if coefficient == -1 else [coefficient]
        return 1, sp.Mul(*lead, *factors, evaluate=False)
    if isinstance(expr, sp.Pow):
        sign, base = _arrange(expr.base, arr)
        exp = _signed(*_arrange(expr.exp, arr))
        if sign < 0 and not (expr.exp.is_integer and expr.exp.is_number):
            return 1, sp.Pow(_signed(sign, base), exp, evaluate=False)
        return (-1 if sign < 0 and int(expr.exp) % 2 else 1), sp.Pow(base, exp, evaluate=False)
    if isinstance(expr, sp.Function) and len(expr.args) == 1 and isinstance(expr, _ODD + _EVEN):
        sign, arg = _arrange(expr.args[0], arr)
        outer = sign if isinstance(expr, _ODD) else 1
        return outer, expr.func(arg, evaluate=False)
    try:
        return 1, expr.func(*[_signed(*_arrange(a, arr)) for a in expr.args], evaluate=False)
    except TypeError:  # a node that cannot be built unevaluated is shown as SymPy has it
        return 1, expr


def _difference(expr: sp.Add, arr: Arrangement | None) -> tuple[int, sp.Basic] | None:
    """P − Q written as the paper writes it (Q − P turned round), for two symbols P and Q."""
    if arr is None or len(expr.args) != 2:
        return None
    plus = [t for t in expr.args if t.is_Symbol]
    minus = [-t for t in expr.args if (-t).is_Symbol]
    if len(plus) != 1 or len(minus) != 1:
        return None
    p, q = plus[0], minus[0]
    if (glyph_of(p), glyph_of(q)) in arr.differences:
        return 1, sp.Add(p, sp.Mul(-1, q, evaluate=False), evaluate=False)
    if (glyph_of(q), glyph_of(p)) in arr.differences:
        return -1, sp.Add(q, sp.Mul(-1, p, evaluate=False), evaluate=False)
    return None


def _positions(expr: sp.Basic, arr: Arrangement) -> list[float]:
    return sorted(arr.position(s) for s in expr.free_symbols)


def _term_key(term: sp.Basic, arr: Arrangement) -> tuple:
    """A term goes where its last-introduced symbol stands: in fV₀ − δΩ₀ − [..] g t, the term in
    V₀ before the one in Ω₀ before the one in t, though f comes first in all of them.  A number
    goes where the paper writes it (1 + R²/k², θ/2 + π/4), else last."""
    if term.is_number:
        return (arr.number_position(display_tex(arrange(term, None))), 0)
    known = [p for p in _positions(term, arr) if p < math.inf]
    return (known[-1] if known else math.inf, len(known))


def _factor_key(factor: sp.Basic, arr: Arrangement) -> tuple:
    """Numbers, then letters by where the paper first writes them, then sin and cos, then sums
    (the paper's fg(1 + R²/k²) cos α, 2RΩV sin(β − α), k²(r − r₀))."""
    if factor.is_number:
        return (0,)
    known = _positions(factor, arr)
    rank = 3 if isinstance(factor, sp.Add) or (isinstance(factor, sp.Pow) and isinstance(factor.base, sp.Add)) \
        else 2 if isinstance(factor, sp.Function) or (isinstance(factor, sp.Pow) and isinstance(factor.base, sp.Function)) \
        else 1
    return (rank, known[0] if known else math.inf)


def _adjacent(left: sp.Basic, right: sp.Basic, arr: Arrangement) -> int:
    """-1 when the paper writes ``left`` right before ``right`` somewhere (the RY of mk²p' = RY + L,
    although Y first stands in mη'' = Y), 1 for the reverse, 0 when it never writes them side by side."""
    letters = [x.base if x.is_Pow else x for x in (left, right)]
    if not all(x.is_Symbol for x in letters):
        return 0
    a, b = (_bare(glyph_of(x)) for x in letters)
    if (a, b) in arr.neighbours:
        return -1
    if (b, a) in arr.neighbours:
        return 1
    return 0


def _ordered(items: list, arr: Arrangement | None, key, adjacent=None) -> list:
    """Sorted by ``key`` (stable, so SymPy's order decides ties), two letters the paper writes
    side by side in its order; SymPy's order without an arrangement."""
    if arr is None:
        return items
    items = sorted(items, key=lambda item: key(item, arr))
    if adjacent is None:
        return items
    # Adjacent swaps only, between neighbours of equal rank: the order stays that of the key elsewhere.
    for _ in range(len(items)):
        for i in range(len(items) - 1):
            same_rank = key(items[i], arr)[0] == key(items[i + 1], arr)[0]
            if same_rank and adjacent(items[i], items[i + 1], arr) > 0:
                items[i], items[i + 1] = items[i + 1], items[i]
    return items


# ---------------------------------------------------------------------------------------------
# Printing a tree in its stored order.


def _negative(node: sp.Basic) -> tuple[bool, sp.Basic]:
    """(is it −X, X) for a negative number or a product led by one, without evaluating anything."""
    if isinstance(node, sp.Number) and node < 0:
        return True, -node
    if isinstance(node, sp.Mul) and node.args:
        neg, first = _negative(node.args[0])
        if neg:
            rest = ([first] if first != 1 else []) + list(node.args[1:])
            return True, rest[0] if len(rest) == 1 else sp.Mul(*rest, evaluate=False)
    return False, node


class DisplayPrinter(PaperPrinter):
    """The paper's notation, printing sums and products in the order they are stored.

    A product nested in a product keeps its own fraction (the paper's (Rδ/k²) g sin(β − α)); a
    product of one level puts every denominator under one fraction bar, as SymPy does.
    """

    def __init__(self):
        super().__init__({"mul_symbol": None, "order": "none"})

    def _print_Add(self, expr, order=None):
        out = ""
        for i, term in enumerate(_terms(expr)):
            negative, magnitude = _negative(term)
            body = self._print(magnitude)
            if isinstance(magnitude, sp.Add):
                body = rf"\left({body}\right)"
            if i == 0:
                out = ("- " if negative else "") + body
            else:
                out += (" - " if negative else " + ") + body
        return out

    def _print_Mul(self, expr):
        negative, expr = _negative(expr)
        numerator, denominator = [], []
        self._collect(expr, numerator, denominator, top=True)
        top = self._product(numerator) or "1"
        body = top if not denominator else rf"\frac{{{top}}}{{{self._product(denominator)}}}"
        return ("- " if negative else "") + body

    def _collect(self, node, numerator: list, denominator: list, top: bool) -> None:
        if isinstance(node, sp.Mul) and (top or not _has_denominator(node)):
            for arg in node.args:
                self._collect(arg, numerator, denominator, top=False)
        elif isinstance(node, sp.Rational) and not isinstance(node, sp.Integer):
            if node.p != 1:
                numerator.insert(0, sp.Integer(node.p))
            denominator.insert(0, sp.Integer(node.q))
        elif isinstance(node, sp.Pow) and node.exp.is_number and node.exp.is_negative:
            denominator.append(node.base if node.exp == -1 else sp.Pow(node.base, -node.exp, evaluate=False))
        elif node != 1:
            numerator.append(node)

    def _product(self, factors: list) -> str:
        out, last = "", None
        for i, factor in enumerate(factors):
            tex = self._print(factor)
            negative, _ = _negative(factor)
            if (isinstance(factor, sp.Add) and len(factors) > 1) or (negative and i > 0):
                tex = rf"\left({tex}\right)"
            if out:
                out += r" \cdot " if isinstance(last, sp.Number) and isinstance(factor, sp.Number) else " "
            out += tex
            last = factor
        return out

    def _print_Pow(self, expr):
        if expr.exp.is_number and expr.exp.is_negative:
            return self._print_Mul(sp.Mul(expr, evaluate=False))
        if expr.exp == sp.S.Half:
            return rf"\sqrt{{{self._print(expr.base)}}}"
        return super()._print_Pow(expr)

    def _print_Function(self, expr, exp=None):
        # The paper's sin(β − α): plain parentheses round a compound argument of sin, cos, tan.
        if expr.func in (sp.sin, sp.cos, sp.tan) and not expr.args[0].is_Symbol:
            name = f"\\{expr.func.__name__}" + (f"^{{{exp}}}" if exp is not None else "")
            return f"{name}({self._print(expr.args[0])})"
        return super()._print_Function(expr, exp)


def _terms(node: sp.Add) -> list[sp.Basic]:
    """The terms of a sum, a sum nested in it without a sign opened: a − b + c built as (a − b) + c."""
    out = []
    for term in node.args:
        out += _terms(term) if isinstance(term, sp.Add) else [term]
    return out


def _has_denominator(node: sp.Mul) -> bool:
    return any(
        (isinstance(a, sp.Pow) and a.exp.is_number and a.exp.is_negative)
        or (isinstance(a, sp.Rational) and not isinstance(a, sp.Integer))
        for a in node.args
    )


_PRINTER = DisplayPrinter()


def display_tex(tree: sp.Basic) -> str:
    """LaTeX of an arranged (or explicitly built) tree, in its stored order."""
    return _PRINTER.doprint(tree)


# ---------------------------------------------------------------------------------------------
# Widths and lines.

# Widths of Computer Modern math italic at 10 pt (points), letters and the Greek the paper uses.
_LETTERS = dict(zip("abcdefghijklmnopqrstuvwxyz", (5.3, 4.3, 4.3, 5.2, 4.7, 5.4, 4.8, 5.8, 3.4, 4.1, 5.2, 3.0, 8.8,
                                                    6.0, 4.9, 5.0, 4.5, 4.5, 4.7, 3.6, 5.7, 4.9, 7.2, 5.7, 4.9, 4.7)))
_LETTERS.update(zip("ABCDEFGHIJKLMNOPQRSTUVWXYZ", (7.5, 7.6, 7.2, 8.3, 7.4, 6.4, 7.9, 8.3, 4.4, 5.5, 8.5, 6.8, 9.7,
                                                    8.0, 7.6, 6.4, 7.9, 7.6, 6.1, 5.8, 6.8, 5.8, 9.4, 8.3, 5.8, 6.8)))
_GREEK_WIDTHS = {"alpha": 6.4, "beta": 5.7, "gamma": 5.2, "delta": 4.4, "epsilon": 4.1, "varepsilon": 4.7, "zeta": 4.4,
                 "eta": 5.0, "theta": 4.7, "kappa": 5.8, "lambda": 5.8, "mu": 6.0, "nu": 5.1, "xi": 4.5, "pi": 5.7,
                 "rho": 5.2, "sigma": 5.7, "tau": 4.4, "varphi": 6.5, "phi": 5.9, "psi": 6.5, "omega": 6.2,
                 "Omega": 7.2, "Delta": 8.3, "Sigma": 7.2, "Phi": 7.2, "ell": 4.2}
_DIGIT = 5.0
_BINARY, _RELATION = 12.2, 13.4
_WIDE_COMMANDS = {  # width in pt at 10 pt
    "sin": 14.5, "cos": 14.5, "tan": 14.5, "ln": 10.0, "log": 14.0, "exp": 15.0, "max": 17.0, "min": 15.5,
    "quad": 10.0, "qquad": 20.0, ",": 1.7, ";": 2.8, ":": 2.2, "!": -1.7, "cdot": 7.8, "times": 12.2,
    "leq": _RELATION, "geq": _RELATION, "equiv": _RELATION, "to": _RELATION, "mapsto": _RELATION,
    "propto": _RELATION, "approx": _RELATION, "neq": _RELATION, "leftrightarrow": _RELATION + 4,
    "partial": 5.7, "infty": 10.0, "ldots": 13.0, "dots": 13.0, "cdots": 13.0, "pm": _BINARY, "mp": _BINARY,
    "left": 0.0, "right": 0.0, "bigl": 0.0, "bigr": 0.0, "Bigl": 0.0, "Bigr": 0.0, "big": 0.0, "Big": 0.0,
    "#": 8.3, "{": 5.0, "}": 5.0, "|": 2.8, "max_": 17.0,
}
_ACCENTS = {"dot", "hat", "tilde", "bar", "mathbf", "mathcal", "mathrm", "boldsymbol", "vec", "operatorname", "text"}


def tex_width(tex: str) -> float:
    """Estimated width (pt at 10 pt type) of a line of display maths: the widest of its lines
    when it has several (\\\\), alignment marks ignored."""
    return max(_width(_Tokens(line)) for line in re.split(r"\\\\", tex))


class _Tokens:
    def __init__(self, tex: str):
        self.items = re.findall(r"\\[a-zA-Z]+|\\.|[{}^_]|[^\s]", _GROUPS_ENV.sub(" ", tex))
        self.i = 0

    def next(self):
        self.i += 1
        return self.items[self.i - 1]

    def more(self) -> bool:
        return self.i < len(self.items) and self.items[self.i] != "}"


_GROUPS_ENV = re.compile(r"\\(begin|end)\{[^{}]*\}|&")


def _group(tokens: _Tokens, scale: float = 1.0) -> float:
    """The width of the next argument: a {…} group or a single token."""
    if tokens.i >= len(tokens.items):
        return 0.0
    if tokens.items[tokens.i] == "{":
        tokens.next()
        width = _width(tokens, scale)
        if tokens.i < len(tokens.items):
            tokens.next()  # the closing brace
        return width
    return _width(_Tokens(tokens.next()), scale)


def _width(tokens: _Tokens, scale: float = 1.0) -> float:
    width, previous = 0.0, None
    while tokens.more():
        token = tokens.next()
        if token == "{":
            tokens.i -= 1
            width += _group(tokens, scale)
        elif token in ("^", "_"):
            width += _group(tokens, scale * 0.72)
        elif token == "\\frac":
            inner = 0.85 if scale < 1 or previous == "frac" else 1.0
            width += max(_group(tokens, scale * inner), _group(tokens, scale * inner)) + 2.4 * scale
        elif token == "\\sqrt":
            width += _group(tokens, scale) + 8.5 * scale
        elif token[1:] in _ACCENTS:
            text = token[1:] in ("text", "mathrm", "operatorname")
            width += _group(tokens, scale * (0.86 if text else 1.0)) + (1.0 if token == "\\mathbf" else 0.0)
        elif token.startswith("\\") and token[1:] in _WIDE_COMMANDS:
            width += _WIDE_COMMANDS[token[1:]] * scale
            if token[1:] in ("left", "right", "bigl", "bigr", "Bigl", "Bigr", "big", "Big") and tokens.i < len(tokens.items):
                delimiter = tokens.next()
                if delimiter != ".":
                    tall = token[1:] in ("left", "right") and _encloses_fraction(tokens, token == "\\left")
                    width += (7.2 if tall else 4.2 if token[1:] in ("left", "right") else 4.6) * scale
        elif token.startswith("\\"):
            width += _GREEK_WIDTHS.get(token[1:], 7.0) * scale  # a Greek letter, or another symbol
        elif token in "+-":
            width += (_BINARY if previous not in (None, "(", "[", "=", "rel") else 7.8) * scale
        elif token in "=<>":
            width += _RELATION * scale
            token = "rel"
        elif token in "()[]|":
            width += 3.9 * scale
        elif token == ",":
            width += 4.4 * scale
        elif token == "'":
            width += 2.8 * scale
        elif token.isdigit() or token == ".":
            width += _DIGIT * scale
        else:
            width += _LETTERS.get(token, 5.5) * scale
        previous = token[1:] if token.startswith("\\") else token
    return width


def _encloses_fraction(tokens: _Tokens, opening: bool) -> bool:
    """Whether the \\left … \\right pair at the current token holds a fraction (its delimiters grow)."""
    step, depth, i = (1, 0, tokens.i) if opening else (-1, 0, tokens.i - 3)
    while 0 <= i < len(tokens.items):
        item = tokens.items[i]
        if item == ("\\left" if opening else "\\right"):
            depth += 1
        elif item == ("\\right" if opening else "\\left"):
            if depth == 0:
                return False
            depth -= 1
        elif item in ("\\frac", "\\sqrt", "\\sum", "\\int"):
            return True
        i += step
    return False


@dataclass(frozen=True)
class Lines:
    """A display laid out: its lines (LaTeX, ``&`` before the first relation), or None when it
    cannot be broken to fit the column."""

    lines: list[str] | None
    width: float  # of its widest piece


def relation_pieces(tree: sp.Basic) -> list[str]:
    """The pieces a displayed relation may break between: its left side with the relation and the
    first term, then each further term with its sign.  A sum inside a product (g(a + b)/k²) is
    opened as \\frac{g}{k^2}\\Bigl(a + b\\Bigr) when that is what lets it break."""
    if not isinstance(tree, sp.Rel):
        return _side_pieces(tree)
    lhs = display_tex(tree.lhs)
    relation = {"==": "=", "<": "<", "<=": r"\leq", ">": ">", ">=": r"\geq", "!=": r"\neq"}[tree.rel_op]
    pieces = _side_pieces(tree.rhs, COLUMN - tex_width(f"{lhs} {relation}"))
    return [f"{lhs} &{relation} {pieces[0]}"] + pieces[1:]


def _side_pieces(node: sp.Basic, room: float = COLUMN - INDENT) -> list[str]:
    """The terms of a side as break points; a product too wide for ``room`` is opened round its sum."""
    if isinstance(node, sp.Add):
        pieces = []
        for i, term in enumerate(_terms(node)):
            negative, magnitude = _negative(term)
            body = display_tex(magnitude)
            if isinstance(magnitude, sp.Add):
                body = rf"\left({body}\right)"
            pieces.append((("- " if negative else "") if i == 0 else ("- " if negative else "+ ")) + body)
        return pieces
    whole = display_tex(node)
    opened = _opened_product(node)
    if opened is None or tex_width(whole) <= room:
        return [whole]
    return opened


def _opened_product(node: sp.Basic) -> list[str] | None:
    """A product with one sum among its factors, as 'outside \\Bigl( t₁', '+ t₂', …, '+ tₙ\\Bigr)'."""
    negative, body = _negative(node)
    if not isinstance(body, sp.Mul):
        return None
    numerator, denominator = [], []
    _PRINTER._collect(body, numerator, denominator, top=True)
    sums = [f for f in numerator if isinstance(f, sp.Add)]
    if not sums:
        return None
    widest = max(sums, key=lambda f: tex_width(display_tex(f)))  # (a − c)(9b² − …): open the long one
    sums = [widest]
    others = [f for f in numerator if f is not widest]
    outside = _PRINTER._product(others) or "1"
    if denominator:
        outside = rf"\frac{{{outside}}}{{{_PRINTER._product(denominator)}}}"
    elif outside == "1":
        outside = ""
    terms = _side_pieces(sums[0])
    terms[0] = ("- " if negative else "") + outside + r" \Bigl(" + terms[0]
    terms[-1] += r"\Bigr)"
    return terms


def layout(pieces: list[str], budget: float = COLUMN) -> Lines:
    """Pieces packed greedily into lines of at most ``budget`` points.  Continuation lines are aligned
    after the left side (``&\\quad + …``), so they have the room the left side leaves; when the left
    side takes much of the line, it stands alone (``&lhs = \\\\ &\\qquad …``) and the right side gets the
    whole width.  None when a piece alone is too wide, or the lines are too many."""
    widest = max(tex_width(p) for p in pieces)
    lhs, _, first = pieces[0].partition("&")
    lhs_width = tex_width(lhs) if first else 0.0
    lines = _packed_lines(pieces, budget, budget - lhs_width - INDENT)
    if lines is not None:
        return Lines([lines[0]] + [r"&\quad " + line for line in lines[1:]], widest)
    if not first:
        return Lines(None, widest)
    relation, _, term = first.strip().partition(" ")
    lines = _packed_lines([term] + pieces[1:] if term else pieces[1:], budget - 2 * INDENT, budget - 2 * INDENT)
    if lines is None:
        return Lines(None, widest)
    return Lines([f"&{lhs.strip()} {relation}"] + [r"&\qquad " + line for line in lines], widest)


def _packed_lines(pieces: list[str], first_room: float, room: float) -> list[str] | None:
    """Greedy packing: the first line within ``first_room``, the others within ``room``."""
    lines, current = [], ""
    for piece in pieces:
        candidate = f"{current} {piece}".strip()
        if current and tex_width(candidate) > (room if lines else first_room):
            lines.append(current)
            current = piece
        else:
            current = candidate
    lines.append(current)
    if any(tex_width(line) > (room if i else first_room) for i, line in enumerate(lines)) or len(lines) > MAX_LINES:
        return None
    return lines
