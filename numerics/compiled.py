"""The engine compiled by numba: the same code as `engine` and `kernels`, a machine-code copy of each function.

Numba compiles a function from its bytecode and the globals it sees; here
every function of `kernels` and `engine` is copied into one shared namespace
in which its callees are the compiled copies, so the whole call graph
compiles while the interpreted originals stay untouched (the command line
uses them for a single scene: nothing to compile there).  Compiled code
releases the GIL (``nogil``): `batch.simulate_many` spreads chunks of a batch
over threads — numba's own ``parallel`` (OpenMP) starts its team in 1.7 µs
when called back to back but ~50 µs after 10 ms idle, as a pool thread does,
and GNU OpenMP makes a forked child abort (a user's multiprocessing).
Compiled code is cached on disk (``cache=True``): the first run of each copy
of this source compiles (its cost is measured in the README), later processes
load it.  Numba keys its cache by the source's folder too (`copy_folder`): a
new checkout, or the package installed elsewhere, compiles again, as does
another numba or a changed engine (`cache_folder`).
"""

from __future__ import annotations

import hashlib
import os
import sys
import tempfile
import types
from pathlib import Path

import llvmlite.binding as llvm
import numba
from numba.core import caching
from numba.extending import intrinsic

from numerics import dop853_steps, engine, kernels, lane_rows, lanes, vector_exp

MODULES = (lane_rows, vector_exp, kernels, dop853_steps, engine, lanes)


def cache_folder() -> Path:
    """Where the compiled code is kept: $APPELL_NUMBA_CACHE (make check and make test keep it in build/numba,
    so that test runs share it) or else the user's cache (as the verification record, `paper.record`), in
    a folder named by a hash of these modules, of this file and of numba's version — numba itself only
    checks the timestamp of the file a function comes from, so a change here or an upgrade would otherwise
    load stale code.  Only this folder is written (never the package's own, which may be read-only)."""
    from paper.record import folder

    digest = hashlib.sha256(numba.__version__.encode())
    for path in [Path(__file__)] + [Path(m.__file__) for m in MODULES]:
        digest.update(path.read_bytes())
    base = Path(os.environ["APPELL_NUMBA_CACHE"]) if os.environ.get("APPELL_NUMBA_CACHE") else folder()
    return base / f"numba-{digest.hexdigest()[:16]}"


def unusable(folder: Path) -> str | None:
    """Why compiled code cannot be kept in ``folder`` (created if need be), or None.  Numba, finding it
    unwritable, would keep it in the package's own __pycache__ instead: keyed there by timestamps only, and
    written where nothing asked (an audit: 55 files)."""
    try:
        folder.mkdir(parents=True, exist_ok=True)
        with tempfile.TemporaryFile(dir=folder):
            pass
    except OSError as error:
        return error.strerror or str(error)
    return None


numba.config.CACHE_DIR = str(cache_folder())
# Where the cache cannot be kept, compiled in memory for this process only, and said once.
CACHE = unusable(Path(numba.config.CACHE_DIR))
if CACHE is not None:
    print(f"appell: cannot keep the compiled engine in {numba.config.CACHE_DIR} ({CACHE}; $APPELL_NUMBA_CACHE sets "
          "the folder): compiling it for this process only, up to a minute each time", file=sys.stderr, flush=True)


def copy_folder(folder: Path) -> Path:
    """Where in the cache ``folder`` numba keeps this copy's compiled code: a subfolder named by the path of the
    engine's source folder (numba's `_CacheLocator`), so that another checkout of the same source compiles anew
    (measured: 52 s for a copy of the checkout beside a full cache of the original)."""
    return folder / caching._CacheLocator.get_suitable_cache_subpath(engine.__file__)


def announce_first_compile(folder: Path, stream) -> bool:
    """One line on ``stream`` when someone reads it (a terminal, or a Jupyter notebook) and ``folder`` holds no
    compiled code of this copy yet: the first call then compiles for up to a minute (README, "Start-up"), which
    would otherwise pass without a word.  A pipe or a log stays silent."""
    # (no stderr at all under pythonw or a daemon; a notebook's stderr is no terminal but is shown under the cell)
    read = stream is not None and (stream.isatty() or "ipykernel" in sys.modules)
    if not read or any(copy_folder(folder).glob("*.nbi")):  # numba's index of each cached function
        return False
    print(f"appell: compiling the simulator's engine, once for this copy of appell (up to a minute; kept in {folder})",
          file=stream, flush=True)
    return True


if CACHE is None:
    announce_first_compile(Path(numba.config.CACHE_DIR), sys.stderr)

_save_overload = caching.Cache.save_overload


