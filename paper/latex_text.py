"""Prose as LaTeX: the statements, reasons and captions, their words as text and their maths as maths.

The claims' statements are written in Unicode for the terminal ("V' < −fg under
δ < fR (9): V decreases and V − V₀ < −fgt").  Set as text, their maths would
come out upright, with "r_0", "V^κ" and "10^-200" printed literally.  So a
statement is cut into words and maths: a run of letters is maths when it holds
a Greek letter, an accent or an index, has no vowel (fR, fmg, dt, xy), or is a
single letter — but for the article "a" (or "A" opening a sentence) before a
word; numbers, operators and brackets join the maths they stand next to; a
bracket whose contents hold a word stays text, as do the paper's equation
numbers "(9)", its sections "n°8" and claim identifiers ("n8.V_decreases",
set in typewriter).  Within maths, ² and ₀ become ^{2} and _{0}, x^(α − 1) and
√(R² + k²) take their bracket as the group, and units (m/s, rad/s) are upright.

pdflatex reads bytes: a character with no LaTeX here is an error, not a blank.
"""

from __future__ import annotations

import re

# Text mode.
TEXT_MAP = {
    "–": "--", "—": "---", "’": "'", "‘": "`", "“": "``", "”": "''", "…": r"\dots{}", "°": r"\textsuperscript{o}",
    "é": r"\'e", "è": r"\`e", "à": r"\`a", "ç": r"\c{c}", "ê": r"\^e", "ô": r"\^o", "î": r"\^{\i}", "ù": r"\`u",
    "É": r"\'E", "ĳ": "ij", "ö": r"\"o", "ø": r"{\o}", "Ø": r"{\O}",
}
SPECIAL = {"&": r"\&", "%": r"\%", "$": r"\$", "#": r"\#", "_": r"\_", "{": r"\{", "}": r"\}", "~": r"\textasciitilde{}",
           "^": r"\textasciicircum{}", "\\": r"\textbackslash{}", "<": r"\textless{}", ">": r"\textgreater{}", "|": r"\textbar{}"}

# Math mode.
GREEK = {
    "α": r"\alpha", "β": r"\beta", "γ": r"\gamma", "δ": r"\delta", "ε": r"\varepsilon", "ζ": r"\zeta", "η": r"\eta",
    "θ": r"\theta", "κ": r"\kappa", "λ": r"\lambda", "μ": r"\mu", "ν": r"\nu", "ξ": r"\xi", "π": r"\pi", "ρ": r"\rho",
    "σ": r"\sigma", "τ": r"\tau", "φ": r"\varphi", "χ": r"\chi", "ψ": r"\psi", "ω": r"\omega", "Ω": r"\Omega", "Δ": r"\Delta",
    "Φ": r"\Phi", "Σ": r"\Sigma", "ℓ": r"\ell", "∂": r"\partial", "ĉ": r"\hat{c}", "𝓕": r"\mathcal{F}", "𝓛": r"\mathcal{L}", "𝓝": r"\mathcal{N}", "𝓡": r"\mathcal{R}",
}
OPERATORS = {
    "−": "-", "-": "-", "+": "+", "=": "=", "<": "<", ">": ">", "≤": r"\leq", "≥": r"\geq", "≠": r"\neq",
    "≈": r"\approx", "≡": r"\equiv", "∝": r"\propto", "→": r"\to", "↦": r"\mapsto", "↔": r"\leftrightarrow",
    "±": r"\pm", "∓": r"\mp", "×": r"\times", "·": r"\cdot", "/": "/", "∫": r"\int", "∈": r"\in", "∉": r"\notin",
    "⊂": r"\subset", "⊥": r"\perp", "∞": r"\infty", "∑": r"\sum", "∏": r"\prod", "½": r"\tfrac12", "|": "|", "*": "^{*}",
    "∀": r"\forall", "∃": r"\exists", "…": r"\dots", "⋯": r"\cdots", "'": "'", "′": "'",
}
SUPERSCRIPTS = {"²": "2", "³": "3", "⁴": "4", "⁵": "5", "⁶": "6", "⁷": "7", "⁸": "8", "⁹": "9", "¹": "1", "⁻": "-", "ᵏ": "k", "⁰": "0", "ⁿ": "n"}
SUBSCRIPTS = {"₀": "0", "₁": "1", "₂": "2", "₃": "3", "₄": "4", "₅": "5", "ᵢ": "i", "ₙ": "n", "ₘ": "m"}
FUNCTIONS = {"sin": r"\sin", "cos": r"\cos", "tan": r"\tan", "ln": r"\ln", "log": r"\log", "exp": r"\exp",
             "max": r"\max", "min": r"\min", "const": r"\mathrm{const}"}
