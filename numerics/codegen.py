"""Generate `numerics/kernels.py` from the derivation: the simulator's right-hand sides and closed forms.

The simulator imports no SymPy (design notes, "generated, not re-derived at
run time"): every formula it evaluates is written here, once, from the SymPy
objects that derivation/ holds, into plain Python on floats (``math`` only,
so that numba can compile it unchanged), with common subexpressions shared
(``sympy.cse``).  The generated file is committed and is never edited by
hand; ``--check`` regenerates it in memory and fails when it differs, as
``appell paper --check`` does for paper/.

    python -m numerics.codegen            # write numerics/kernels.py and numerics/dop853_steps.py
    python -m numerics.codegen --check    # exit 1 when either is stale

Every kernel states its contract (argument order, what it returns, the
paper's equation) in its docstring, as pydy's generated code does.
"""

from __future__ import annotations

import sys
from dataclasses import dataclass
from pathlib import Path

import sympy as sp
from sympy.printing.precedence import PRECEDENCE
from sympy.printing.pycode import PythonCodePrinter

KERNELS = Path(__file__).with_name("kernels.py")

HEADER = '''"""The simulator's formulas, generated from the derivation by `numerics.codegen`: do not edit.

Regenerate with ``python -m numerics.codegen`` (``--check`` fails when this
file is stale).  Plain Python on floats, ``math`` only: the interpreted
engine runs it as it is, and numba compiles it unchanged (`numerics.compiled`).
Parameters always come in the order f, R, k, delta, epsilon, g (SI units).
"""

import math

'''


@dataclass(frozen=True)
class Kernel:
    name: str
    args: tuple
    outputs: list
    doc: str


def _name(symbol: sp.Symbol) -> str:
    return {"V_0": "V0", "Omega_0": "Omega0", "beta_0": "beta0", "r_0": "r0", "t": "tau"}.get(symbol.name, symbol.name)


class _Printer(PythonCodePrinter):
    """Python source with small integer powers written as products: ``(k*k)``, ``1/(k*k)``.  With ``k**2`` in
    it, numba's code for a loop over lanes is not vectorised (seen in the assembly, `numerics.lanes`); a
    product is exact where ``**`` is, and ``1/(k*k)`` within an ulp of ``k**(-2)``."""

    def _print_Pow(self, expr, rational=False):
        base, exponent = expr.as_base_exp()
        if exponent.is_Integer and 2 <= abs(exponent) <= 4:
            product = "*".join([self.parenthesize(base, PRECEDENCE["Mul"])] * abs(int(exponent)))
            return f"({product})" if exponent > 0 else f"(1/({product}))"
        return super()._print_Pow(expr, rational)


def _code(kernel: Kernel) -> str:
    """One kernel as Python source: the subexpressions shared, then the outputs as a tuple (or a float)."""
    printer = _Printer({"standard": "python3", "fully_qualified_modules": True})
    rename = {a: sp.Symbol(_name(a)) for a in kernel.args}
    outputs = [sp.sympify(e).xreplace(rename) for e in kernel.outputs]
    shared, reduced = sp.cse(outputs, symbols=sp.numbered_symbols("x"), optimizations="basic", order="canonical")
    lines = [f"def {kernel.name}({', '.join(_name(a) for a in kernel.args)}):", f'    """{kernel.doc}"""']
    lines += [f"    {symbol} = {printer.doprint(expr)}" for symbol, expr in shared]
    body = ["0.0" if e == 0 else printer.doprint(e) for e in reduced]  # a float, so numba types a uniform tuple
    lines.append(f"    return {body[0]}" if len(body) == 1 else f"    return ({', '.join(body)})")
    return "\n".join(lines) + "\n"


