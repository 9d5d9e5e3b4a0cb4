"""The rules every input meets, written once: scene files, state arrays, the Python API and CLI flags.

Whatever the entry (a JSON scene, a row of a CSV or .npz, ``Params(...)``,
``simulate(scene, tol=...)``, ``--tol``), a value goes through the same
function here, so the command line and the API cannot disagree.  A broken
rule is a `SceneError` whose message is one line naming the field and the
rule ("scene [4812].state.p: must be finite, got nan"); the command line
prints it and exits with status 2.

Two more failures are never a traceback or a NaN dressed as a result
either: `UnrepresentableError`, a `SceneError` for a motion whose times or
lengths would overflow float64 (refused before any work), and
`ComputationError` for a failure on valid input: a result that came out
non-finite, or a numerical loop that reached its bound on work
(`WorkLimitError`); the command line prints its one line and exits 1.
"""

from __future__ import annotations

import math
import numbers
from decimal import MAX_EMAX, MIN_ETINY, Decimal, InvalidOperation
from fractions import Fraction

MODELS = ("appell", "classical")
# Relative tolerances of the numerical slide: float64's precision bounds them below, what is calibrated above.
# Above 1e-5, DOP853's few long steps near δ = fR (stiff there) can miss the tolerance and the estimate both:
# at 0.999 fR and tol 3e-4 a rest point was 2.8× the tolerance and 4.4× its estimate off (an audit), while
# at 1e-5 and below none was over: 80,000 shots from 0.5 to 0.999 fR at 1e-5 (worst 0.20 tol), 120,000 from 0.99
# to 0.9999 fR at each of 1e-5, 5e-6, 2e-6, 1e-6, 1e-7 (worst 0.30 tol), against the same shots at tol 1e-13.
TOL_RANGE = (1e-13, 1e-5)
# The tolerance when none is given: one scene, a batch and the command line alike (a user audit: the batch's
# 1e-9 beside simulate's 1e-10 put a loop's rest points 6e-9 from the batch's, and looked like a bug).
DEFAULT_TOL = 1e-10
# Every time, length and speed of a motion must stay below this, so that their squares and products
# (energies, V², distances travelled) stay finite in float64 (largest 1.8e308).
SCALE_LIMIT = 1e100


class SceneError(ValueError):
    """Bad input: ``field`` names where (``params.delta``, ``scene [3].state.p``), ``rule`` what was broken."""

    def __init__(self, field: str, rule: str):
        super().__init__(f"{field}: {rule}")
        self.field, self.rule = field, rule

    def within(self, prefix: str) -> SceneError:
        """The same error one level down, e.g. inside scene [3] of a list; each field of a list of them
        ("params.delta, params.g") is put under the prefix."""
        def under(field: str) -> str:
            if field == "scene" or field.startswith("scene."):
                return prefix + field[len("scene"):]
            return f"{prefix}.{field}"

        return type(self)(", ".join(under(field) for field in self.field.split(", ")), self.rule)


class UnrepresentableError(SceneError):
    """A motion whose times, lengths or speeds cannot be represented in float64."""


class ComputationError(ArithmeticError):
    """A computation that failed on valid input: a result came out non-finite, or a loop reached its bound."""


class WorkLimitError(ComputationError):
    """A numerical loop reached its bound on work (steps, iterations, horizon doublings)."""


class ToleranceWarning(UserWarning):
    """A result whose error estimate is above TOL_WARNING × the tolerance asked: the tolerance may be missed."""


# An estimate this many times the tolerance asked says the tolerance may be missed.  Estimates stay below 20× it
# (at tol 1e-13; 5× at 1e-10) on the 163 bench and calibration scenes and 20,000 pool shots (bench.timing_states),
# but a long lever makes them pessimistic: 1,023× with errors of 0.15× on random shots at δ = 0.9999 fR (an audit of
# tests/numerics/test_batch.py's set).  Above 1,000× were shots float64 or the integrator cannot resolve that
# finely, off by 4.6 to 440× tol (a start 100 km from the origin at tol 1e-12, k = 0.002 R: audits; that ball now
# slides again, `engine.RERUN_SPIN_RATIO`, and is within tol); below it a miss goes unwarned (1.6× and 3.7× on 2 of
# 800 random shots 319 m and 6 km from the origin, each an ulp of its coordinates off).  README, "Error estimates".
TOL_WARNING = 1000.0