UNITS = {"m/s": r"\,\mathrm{m/s}", "rad/s": r"\,\mathrm{rad/s}", "mm": r"\,\mathrm{mm}", "m/s²": r"\,\mathrm{m/s^2}"}
# Runs with a vowel that are maths, not words: a product of constants, a differential.
PRODUCTS = {"ac", "du"}
# Vowel-free runs that are English words.
WORDS = {"by", "my", "why", "try", "dry", "fly", "sky", "th", "st", "nd", "rd"}

_LETTER = r"A-Za-zÀ-ÖØ-öø-ÿĳ"
_GREEK = "".join(GREEK)
_MARKS = "".join(SUPERSCRIPTS) + "".join(SUBSCRIPTS) + "\u0307"
TOKEN = re.compile(
    rf"""(?P<section>n°\s?\d+(?:'s)?)
    |(?P<eqref>(?<![\w{_GREEK}])\(\d{{1,2}}\)(?![\w{_GREEK}]))
    |(?P<ident>[a-z][a-z0-9_]+(?:\.[A-Za-z][A-Za-z0-9_]*(?:-\d+)?)+)
    |(?P<possessive>'s(?![{_LETTER}]))
    |(?P<abbreviation>(?<![{_LETTER}])(?:i\.e\.|e\.g\.|cf\.))
    |(?P<unit>(?<![{_LETTER}])(?:rad/s|m/s²|m/s|mm)(?![{_LETTER}]))
    |(?P<word>[{_LETTER}]+(?:['’][{_LETTER}]+)+)
    |(?P<name>(?:[{_LETTER}{_GREEK}][{_MARKS}]*(?:'(?![{_LETTER}])|′)*)+)
    |(?P<sci>(?<![\w.])\d+(?:\.\d+)?e[-+]?\d+(?![\w.]))
    |(?P<number>\d+(?:\.\d+)?)
    |(?P<space>\s+)
    |(?P<other>.)""",
    re.VERBOSE,
)


class _Token:
    __slots__ = ("kind", "text", "math")

    def __init__(self, kind: str, text: str):
        self.kind, self.text, self.math = kind, text, False


def _tokens(text: str) -> list[_Token]:
    out = []
    for m in TOKEN.finditer(text):
        kind, body = m.lastgroup, m.group(0)
        letters = body.rstrip("'")
        if kind == "word" and not _has_vowel(body):  # N'L: letters and primes, not an elided word
            out += [_Token("name" if part != "'" else "other", part) for part in re.findall(r"[^']+|'", body)]
        elif kind == "name" and letters != body and len(letters) > 2 and _has_vowel(letters) and letters.isalpha():
            out += [_Token("word", letters), _Token("possessive", body[len(letters):])]  # roots': a plural's apostrophe
        else:
            out.append(_Token(kind, body))
    return out


def _has_vowel(text: str) -> bool:
    """A vowel, y counting as one in runs of four letters or more (glyph, but not xy)."""
    vowels = "aeiouAEIOUéèàêôî" + ("yY" if len(text) >= 4 else "")
    return any(ch in vowels for ch in text)


def _is_math_name(text: str) -> bool | None:
    """True for maths, False for a word, None for a function name (maths next to maths)."""
    if any(ch in GREEK or ch in _MARKS or ch in "'′" for ch in text):
        return True
    if text in FUNCTIONS:
        return None
    if len(text) == 1 or text in PRODUCTS:
        return True
    return not _has_vowel(text) and text not in WORDS