def kernels() -> list[Kernel]:
    """Every formula the simulator evaluates, from derivation/ (through `equations` and `phases`)."""
    from derivation.symbols import R
    from numerics import equations, phases

    ca, sa = sp.symbols("cos_alpha sin_alpha", real=True)
    slide = equations.sliding_expressions()
    on_unit = {sp.cos(equations.As): ca, sp.sin(equations.As): sa}
    unit_args = (equations.Vs, ca, sa, equations.Ps, equations.Qs, equations.cb, equations.sb)
    rates = [slide[n].subs(on_unit) for n in ("V'", "V alpha'", "p'", "q'", "xi'", "eta'")]
    slip = equations.slip_expressions()
    out = [
        Kernel(
            "slide_rates", unit_args + equations.PARAMS, rates,
            "V', V alpha', p', q', xi', eta' while sliding (eqs. (4)-(8), n°2), from V, the slip's unit vector "
            "(cos alpha, sin alpha), p, q and the rotation's unit vector (cos beta, sin beta).",
        ),
        Kernel(
            "slip_velocity", slip["args"], slip["u, v"],
            "(u, v), the slip of the contact point, from the centre's velocity and the rotation: eq. (2).",
        ),
        Kernel(
            "centre_velocity", unit_args[:5] + (R,), [rates[4], rates[5]],
            "(xi', eta') from the slip V (cos alpha, sin alpha) and the rotation (p, q): eq. (2) solved for the centre.",
        ),
    ]
    forms = {
        "classical": (phases.classical_forms(), "n°3 (delta = 0, or the classical model)"),
        "follow": (phases.straight_forms("follow"), "the straight shot theta = +pi/2"),
        "draw": (phases.straight_forms("draw"), "the straight shot theta = -pi/2"),
        "rolling": (phases.rolling_forms(), "n°7, pure rolling"),
        "pivot": (phases.pivot_forms(), "eq. (5), the pivot"),
    }
    for key, ((args, exprs, end_args, ends), what) in forms.items():
        state = "r" if key == "pivot" else "(V, p, q, xi, eta, xi', eta') in the slip frame"
        out.append(Kernel(f"{key}_at", args, exprs, f"{state} at tau after the start of {what}."))
        end = "(slip end, spin end)" if len(ends) == 2 else "the duration"
        out.append(Kernel(f"{key}_end", end_args, ends, f"{end} of {what}."))
    return out


def source() -> str:
    return HEADER + "\n\n".join(_code(k) for k in kernels())


STEPS = Path(__file__).with_name("dop853_steps.py")

STEPS_HEADER = '''"""Dormand–Prince 8(5,3)'s linear combinations, unrolled from `numerics.dop853_tables` by `numerics.codegen`:
do not edit.

Every stage's input y + h Σ_j a_sj k_j (of the components the rates read:
`numerics.lane_rows.RATES_READ`), the 8th-order solution, the two
embedded error estimates and the dense output's rows, written out with only
the nonzero coefficients (exact: each float is the table's own), for state
vectors of length n: straight-line arithmetic that numba compiles to a few
instructions per component, where a loop over the table's zeros cost ten
times more.  The lanes' versions address a block of lanes by its rows
(`numerics.lane_rows`).
"""

from numerics.lane_rows import LANES, NEWEST, ROW_H, ROW_K, ROW_Y, ROW_Y_NEW, ROW_Y_STAGE, STAGE

'''


def _combination(weights, lanes: bool = False) -> str:
    index = "i, l" if lanes else "i"
    terms = [f"{float(w)!r} * K[{j}, {index}]" for j, w in enumerate(weights) if w != 0.0]  # repr: the exact float
    return " + ".join(terms) if terms else "0.0"


def _lanes_step(name: str, weights, out_row: str, what: str, components=None) -> str:
    """A loop over lanes [0, width) of the block ``L`` (rows of `numerics.lane_rows`): ``what``, K[j] the rates
    of stages 0 … len(weights) − 1.  The last of them is still in block NEWEST, where the rates were written:
    copied into its own block here (stage 1's, K[0], is in place).  The components are written out, every
    row a constant: with a loop over them the compiler left the loop over lanes scalar (seen in its code).
    ``components``: those written (default all); the copy out of block NEWEST is of every one."""
    from numerics.lane_rows import N_Y

    components = range(N_Y) if components is None else components
    last = len(weights) - 1
    lines = [
        f"def {name}(L, width):",
        f'    """{what}, in lanes [0, width) of the block L (`numerics.lanes`)."""',
        f"    k, y, out = ROW_K * LANES, ROW_Y * LANES, {out_row} * LANES",
        "    for l in range(width):",
        "        h = L[ROW_H * LANES + l]",
    ]
    for i in range(N_Y):
        row = f" + {i} * LANES" if i else ""
        terms = []
        for j, w in enumerate(weights):
            if w != 0.0:
                stage = f" + {j} * STAGE" if j else ""
                value = f"newest_{i}" if j == last and last > 0 else f"L[k{stage}{row} + l]"
                terms.append(f"{float(w)!r} * {value}")  # repr: the exact float
        if last > 0:
            lines += [f"        newest_{i} = L[k + NEWEST * STAGE{row} + l]", f"        L[k + {last} * STAGE{row} + l] = newest_{i}"]
        if i in components:
            lines.append(f"        L[out{row} + l] = L[y{row} + l] + h * ({' + '.join(terms)})")
    return "\n".join(lines) + "\n"


