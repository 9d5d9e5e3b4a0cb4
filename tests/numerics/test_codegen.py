"""The generated kernels: up to date with the derivation, equal to its SymPy expressions, and the only
formulas the simulator needs at run time (no SymPy imported)."""

import math
import random
import subprocess
import sys

import numpy as np
import pytest
import sympy as sp

from numerics import codegen, dop853_tables, kernels


def test_committed_kernels_are_up_to_date(capsys):
    assert codegen.main(["--check"]) == 0
    assert "up to date" in capsys.readouterr().out


@pytest.mark.parametrize("which", ["KERNELS", "STEPS"])
def test_the_staleness_check_fails_on_an_edited_file(tmp_path, monkeypatch, capsys, which):
    # Mutation: one coefficient changed by hand in a copy; --check must name the file and fail.
    path = getattr(codegen, which)
    copy = tmp_path / path.name
    text = path.read_text(encoding="utf-8")
    copy.write_text(text.replace("*", " * ", 1), encoding="utf-8")
    monkeypatch.setattr(codegen, which, copy)
    monkeypatch.setattr(codegen, "generated", lambda: {codegen.KERNELS: codegen.source(), codegen.STEPS: codegen.steps_source()})
    assert codegen.main(["--check"]) == 1
    assert f"stale: {path.name}" in capsys.readouterr().err
    copy.unlink()  # a missing file is stale too
    assert codegen.main(["--check"]) == 1


@pytest.mark.parametrize("kernel", codegen.kernels(), ids=lambda k: k.name)
def test_each_kernel_equals_its_sympy_expressions(kernel):
    """The generated Python (after cse and printing) against the expressions it came from, at random points,
    evaluated by SymPy itself at 30 digits: what numba compiles is what the derivation says."""
    rng = random.Random(kernel.name)
    fn = getattr(kernels, kernel.name)
    for _ in range(5):
        values = {}
        for a in kernel.args:
            name = codegen._name(a)
            if name in ("cos_alpha", "cos_beta"):
                angle = rng.uniform(-math.pi, math.pi)
                values[a] = math.cos(angle)
                values[sp.Symbol(name.replace("cos", "sin"), real=True)] = math.sin(angle)
            elif name == "tau":
                values[a] = rng.uniform(0.0, 0.05)  # inside every phase of the parameters below
            elif name in ("f", "R", "k", "delta", "epsilon", "g"):
                values[a] = {"f": 0.2, "R": 0.03, "k": 0.019, "delta": 0.0015, "epsilon": 0.0008, "g": 9.81}[name]
            elif not any(s.name == a.name for s in values):
                values[a] = rng.uniform(0.5, 3.0)
        args = [values[next(s for s in values if s.name == a.name)] for a in kernel.args]
        got = fn(*args)
        got = got if isinstance(got, tuple) else (got,)
        subs = {a: sp.Float(v, 30) for a, v in zip(kernel.args, args)}
        for value, expr in zip(got, kernel.outputs):
            want = complex(sp.sympify(expr).evalf(30, subs=subs))
            assert want.imag == 0
            assert value == pytest.approx(want.real, rel=1e-12, abs=1e-14), kernel.name


def test_dop853_tables_are_consistent_and_scipys():
    """The row sums of A are the nodes C and the weights sum to 1 (the order conditions of lowest order),
    and every coefficient is SciPy's own (whose tables Hairer's code was transcribed into)."""
    t = dop853_tables
    n = t.N_STAGES
    assert np.allclose(t.A[:n, :n].sum(axis=1), t.C[:n], rtol=0, atol=1e-15)
    assert abs(t.B.sum() - 1) < 1e-15
    scipy_tables = pytest.importorskip("scipy.integrate._ivp.dop853_coefficients")
    assert np.array_equal(t.A, scipy_tables.A) and np.array_equal(t.C, scipy_tables.C)
    assert np.array_equal(t.B, scipy_tables.B) and np.array_equal(t.D, scipy_tables.D)
    assert np.array_equal(t.E3, scipy_tables.E3) and np.array_equal(t.E5, scipy_tables.E5)


def test_the_simulator_imports_no_sympy():
    """Design notes, 'generated, not re-derived at run time': a scene simulated (compiled and interpreted,
    one and many, states inside the slide) and no SymPy or derivation module loaded."""
    code = (
        "import sys, numpy as np\n"
        "from numerics.scene import load\n"
        "from numerics.simulate import simulate\n"
        "from numerics.batch import simulate_many\n"
        "s = load('numerics/scenes/sample.json')\n"
        "simulate(load('numerics/scenes/cue.json'), jit=False)\n"
        "m = simulate(s, jit=False); m.states(np.linspace(0, m.t_slide_end, 5))\n"
        "simulate(s).state_at(0.01)\n"
        "simulate_many(s.params, np.array([s.state.row()] * 3))\n"
        "loaded = [n for n in sys.modules if n.split('.')[0] in ('sympy', 'derivation', 'reduction')]\n"
        "print(loaded)\n"
        "sys.exit(1 if loaded else 0)\n"
    )
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert done.returncode == 0, done.stdout + done.stderr