def _save_or_keep_in_memory(cache, signature, data):
    """Numba's `Cache.save_overload`, except that for this engine's functions a cache folder that fills up (or
    fails) while the code is saved leaves the compiled code in memory for this process, said once: a full disk
    under $APPELL_NUMBA_CACHE was an error blamed on standard output (an audit).  Numba removes its half file."""
    global CACHE
    try:
        _save_overload(cache, signature, data)
    except OSError as error:
        if getattr(cache._py_func, "__module__", None) not in NAMES:  # another's numba code: numba's own behaviour
            raise
        cache.disable()
        if CACHE is None:
            CACHE = error.strerror or str(error)
            print(f"appell: cannot keep the compiled engine in {numba.config.CACHE_DIR} ({CACHE}; $APPELL_NUMBA_CACHE "
                  "sets the folder): compiled for this process only", file=sys.stderr, flush=True)


NAMES = {module.__name__ for module in MODULES}
caching.Cache.save_overload = _save_or_keep_in_memory

# No fast-math at all, not even fused multiply-adds: IEEE arithmetic, each operation rounded once, so that
# the lanes' vector code and a single scene's scalar code give the same bits (tested: a batch is its scenes
# one by one).  Fusing would save a quarter of the lanes' time, but the compiler fuses differently in each.
# Not "arcp" either (1/Ω overflows for a subnormal spin where p/Ω does not: found by the property tests).
FASTMATH = set()
# NumPy's error model: a division by zero gives ∞ or NaN (every row's status check catches them) instead of
# a test and a raise at each division, which keeps the loops over lanes from being vectorised (`lanes`).
ERROR_MODEL = "numpy"
# What is left of a loop after its 8-lane vector body, run as a 4-lane vector instead of one by one (LLVM's
# vector epilogue: by default only after a body of 16 or more).  The lanes round their busy lanes up to 4
# (`lanes.VECTOR`).  An option of LLVM, so for every loop compiled in this process: it changes which
# instructions run, and no result of code without fast-math (this engine's: the same operations, each rounded
# once; the README says so for other numba code in the process).
EPILOGUE = "-epilogue-vectorization-force-VF=4"
llvm.set_option("", EPILOGUE)
# Small functions called once per stage: inlined into their caller (a call passing arrays costs more than them).
# Not the lanes' stages: each is a loop over lanes, vectorised best on its own; but the lanes' rate loop
# and the step norms' terms (_rates_from, _norm_terms, lanes_error_terms), so that the rows their callers give
# them are constants (`numerics.lane_rows`).
INLINE = ("exp", "_store", "rates_in_sigma", "rates_at", "unit_rotation", "slide_rates", "turn_norm", "step_norm", "accept",
          "step_factor", "_rates_from", "_norm_terms", "lanes_error_terms")


@intrinsic
def _float_bits(typingctx, x):
    """`vector_exp.float_bits` compiled: a bitcast, no instruction (a vector loop keeps it in its registers)."""
    def codegen(context, builder, signature, args):
        return builder.bitcast(args[0], context.get_value_type(numba.types.int64))
    return numba.types.int64(numba.types.float64), codegen


@intrinsic
def _bits_float(typingctx, n):
    """`vector_exp.bits_float` compiled: a bitcast."""
    def codegen(context, builder, signature, args):
        return builder.bitcast(args[0], context.get_value_type(numba.types.float64))
    return numba.types.float64(numba.types.int64), codegen


# The interpreted engine's primitives that compile as something else: `vector_exp` reads a float's bits through
# the struct module, which numba does not compile, and which compiled is a reinterpretation of the register.
COMPILED_AS = {"float_bits": _float_bits, "bits_float": _bits_float}


def _compile(modules) -> dict:
    namespace: dict = {}
    for module in modules:
        namespace.update(vars(module))
    for module in modules:
        for name, value in vars(module).items():
            if name in COMPILED_AS:
                namespace[name] = COMPILED_AS[name]
            elif isinstance(value, types.FunctionType) and value.__module__ == module.__name__:
                copy = types.FunctionType(value.__code__, namespace, name, value.__defaults__, value.__closure__)
                copy.__module__, copy.__qualname__ = value.__module__, value.__qualname__
                inline = "always" if name in INLINE or (module is dop853_steps and not name.startswith("lanes")) else "never"
                namespace[name] = numba.njit(cache=CACHE is None, nogil=True, inline=inline, fastmath=FASTMATH,
                                             error_model=ERROR_MODEL)(copy)
    return namespace


_COMPILED = _compile(MODULES)
solve = _COMPILED["solve"]
solve_many = _COMPILED["solve_many"]  # `lanes.solve_many`
states_at = _COMPILED["states_at"]
first_order_end = _COMPILED["first_order_end"]  # for the peers of `appell bench`, which finish as the engine does
roll = _COMPILED["roll"]
motion_scales = _COMPILED["motion_scales"]  # the bounds every scene of a batch is checked against, before work
all_within = _COMPILED["all_within"]  # the common case of that check, in one pass (`batch.bad_rows`)