def _significant(tokens: list[_Token], i: int, step: int) -> _Token | None:
    i += step
    while 0 <= i < len(tokens) and tokens[i].kind == "space":
        i += step
    return tokens[i] if 0 <= i < len(tokens) else None


def _classify(tokens: list[_Token]) -> None:
    """Mark the tokens that are maths."""
    words = []
    for i, tok in enumerate(tokens):
        if tok.kind == "name":
            verdict = _is_math_name(tok.text)
            if tok.text in ("a", "A"):
                nxt = _significant(tokens, i, 1)
                prev = _significant(tokens, i, -1)
                opens_sentence = prev is None or prev.text in (".", ":") or tok.text == "a"
                if opens_sentence and nxt is not None and nxt.kind in ("word", "name") and _is_math_name(nxt.text) is False:
                    verdict = False
            tok.math = bool(verdict)
            if verdict is None:
                words.append(i)
        elif tok.kind == "other" and (tok.text in OPERATORS or tok.text in SUPERSCRIPTS or tok.text in "^_√"):
            tok.math = True
        elif tok.kind in ("unit", "sci"):
            tok.math = True
    # A hyphen or a slash between words (17-point, sliding/rolling) is text.
    for i, tok in enumerate(tokens):
        if tok.text in "-/":
            prev, nxt = (tokens[i - 1] if i else None), (tokens[i + 1] if i + 1 < len(tokens) else None)
            if nxt is not None and nxt.kind in ("word", "name") and not nxt.math and prev is not None and prev.kind in ("word", "name", "number"):
                tok.math = False
    # Function names and numbers are maths next to maths.
    for _ in range(2):
        for i, tok in enumerate(tokens):
            if (i in words or tok.kind == "number") and not tok.math:
                neighbours = [_significant(tokens, i, -1), _significant(tokens, i, 1)]
                tok.math = any(n is not None and (n.math or (n.text in "(" and i in words)) for n in neighbours)


def _group_is_math(tokens: list[_Token], start: int) -> int | None:
    """For an opening bracket at ``start``: the index of its closing bracket when everything between
    is maths (or spaces, commas, brackets), else None."""
    pairs = {"(": ")", "[": "]", "{": "}"}
    depth, i = 0, start
    while i < len(tokens):
        tok = tokens[i]
        if tok.text in pairs:
            depth += 1
        elif tok.text in pairs.values():
            depth -= 1
            if depth == 0:
                return i
        elif tok.kind != "space" and tok.text != "," and not tok.math:
            return None
        i += 1
    return None


def _spans(tokens: list[_Token]) -> list[tuple[int, int]]:
    """[start, end) of the maximal runs of maths."""
    spans, i = [], 0
    while i < len(tokens):
        tok = tokens[i]
        if tok.math or (tok.text in "([{" and _group_is_math(tokens, i) is not None):
            start, depth = i, 0
            while i < len(tokens):
                tok = tokens[i]
                if tok.text in "([{":
                    close = _group_is_math(tokens, i)
                    # A bracket set off by a space after a complete term is an aside: β = 0 (p = Ω, q = 0).
                    prev = _significant(tokens, i, -1)
                    aside = i > start and tokens[i - 1].kind == "space" and prev is not None and prev.text not in OPERATORS
                    if close is None or aside:
                        break
                    i = close + 1
                    continue
                if tok.math or tok.kind == "space" or (depth and tok.text == ","):
                    i += 1
                    continue
                break
            end = i
            while end > start and tokens[end - 1].kind == "space":
                end -= 1
            if any(t.kind in ("name", "other", "unit", "sci") and t.math for t in tokens[start:end]):
                spans.append((start, end))
            i = max(end, start + 1)
        else:
            i += 1
    return spans