def beyond_tolerance(estimate, tol: float) -> str | None:
    """What to warn of when ``estimate`` (None: no rest point) is above TOL_WARNING × ``tol``; else None."""
    if estimate is None or not estimate > TOL_WARNING * tol:
        return None
    ratio = estimate / tol
    times = f"{ratio:,.0f}" if ratio < 1e6 else f"{ratio:.1e}"  # (1e85 m from the origin: 86 digits, an audit)
    return (f"the rest point's estimated relative error {estimate:.1e} is {times}× the tolerance asked ({tol:g}): "
            f"the tolerance may be missed (README, 'Error estimates')")


def describe(value) -> str:
    """A short, safe rendering of any value for an error message."""
    try:
        text = repr(value)
    except Exception:  # noqa: BLE001  a hostile __repr__ must not turn a message into a traceback
        text = f"<{type(value).__name__}>"
    text = text.replace("\r", "\\r").replace("\n", "\\n")  # one line, whatever the value
    return text if len(text) <= 40 else text[:37] + "..."


def key_name(where: str, key) -> str:
    """The field ``key`` of ``where``, printable on one line: params.delta, or params['\\n'] for odd keys."""
    if isinstance(key, str) and key.isidentifier():
        return f"{where}.{key}"
    return f"{where}[{describe(key)}]"


REAL_TYPES = (numbers.Real, Decimal, Fraction)  # and mpmath's mpf, by name (mpmath is not imported here)


def is_real(value) -> bool:
    """Whether `real` takes ``value`` as a number at all (before its range): not a bool or text."""
    kind = type(value).__name__
    return not isinstance(value, (bool, str, bytes)) and kind != "bool_" and (isinstance(value, REAL_TYPES) or kind == "mpf")


def real(value, field: str) -> float:
    """A finite float64 from any real number (int, float, NumPy scalar, Decimal, Fraction, mpmath), or SceneError.

    Refused: bool (JSON's true is no speed), strings, complex numbers, NaN, ±∞, and
    integers beyond float64's range.
    """
    if not is_real(value):
        what = "a real number" if isinstance(value, numbers.Complex) and not isinstance(value, numbers.Real) else "a number"
        raise SceneError(field, f"must be {what}, got {describe(value)}")
    try:
        number = float(value)
    except OverflowError:
        raise SceneError(field, f"must be within float64's range (|x| < 1.8e308), got {describe(value)}") from None
    except (TypeError, ValueError):
        raise SceneError(field, f"must be a number, got {describe(value)}") from None
    if not math.isfinite(number):
        finite_source = isinstance(value, (numbers.Integral, Fraction)) or (isinstance(value, Decimal) and value.is_finite())
        if finite_source:
            raise SceneError(field, f"must be within float64's range (|x| < 1.8e308), got {_given(value)}")
        raise SceneError(field, f"must be finite, got {number}")
    if number == 0 and value != 0:  # 1e-400 read as 0: a ball that was moving would lie still
        raise SceneError(field, f"must be 0 or at least 4.9e-324 in size (float64's smallest), got {_given(value)}")
    return number


def _given(value) -> str:
    """A number as the user wrote it: a JSON literal beyond float64 is read as a Decimal (`decimal_beyond_float`)."""
    if not isinstance(value, Decimal):
        return describe(value)
    text = str(value)
    return text if len(text) <= 40 else text[:37] + "..."


def int_beyond_str_limit(literal: str):
    """A JSON integer literal as an int, or, past Python's limit on reading one (4,300 digits: json.loads raised and
    the file, not the field, was named), as a Decimal, which `real` refuses by its field (json.loads' parse_int)."""
    return int(literal) if len(literal) <= 4000 else Decimal(literal)


