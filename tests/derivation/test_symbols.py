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


def test_snapshot_refuses_a_derivative_in_another_variable():
    x = sp.Symbol("x")
    f = sp.Function("F")(x)
    try:
        snapshot(sp.Derivative(f, x))
    except ValueError:
        return
    raise AssertionError("a derivative in x was accepted")


def test_labels_are_distinct_from_paper_symbols():
    assert label("V", "V") != snapshot_symbol(V)
