import sympy as sp

from derivation.symbols import V, alpha, d, label, snapshot, snapshot_symbol, t, xi


def test_snapshot_names_derivatives_with_accents():
    expr = d(xi, 2) + d(xi) * V + sp.cos(alpha)
    snap = snapshot(expr)
    names = {s.name for s in snap.free_symbols}
    assert names == {"xi''", "xi'", "V", "alpha"}
    assert not snap.atoms(sp.Derivative) and not snap.has(t)


def test_snapshot_keeps_the_sign_of_magnitudes_only():
    assert snapshot_symbol(V).is_positive
    assert snapshot_symbol(V, 1).is_positive is None  # V' has no sign a priori
    assert snapshot_symbol(alpha).is_positive is None


def test_snapshot_accents_are_derivatives_in_the_function_own_variable():
    phi = sp.Symbol("phi")
    x = sp.Function("x")(phi)
    assert snapshot(sp.diff(x, phi, 2)) == sp.Symbol("x''", real=True)


def test_snapshot_refuses_a_partial_derivative():
    x, y = sp.symbols("x y")
    F = sp.Function("F")(x, y)
    try:
        snapshot(sp.Derivative(F, x))
    except ValueError:
        return
    raise AssertionError("a derivative in x was accepted")


def test_labels_are_distinct_from_paper_symbols():
    assert label("V", "V") != snapshot_symbol(V)