def decimal_beyond_float(literal: str):
    """A JSON number literal as a float, or as a Decimal where float64 cannot hold it (1e400 read as ∞, 1e-400 as
    0), so that `real` refuses it by the name of its field rather than take ∞ or 0 for it (json.loads' parse_float)."""
    number = float(literal)
    if math.isinf(number) or (number == 0 and any(ch in "123456789" for ch in literal.lower().split("e")[0])):
        try:
            return Decimal(literal)
        except InvalidOperation:  # an exponent past Decimal's own (1e10¹⁸): a traceback once (an audit)
            return _Literal(literal, huge=math.isinf(number))
    return number


class _Literal(Decimal):
    """A number literal beyond Decimal's exponents: the largest (or smallest) Decimal of its sign, which `real`
    refuses as it would the literal, and the literal as written, which the refusal quotes."""

    def __new__(cls, literal: str, huge: bool):
        sign = "-" if literal.lstrip().startswith("-") else ""
        self = super().__new__(cls, f"{sign}1E{MAX_EMAX if huge else MIN_ETINY}")
        self.literal = literal
        return self

    def __str__(self) -> str:
        return self.literal


def tolerance(tol, field: str = "tol") -> float:
    """A relative tolerance of the numerical slide, within `TOL_RANGE`."""
    if type(tol) is float and TOL_RANGE[0] <= tol <= TOL_RANGE[1]:  # the common case, on every call of simulate
        return tol
    tol = real(tol, field)
    if not TOL_RANGE[0] <= tol <= TOL_RANGE[1]:
        raise SceneError(field, f"must be between {TOL_RANGE[0]:g} and {TOL_RANGE[1]:g}, got {tol!r}")  # !r: 1.0000001e-05 is not 1e-05
    return tol


def model(name, field: str = "model") -> str:
    if not isinstance(name, str) or name not in MODELS:
        raise SceneError(field, f"must be one of {', '.join(MODELS)}, got {describe(name)}")
    return name


def workers(n, field: str = "workers") -> int:
    """A number of worker processes: an integer >= 1."""
    if type(n) is int and n >= 1:  # the common case, on every call of simulate_many (chunk), without the ABC check
        return n
    if isinstance(n, bool) or not isinstance(n, numbers.Integral) or n < 1:
        raise SceneError(field, f"must be an integer >= 1, got {describe(n)}")
    return int(n)


def fields(obj, where: str, required: tuple, optional: tuple = ()) -> dict:
    """The named fields of a decoded JSON object, each a finite real; unknown and missing ones refused."""
    if not isinstance(obj, dict):
        raise SceneError(where, f"must be an object, got {describe(obj)}")
    allowed = required + optional
    unknown = sorted((name for name in obj if name not in allowed), key=str)
    if unknown:
        raise SceneError(key_name(where, unknown[0]), f"unknown field (allowed: {', '.join(allowed)})")
    missing = [name for name in required if name not in obj]
    if missing:
        raise SceneError(f"{where}.{missing[0]}", "missing")
    return {name: real(obj[name], f"{where}.{name}") for name in allowed if name in obj}


def scale_error(where: str, name: str, value: float) -> UnrepresentableError:
    """The error for a motion whose characteristic time, length or speed (named) is not far inside float64."""
    return UnrepresentableError(
        where, f"the motion's {name} would be {value:.3g}, not below {SCALE_LIMIT:.0e}: its times, lengths "
        "or speeds cannot be represented in float64 (speeds or spins too large or tiny, or coefficients too small or too large)",
    )


def in_scene(index: int, error: Exception) -> str:
    """An error of scene ``index`` of a list, as one line naming it: "scene [4812].state.p: must be finite, got nan"."""
    if isinstance(error, SceneError):
        return str(error.within(f"scene [{index}]"))
    return f"scene [{index}].{error}"