def _math_name(text: str) -> str:
    """ξ̇₀'² → \\dot{\\xi}_{0}'^{2}: letters, then each run of indices as one group; sin²θ → \\sin^{2}\\theta."""
    function = re.match(rf"(sin|cos|tan|log|ln)(?=[{_MARKS}])", text)
    if function:  # sin²θ, log₁₀: the function upright, its index on it
        return FUNCTIONS[function.group(1)] + _math_name(text[function.end():]).lstrip()
    out, i = [], 0
    while i < len(text):
        ch = text[i]
        if ch == "\u0307" and out:
            out[-1] = rf"\dot{{{out[-1]}}}"
        elif ch in SUBSCRIPTS or ch in SUPERSCRIPTS:
            table, mark = (SUBSCRIPTS, "_") if ch in SUBSCRIPTS else (SUPERSCRIPTS, "^")
            run = ""
            while i < len(text) and text[i] in table:
                run += table[text[i]]
                i += 1
            out.append(f"{mark}{{{run}}}")
            continue
        elif ch in "'′":
            out.append("'")
        else:
            out.append(GREEK.get(ch, ch))
        i += 1
    return " ".join(out).replace(" _", "_").replace(" ^", "^").replace(" '", "'")


def _math(tokens: list[_Token]) -> str:
    """LaTeX (math mode) of a run of maths tokens."""
    out: list[str] = []
    i = 0

    def group(j: int) -> tuple[str, int]:
        """The argument at token j of ^, _ or √: a bracket's contents, or a (signed) token."""
        while j < len(tokens) and tokens[j].kind == "space":
            j += 1
        if j < len(tokens) and tokens[j].text in "({":
            close = _group_is_math(tokens, j)
            if close is not None:
                return _math(tokens[j + 1 : close]), close + 1
        sign = ""
        if j < len(tokens) and tokens[j].text in "−-":
            sign, j = "-", j + 1
        if j < len(tokens):
            return sign + _piece(tokens[j]), j + 1
        return sign, j

    while i < len(tokens):
        tok = tokens[i]
        if tok.text in "^_":
            arg, i = group(i + 1)
            out.append(f"{tok.text}{{{arg}}}")
            continue
        if tok.text == "√":
            arg, i = group(i + 1)
            out.append(rf"\sqrt{{{arg}}}")
            continue
        if tok.kind != "space":
            out.append(_piece(tok))
        i += 1
    return re.sub(r" (?=[_^'])", "", " ".join(out))


def _piece(tok: _Token) -> str:
    if tok.kind == "name":
        return FUNCTIONS.get(tok.text) or _math_name(tok.text)
    if tok.kind == "unit":
        return UNITS[tok.text]
    if tok.kind == "sci":  # 3.7e-02 → 3.7\times10^{-2}, 1e-9 → 10^{-9} (it was set as 3.7 e - 02, e a variable)
        mantissa, exponent = tok.text.split("e")
        power = f"10^{{{int(exponent)}}}"
        return power if float(mantissa) == 1 else rf"{mantissa}\times{power}"
    if tok.text in SUPERSCRIPTS:
        return f"^{{{SUPERSCRIPTS[tok.text]}}}"
    if tok.text in SUBSCRIPTS:  # on a bracket: (x + y)₁ (a bare ₁ passed into the LaTeX and stopped pdflatex)
        return f"_{{{SUBSCRIPTS[tok.text]}}}"
    if tok.text in OPERATORS:
        return OPERATORS[tok.text]
    if tok.text in "{}":
        return "\\" + tok.text
    return tok.text


def _text(tok: _Token, previous: _Token | None) -> str:
    """LaTeX (text mode) of a token outside the maths."""
    if tok.kind == "ident":  # a claim or module: typewriter, breakable after its dots and underscores
        return rf"\texttt{{{identifier(tok.text)}}}"
    if tok.text == "'" and (previous is None or previous.kind == "space"):
        return "`"
    out = []
    for ch in tok.text:
        if ch in SPECIAL:
            out.append(SPECIAL[ch])
        elif ch == "°" and tok.kind != "section":  # a degree (α₀ = 5.19°), not the o of n°8 (a referee read "5.19º")
            out.append(r"\ensuremath{^\circ}")
        elif ord(ch) < 128:
            out.append(ch)
        elif ch in TEXT_MAP:
            out.append(TEXT_MAP[ch])
        elif ch in GREEK or ch in OPERATORS or ch in SUPERSCRIPTS or ch in SUBSCRIPTS:
            out.append(f"${_math([_Token('name' if ch in GREEK else 'other', ch)])}$")
        else:
            raise ValueError(f"no LaTeX for {ch!r} (U+{ord(ch):04X})")
    return "".join(out)