def steps_source() -> str:
    """The generated combinations of DOP853 (from the coefficient tables, no formula typed)."""
    from numerics import dop853_tables as tab
    from numerics.lane_rows import RATES_READ

    out = [STEPS_HEADER]
    for s in range(1, tab.N_EXTENDED):
        if s == tab.N_STAGES:
            continue  # stage 12 is the rates at the new point, y + h Σ B_j k_j: `solution`
        out.append(
            f"def stage_{s}(y, K, h, out):\n"
            f'    """out = y + h Σ_j A[{s}, j] K[j], the input of stage {s}: the components its rates read."""\n'
            f"    for i in range({RATES_READ.start}, {RATES_READ.stop}):\n"
            f"        out[i] = y[i] + h * ({_combination(tab.A[s, :s])})\n"
        )
    for s in range(1, tab.N_STAGES):  # the same for a block of lanes (`numerics.lane_rows`), one h per lane
        out.append(_lanes_step(f"lanes_stage_{s}", tab.A[s, :s], "ROW_Y_STAGE",
                               f"Y_STAGE = Y + h Σ_j A[{s}, j] K[j], the input of stage {s} (the components its "
                               "rates read)", RATES_READ))
    out.append(_lanes_step("lanes_solution", tab.B, "ROW_Y_NEW", "Y_NEW = Y + h Σ_j B_j K[j], the 8th-order step"))
    out.append(
        "def solution(y, K, h, out):\n"
        '    """out = y + h Σ_j B_j K[j]: the 8th-order step."""\n'
        "    for i in range(y.shape[0]):\n"
        f"        out[i] = y[i] + h * ({_combination(tab.B)})\n"
    )
    out.append(
        "def error_terms(K, i, l):\n"
        '    """(Σ_j E5_j K[j, i, l], Σ_j E3_j K[j, i, l]): the 5th- and 3rd-order error estimates of component i\n'
        '    in lane l, over h (a single scene is lane 0 of its K reshaped to (stages, components, 1))."""\n'
        f"    return ({_combination(tab.E5, lanes=True)}, {_combination(tab.E3, lanes=True)})\n"
    )
    lane_terms = [[f"{float(w)!r} * " + (f"L[k + {j} * STAGE + l]" if j else "L[k + l]") for j, w in enumerate(weights)
                   if w != 0.0] for weights in (tab.E5, tab.E3)]
    out.append(
        "def lanes_error_terms(L, i, l):\n"
        '    """`error_terms` of component i in lane l of the block L (`numerics.lanes`; i a constant where it is\n'
        '    inlined, so that every row is)."""\n'
        "    k = (ROW_K + i) * LANES\n"
        f"    return ({' + '.join(lane_terms[0])}, {' + '.join(lane_terms[1])})\n"
    )
    for m in range(4):
        out.append(
            f"def dense_{m}(K, i):\n"
            f'    """Σ_j D[{m}, j] K[j, i]: row {m + 3} of the interpolant, over h."""\n'
            f"    return {_combination(tab.D[m])}\n"
        )
    return "\n\n".join(out)


def generated() -> dict[Path, str]:
    """Every generated file of the simulator and its text."""
    return {KERNELS: source(), STEPS: steps_source()}


def main(argv=None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    files = generated()
    if "--check" in argv:
        stale = [path.name for path, text in files.items() if not path.exists() or path.read_text(encoding="utf-8") != text]
        if stale:
            print(f"stale: {', '.join(stale)} (run 'python -m numerics.codegen' and commit)", file=sys.stderr)
            return 1
        print(f"{', '.join(path.name for path in files)}: up to date")
        return 0
    for path, text in files.items():
        path.write_text(text, encoding="utf-8")
        print(f"wrote {path}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
