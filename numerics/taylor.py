"""Taylor-series integration in mpmath, the coefficient recurrences generated from SymPy.

Two halves:

* `generate` turns the right-hand side of an ODE, given as SymPy
  expressions (the ones the derivation holds, never retyped), into Python
  source for a function that returns the Taylor coefficients of the
  solution through a point, to any order.  The expressions are split into
  common subexpressions (``sympy.cse``), every node of that DAG becomes one
  rule of automatic differentiation ("jet arithmetic"): sums, products,
  quotients, integer and rational powers (square roots), exp, log, sin and
  cos, each giving the n-th coefficient of its result from the first n of
  its operands.  Parameter-only subexpressions are evaluated once per call.
  The source is kept (``Generated.source``) so that it can be read, or
  written into a committed file.

* `integrate` is the Taylor method with the calling convention of
  `numerics.reference.integrate` (times landed on, events, ``on_step``,
  the same ``Outcome``): order and step come from the coefficients as in
  Jorba & Zou (2005): step h = min over the last two orders j of
  (ε‖y‖/‖y_j‖)^(1/j) · exp(−0.7/(p − 1)), per component (their ρ/e² at their
  order p = ⌈−½ ln ε + 1⌉, which `order_for` keeps: measured here, 0.5–1.5
  times it is no faster).  The Taylor polynomial is the dense output
  (Hairer, Nørsett & Wanner, *Solving ODEs I*, §II.6): requested times are
  read off it and events (a sign change of a function of (t, y)) are
  located on it, without new evaluations of the right-hand side.

References: À. Jorba and M. Zou, "A software package for the numerical
integration of ODEs by means of high-order Taylor methods", Experimental
Mathematics 14 (2005) 99–117; E. Hairer, S. P. Nørsett and G. Wanner,
*Solving Ordinary Differential Equations I*, 2nd ed., Springer 1993, §I.8
(Taylor series by recursive differentiation) and §II.6 (dense output).

The arithmetic is mpmath's (call inside ``mpmath.workdps``); the products
of series are sums of exact products rounded once (`dot`, as `mpmath.fdot`).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable, Sequence

import mpmath
import sympy as sp
from mpmath.libmp import from_man_exp, round_nearest
from sympy.printing.pycode import MpmathPrinter

from numerics.reference import Outcome, Stats

MAX_STEPS = 200_000


# ---------------------------------------------------------------------------
# The generator
# ---------------------------------------------------------------------------


def dot(a: Sequence, b: Sequence):
    """Σ a_i b_i rounded once, as `mpmath.fdot`, 2–3× faster on the Cauchy products here.

    The products of the mantissas are exact integers; they are added exactly
    (shifting to the smallest exponent met, which stays small since the terms
    of one Taylor coefficient are of like size) and rounded to the working
    precision once.  Anything but finite mpf numbers goes to `mpmath.fdot`.
    """
    acc, acc_e = 0, None
    try:
        for x, y in zip(a, b):
            s1, m1, e1, _ = x._mpf_
            s2, m2, e2, _ = y._mpf_
            m = m1 * m2
            if not m:
                if (not m1 and e1) or (not m2 and e2):  # inf or nan
                    return mpmath.fdot(a, b)
                continue
            e = e1 + e2
            if s1 ^ s2:
                m = -m
            if acc_e is None:
                acc, acc_e = m, e
            elif e >= acc_e:
                acc += m << (e - acc_e)
            else:
                acc, acc_e = (acc << (acc_e - e)) + m, e
    except AttributeError:
        return mpmath.fdot(a, b)
    if acc_e is None:
        return mpmath.mpf(0)
    return mpmath.mp.make_mpf(from_man_exp(acc, acc_e, mpmath.mp.prec, round_nearest))


@dataclass
class Generated:
    """A generated coefficient function: ``fn(x0, y0, par, order)`` -> per state, its coefficients 0..order."""

    source: str
    fn: Callable
    state: tuple
    params: tuple
    indep: object

    def bind(self, values: Sequence) -> Callable:
        """The function (x0, y0, order) with the parameters fixed to ``values``."""
        fn, par = self.fn, tuple(values)
        return lambda x0, y0, order: fn(x0, y0, par, order)


class _Ref:
    """A node of the DAG: a constant (a name evaluated once) or a series (a list of coefficients)."""

    __slots__ = ("name", "const")

    def __init__(self, name: str, const: bool):
        self.name, self.const = name, const


class _Builder:
    def __init__(self, state, params, indep):
        self.printer = MpmathPrinter({"fully_qualified_modules": True})
        self.const_lines: list[str] = []  # once per call: parameter-only subexpressions
        self.zero_lines: list[str] = []  # order 0: the values
        self.step_lines: list[str] = []  # order n ≥ 1: the recurrences
        self.cache: dict = {}
        self.weighted: dict[str, str] = {}  # series name -> name of [j * a_j]
        self.count = 0
        self.symbols: dict = {}
        for i, s in enumerate(params):
            self.symbols[s] = _Ref(f"c_par{i}", True)
        for i, s in enumerate(state):
            self.symbols[s] = _Ref(f"y{i}", False)
        if indep is not None:
            self.symbols[indep] = _Ref("x", False)

    def _new(self, prefix):
        self.count += 1
        return f"{prefix}{self.count}"

    def _const(self, expr) -> _Ref:
        """A parameter-only expression, printed once (its symbols are constant nodes)."""
        names = {s: sp.Symbol(self.symbols[s].name) for s in expr.free_symbols}
        name = self._new("c")
        self.const_lines.append(f"{name} = {self.printer.doprint(expr.xreplace(names))}")
        return _Ref(name, True)

    def _series(self, zero: str, step: str) -> _Ref:
        name = self._new("s")
        self.zero_lines.append(f"{name} = [{zero}]")
        self.step_lines.append(f"{name}.append({step})")
        return _Ref(name, False)

    def _weighted(self, a: _Ref) -> str:
        """[j a_j]: the coefficients of t a'(t), shared by exp, sin, cos and powers of a."""
        if a.name not in self.weighted:
            w = f"w_{a.name}"
            self.zero_lines.append(f"{w} = [0]")
            self.step_lines.append(f"{w}.append(n * {a.name}[n])")
            self.weighted[a.name] = w
        return self.weighted[a.name]

    def node(self, expr) -> _Ref:
        expr = sp.sympify(expr)
        if expr in self.cache:
            return self.cache[expr]
        if expr in self.symbols:
            ref = self.symbols[expr]
        elif not (expr.free_symbols - {s for s, r in self.symbols.items() if r.const}):
            ref = self._const(expr)
        elif isinstance(expr, sp.Add):
            ref = self._add(expr)
        elif isinstance(expr, sp.Mul):
            ref = self._mul(expr)
        elif isinstance(expr, sp.Pow):
            ref = self._pow(expr)
        elif isinstance(expr, (sp.sin, sp.cos)):
            s, c = self._sincos(expr.args[0])
            ref = s if isinstance(expr, sp.sin) else c
        elif isinstance(expr, sp.exp):
            ref = self._exp(expr.args[0])
        elif isinstance(expr, sp.log):
            ref = self._log(expr.args[0])
        else:
            raise NotImplementedError(f"no Taylor rule for {type(expr).__name__}: {expr}")
        self.cache[expr] = ref
        return ref

    def _split(self, expr):
        """A product as (constant factor or None, series factors)."""
        consts, series = [], []
        for factor in sp.Mul.make_args(expr):
            (series if factor.free_symbols - self._const_symbols() else consts).append(factor)
        return (sp.Mul(*consts) if consts else None), series

    def _const_symbols(self):
        return {s for s, r in self.symbols.items() if r.const}

    def _scaled(self, term) -> tuple[str | None, _Ref]:
        """A term as (constant factor's name or None, series node)."""
        k, series = self._split(term)
        ref = self.node(sp.Mul(*series))
        if k is None or k == 1:
            return None, ref
        if k == -1:
            return "-1", ref
        return (str(k) if k.is_Integer else self.node(k).name), ref

    def _add(self, expr) -> _Ref:
        const = [a for a in expr.args if not a.free_symbols - self._const_symbols()]
        terms = [self._scaled(a) for a in expr.args if a.free_symbols - self._const_symbols()]

        def coef(i):
            parts = []
            for k, ref in terms:
                parts.append(f"{ref.name}[{i}]" if k is None else f"({k})*{ref.name}[{i}]")
            return " + ".join(parts)

        zero = coef(0)
        if const:
            zero = f"{self.node(sp.Add(*const)).name} + {zero}"
        return self._series(zero, coef("n"))

    def _mul(self, expr) -> _Ref:
        k, series = self._split(expr)
        num, den = [], []
        for factor in series:
            base, e = factor.as_base_exp()
            if e.is_number and e < 0:
                den.append(base ** (-e))
            else:
                num.append(factor)
        kname = None if k is None or k == 1 else ("-1" if k == -1 else (str(k) if k.is_Integer else self.node(k).name))
        if den:
            # K·a/b with b the product of the denominators: one quotient rule.
            a = self.node(sp.Mul(*num)) if num else None
            return self._div(kname, a, self.node(sp.Mul(*den)))
        if len(num) == 1:
            a = self.node(num[0])
            return self._series(f"({kname})*{a.name}[0]", f"({kname})*{a.name}[n]")
        # Products of series: Cauchy products, two factors at a time.
        left = self.node(sp.Mul(*num[:-1]))
        right = self.node(num[-1])
        scale = "" if kname is None else f"({kname})*"
        return self._series(
            f"{scale}{left.name}[0]*{right.name}[0]",
            f"{scale}fdot({left.name}[:n+1], {right.name}[n::-1])",
        )

    def _div(self, kname, a: _Ref | None, b: _Ref) -> _Ref:
        """c = K a / b:  c_n = (K a_n − Σ_{j=1..n} b_j c_{n−j}) / b_0."""
        name = self._new("s")
        inv = f"inv_{name}"
        k = "" if kname is None else f"({kname})*"
        numer0 = (f"{k}{a.name}[0]" if a else (kname or "1"))
        numer_n = f"{k}{a.name}[n] - " if a else "-"
        self.zero_lines.append(f"{inv} = 1 / {b.name}[0]")
        self.zero_lines.append(f"{name} = [({numer0}) * {inv}]")
        self.step_lines.append(f"{name}.append(({numer_n}fdot({b.name}[1:n+1], {name}[n-1::-1])) * {inv})")
        return _Ref(name, False)

    def _pow(self, expr) -> _Ref:
        base, e = expr.args
        if not e.is_number:
            return self._exp(e * sp.log(base))
        if e < 0:
            return self._div(None, None, self.node(base ** (-e)))
        if e.is_Integer:
            if e == 1:
                return self.node(base)
            half = self.node(base ** (e // 2))
            if e % 2 == 0:
                return self._series(f"{half.name}[0]**2", f"fdot({half.name}[:n+1], {half.name}[n::-1])")
            return self.node(sp.Mul(base ** (e - 1), base, evaluate=False))
        a = self.node(base)
        if e == sp.Rational(1, 2):
            # c² = a:  c_n = (a_n − Σ_{j=1..n−1} c_j c_{n−j}) / (2 c_0).
            name = self._new("s")
            self.zero_lines.append(f"{name} = [mpmath.sqrt({a.name}[0])]")
            self.zero_lines.append(f"inv_{name} = 1 / (2 * {name}[0])")
            self.step_lines.append(f"{name}.append(({a.name}[n] - fdot({name}[1:n], {name}[n-1:0:-1])) * inv_{name})")
            return _Ref(name, False)
        # c = a^e:  n a_0 c_n = Σ_{j=0..n−1} (e(n−j) − j) a_{n−j} c_j  (from a c' = e a' c).
        name = self._new("s")
        ename = self.node(e).name
        wa = self._weighted(a)
        self.zero_lines.append(f"{name} = [{a.name}[0] ** {ename}]")
        self.zero_lines.append(f"w_{name} = [0]")
        self.zero_lines.append(f"inv_{name} = 1 / {a.name}[0]")
        self.step_lines.append(
            f"{name}.append(({ename} * fdot({wa}[n:0:-1], {name}[:n]) - fdot({a.name}[n:0:-1], w_{name}[:n])) * inv_{name} / n)"
        )
        self.step_lines.append(f"w_{name}.append(n * {name}[n])")
        return _Ref(name, False)

    def _exp(self, arg) -> _Ref:
        """c = e^a:  c_n = (1/n) Σ_{j=1..n} j a_j c_{n−j}."""
        a = self.node(arg)
        wa = self._weighted(a)
        name = self._new("s")
        self.zero_lines.append(f"{name} = [mpmath.exp({a.name}[0])]")
        self.step_lines.append(f"{name}.append(fdot({wa}[1:n+1], {name}[n-1::-1]) / n)")
        return _Ref(name, False)

    def _log(self, arg) -> _Ref:
        """c = ln a:  c_n = (a_n − (1/n) Σ_{j=1..n−1} j c_j a_{n−j}) / a_0."""
        a = self.node(arg)
        name = self._new("s")
        self.zero_lines.append(f"{name} = [mpmath.log({a.name}[0])]")
        self.zero_lines.append(f"w_{name} = [0]")
        self.zero_lines.append(f"inv_{name} = 1 / {a.name}[0]")
        self.step_lines.append(f"{name}.append(({a.name}[n] - fdot(w_{name}[1:n], {a.name}[n-1:0:-1]) / n) * inv_{name})")
        self.step_lines.append(f"w_{name}.append(n * {name}[n])")
        return _Ref(name, False)

    def _sincos(self, arg):
        """s = sin a, c = cos a together:  s_n = (1/n) Σ j a_j c_{n−j},  c_n = −(1/n) Σ j a_j s_{n−j}."""
        key = ("sincos", arg)
        if key not in self.cache:
            a = self.node(arg)
            wa = self._weighted(a)
            s, c = self._new("s"), self._new("s")
            self.zero_lines.append(f"{s} = [mpmath.sin({a.name}[0])]")
            self.zero_lines.append(f"{c} = [mpmath.cos({a.name}[0])]")
            # Both from the coefficients below n: the two appends may come in either order.
            self.step_lines.append(f"{s}_n = fdot({wa}[1:n+1], {c}[n-1::-1]) / n")
            self.step_lines.append(f"{c}.append(-fdot({wa}[1:n+1], {s}[n-1::-1]) / n)")
            self.step_lines.append(f"{s}.append({s}_n)")
            self.cache[key] = (_Ref(s, False), _Ref(c, False))
        return self.cache[key]


def generate(rates: Sequence, state: Sequence, params: Sequence = (), indep=None, name: str = "taylor_coefficients") -> Generated:
    """Source and function for the Taylor coefficients of y' = rates(x, y; params).

    ``rates[i]`` is d/dx of ``state[i]`` as a SymPy expression in ``state``,
    ``params`` (constants) and ``indep`` (x, or None for an autonomous system).
    The function ``name(x0, y0, par, order)`` returns, per state variable,
    the list of its Taylor coefficients y_0 … y_order at x0.
    """
    state, params = tuple(state), tuple(params)
    b = _Builder(state, params, indep)
    replacements, reduced = sp.cse(list(rates), symbols=sp.numbered_symbols("cse_"), optimizations="basic")
    for sym, expr in replacements:
        b.cache[sym] = b.node(expr)
        b.symbols[sym] = b.cache[sym]
    outputs = [b.node(e) for e in reduced]

    lines = [f"def {name}(x_at, y_at, par, order):"]
    lines.append(f"    {', '.join(r.name for s, r in b.symbols.items() if s in params) or '_'}{',' if len(params) == 1 else ''} = par")
    lines += [f"    {line}" for line in b.const_lines]
    lines.append("    one, zero = mpmath.mpf(1), mpmath.mpf(0)")
    if indep is not None:
        lines.append("    x = [x_at, one] + [zero] * order")
    for i in range(len(state)):
        lines.append(f"    y{i} = [y_at[{i}]]")
    lines += [f"    {line}" for line in b.zero_lines]
    for i, out in enumerate(outputs):
        lines.append(f"    y{i}.append({out.name}{'' if out.const else '[0]'})")
    lines.append("    for n in range(1, order):")
    lines += [f"        {line}" for line in b.step_lines]
    for i, out in enumerate(outputs):
        lines.append(f"        y{i}.append({'zero' if out.const else f'{out.name}[n] / (n + 1)'})")
    lines.append(f"    return [{', '.join(f'y{i}' for i in range(len(state)))}]")
    source = "\n".join(lines) + "\n"
    namespace = {"mpmath": mpmath, "fdot": dot}
    exec(compile(source, f"<taylor {name}>", "exec"), namespace)
    return Generated(source, namespace[name], state, params, indep)


# ---------------------------------------------------------------------------
# The integrator
# ---------------------------------------------------------------------------

Jet = Callable[[object, list, int], list]  # (x0, y0, order) -> coefficients per component
Event = Callable[[object, list], object]


def order_for(tol) -> int:
    """Jorba & Zou's order, p = ⌈−½ ln ε + 1⌉: the cost per unit length is least there."""
    return max(6, int(mpmath.ceil(-mpmath.log(tol) / 2 + 1)))


def _horner(coefs: list, s) -> object:
    v = coefs[-1]
    for c in reversed(coefs[:-1]):
        v = v * s + c
    return v


def polynomial(coefs: list[list], s) -> list:
    """The Taylor polynomial of each component at offset s: the dense output."""
    return [_horner(c, s) for c in coefs]


def step_size(coefs: list[list], order: int, tol) -> object:
    """The step whose last two terms are within ``tol``: h = min_j (ε ‖y‖/‖y_j‖)^(1/j) · exp(−0.7/(p−1)), j = p−1, p.

    Jorba & Zou (2005) §3.2 write it h = ρ/e² · exp(−0.7/(p−1)) with
    ρ = min_j (‖y‖/‖y_j‖)^(1/j): the same at their order p = −½ ln ε + 1,
    where ε^(1/p) ≈ e^−2; written with ε it stays right at any order.
    Per component and relative to max(1, |y|), as `reference.step` measures
    errors.  Where the last two coefficients vanish everywhere (a polynomial
    solution, exact at any step) the lower ones set the scale instead, so that
    a step towards t = ∞ stays finite and the events along it stay resolvable.
    """
    with mpmath.workprec(53):
        tol = mpmath.mpf(tol)
        for orders in ((order - 1, order), range(1, order + 1)):
            h = mpmath.inf
            for c in coefs:
                scale = max(abs(c[0]), 1)
                for j in orders:
                    if c[j] != 0:
                        h = min(h, (tol * scale / abs(c[j])) ** (mpmath.mpf(1) / j))
            if h != mpmath.inf:
                break
        return h * mpmath.exp(mpmath.mpf(-0.7) / (order - 1))


def _locate(coefs, event: Event, t, h, g0, g1, tol, num):
    """Illinois on the Taylor polynomial: the root of event(t + s, y(t + s)) for s in (0, h]."""
    lo, hi, g_lo, g_hi = num(0), h, g0, g1
    side = 0
    s = hi
    for _ in range(400):
        s = (lo * g_hi - hi * g_lo) / (g_hi - g_lo)
        if not lo < s < hi:
            s = (lo + hi) / 2
        g_s = event(t + s, polynomial(coefs, s))
        if g_s == 0 or hi - lo <= tol * (1 + abs(t + s)) / 16:
            break
        if (g_s > 0) == (g_hi > 0):
            hi, g_hi = s, g_s
            if side == 1:
                g_lo /= 2
            side = 1
        else:
            lo, g_lo = s, g_s
            if side == -1:
                g_hi /= 2
            side = -1
    return s, polynomial(coefs, s)


def integrate(
    jet: Jet,
    t0,
    y0: Sequence,
    t_end,
    tol,
    times: Sequence = (),
    events: Sequence[Event] = (),
    num=mpmath.mpf,
    first_step=None,
    stats: Stats | None = None,
    on_step: Callable[[object, list], None] | None = None,
    order: int | None = None,
    max_steps: int | None = None,
) -> Outcome:
    """Integrate from t0 towards t_end with Taylor steps; stop at the first sign change of an event.

    The convention of `numerics.reference.integrate`: ``times`` (increasing,
    within [t0, t_end]) have their states returned, read off the Taylor
    polynomial; an event stops the integration at its root, located on the
    polynomial to about ``tol`` relative in t; ``on_step`` sees every
    accepted (t, y), starting with (t0, y0).  ``jet(t, y, order)`` gives the
    Taylor coefficients (see `generate`).  ``first_step`` is accepted for the
    common signature and only caps the first step: the coefficients choose.
    """
    stats = Stats() if stats is None else stats
    t, y = num(t0), [num(v) for v in y0]
    t_end = num(t_end)
    p = order or order_for(tol)
    pending = [num(x) for x in times]
    states = []
    while pending and pending[0] <= t:
        states.append(list(y))
        pending.pop(0)
    g_prev = [g(t, y) for g in events]
    if on_step is not None:
        on_step(t, y)
    cap = num(first_step) if first_step is not None else None
    max_steps = MAX_STEPS if max_steps is None else max_steps  # read at call time: tests lower it
    while t < t_end:
        if stats.evaluations > max_steps:  # every expansion, the steps cut short by an event too
            raise ArithmeticError(f"no convergence after {max_steps} steps at t = {t}")
        coefs = jet(t, y, p)
        stats.evaluations += 1
        h = min(num(step_size(coefs, p, tol)), t_end - t)
        if h == mpmath.inf:
            raise ArithmeticError(f"a constant solution integrated to t = ∞ from t = {t}")
        if cap is not None:
            h, cap = min(h, cap), None
        new = polynomial(coefs, h)
        g_new = [g(t + h, new) for g in events]
        crossed = [i for i, (a, b) in enumerate(zip(g_prev, g_new)) if (a > 0 >= b) or (a < 0 <= b)]
        if crossed:
            roots = [(_locate(coefs, events[i], t, h, g_prev[i], g_new[i], tol, num), i) for i in crossed]
            (s, y_s), i = min(roots, key=lambda r: r[0][0])
            while pending and pending[0] <= t + s:
                states.append(polynomial(coefs, pending.pop(0) - t))
            return Outcome(t + s, y_s, i, states, stats)
        while pending and pending[0] <= t + h:
            states.append(polynomial(coefs, pending.pop(0) - t))  # dense output, no step cut short
        stats.steps += 1
        t = t_end if h == t_end - t else t + h
        y, g_prev = new, g_new
        if on_step is not None:
            on_step(t, y)
    return Outcome(t, y, None, states, stats)


def solve(generated: Generated, params: Sequence, t0, y0: Sequence, times: Sequence, digits: int = 30, max_steps: int | None = None) -> tuple[list, Stats]:
    """The state at each of ``times`` (increasing, ≥ t0), about ``digits`` digits: `reference.solve` by Taylor."""
    with mpmath.workdps(digits + 10):
        tol = mpmath.mpf(10) ** (-digits - 2)
        jet = generated.bind([mpmath.mpf(v) for v in params])
        outcome = integrate(jet, t0, y0, max(times), tol, times=times, max_steps=max_steps)
        return outcome.states, outcome.stats