def tex_text(text: str) -> str:
    """Prose (Unicode) as LaTeX source for pdflatex: words as text, maths in $…$."""
    tokens = _tokens(text)
    _classify(tokens)
    out, i, previous = [], 0, None
    spans = dict(_spans(tokens))
    try:
        while i < len(tokens):
            if i in spans:
                out.append(f"${_math(tokens[i:spans[i]])}$")
                previous, i = tokens[spans[i] - 1], spans[i]
                continue
            out.append(_text(tokens[i], previous))
            previous, i = tokens[i], i + 1
    except ValueError as error:
        raise ValueError(f"{error} in: {text}") from None
    tex = "".join(out)
    left = sorted({ch for ch in tex if ord(ch) > 127})
    if left:  # pdflatex stops on it (a subscript on a bracket once passed through): an error here, not there
        raise ValueError(f"no LaTeX for {', '.join(f'{ch} (U+{ord(ch):04X})' for ch in left)} in: {text}")
    return tex


def code_text(text: str) -> str:
    """A command as typed, for \\texttt: LaTeX's special characters escaped, nothing made maths (tex_text set
    ``appell paper --pdf`` as ``appell paper $- - p d f$``); an underscore `UNDERSCORE`'s."""
    return "".join(UNDERSCORE + "{}" if ch == "_" else SPECIAL.get(ch, ch) for ch in text)


# appell-appendix.sty's underscore: the typewriter font's own glyph, which copies out of the PDF as "_" (LaTeX's \_
# is a rule in the default OT1 encoding, which copied as a space: "n8.V decreases").
UNDERSCORE = r"\appellus"


def processor(name: str) -> str:
    """A processor's model name as a reader wants it: "Intel(R) Xeon(R) Processor" set as "Intel Xeon" (the
    marks came out as maths, $( R )$), "AMD EPYC 7B13 64-Core Processor" as "AMD EPYC 7B13"."""
    name = re.sub(r"\((R|TM|tm)\)", "", name)
    name = re.sub(r"\s+(\d+-Core\s+)?(Processor|CPU)\b.*$", "", name.strip())
    return re.sub(r"\s+", " ", name).strip() or "unknown"


def identifier(text: str) -> str:
    """A claim's or a module's name, for \\texttt: breakable after its dots and underscores, which copy as typed."""
    return text.replace("_", UNDERSCORE + r"\allowbreak{}").replace(".", r".\allowbreak{}")


def plain_text(text: str) -> str:
    """Text with no maths in it (a French sentence of the paper): every character as text."""
    out, previous = [], None
    for tok in _tokens(text):
        out.append(_text(tok, previous))
        previous = tok
    return "".join(out)


def pdf_text(text: str) -> str:
    """Plain ASCII for a PDF bookmark (hyperref's \\texorpdfstring): Greek letters by name, accents dropped."""
    import unicodedata

    names = {ch: tex[1:].replace("var", "") for ch, tex in GREEK.items() if re.fullmatch(r"\\[a-zA-Z]+", tex)}
    out = []
    for ch in text:
        if ch in names:
            out.append(names[ch])
        elif ch == "°":
            out.append("o")
        elif ch in "−–—":
            out.append("-")
        elif ch in SUPERSCRIPTS:
            out.append("^" + SUPERSCRIPTS[ch])
        elif ch in SUBSCRIPTS:
            out.append(SUBSCRIPTS[ch])
        else:
            plain = unicodedata.normalize("NFKD", ch).encode("ascii", "ignore").decode()
            out.append(" " if plain and plain in "\\{}$&#%^_~" else plain)  # TeX's specials; < and > are fine
    return "".join(out)
