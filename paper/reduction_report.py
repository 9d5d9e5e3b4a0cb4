"""`appell reduce`: the chain of reductions from (7)–(8) to the Abel equation and its invariants.

Each step names the claim that checks it; the formulas shown are the
claims' own SymPy objects (plain text, or SymPy strings in --json).
"""

from __future__ import annotations

import sympy as sp

from derivation.symbols import theta

# The chain, in order: (claim id, what the step does).
STEPS = [
    ("eq12", "(7)–(8) in x = fV, y = δΩ, θ = β − α"),
    ("n9.constants", "a, b, c read off the derived equations"),
    ("n9.order", "a > b > c > 0 from δ < fR"),
    ("eq13", "every ratio equals dt"),
    ("eq14", "x, y as functions of θ"),
    ("n9.time", "θ against t: y − x = (a − c)t + y₀ − x₀"),
    ("n10.closed_form", "a = c: x(x + A) cos θ tan^h(θ/2 + π/4) = C"),
    ("n10.closed_form_mpmath", "… and along a 30-digit integration"),
    ("n10.violates_9", "a = c needs δ > fR: not the billiard"),
    ("n11.system", "dφ = (tan θ − a/(b cos θ)) dθ"),
    ("n11.lambda", "λ = (b sin θ − c)/(b sin θ − a)"),
    ("n11.second_order", "eliminate y: x²x'' = x'³ + λx'(x − x')²"),
    ("n11.abel", "x = exp ∫z dφ: z' = z³ − z² + λz(1 − z)²"),
    ("n11.trajectory", "… and a 40-digit trajectory solves it"),
    ("n11.abel_theta", "in θ: b cos θ z' = z(z − 1)((2b sin θ − a − c)z − (b sin θ − c))"),
    ("normal.form", "normal form du/dτ = u³ + I(τ), z = P u + Q"),
    ("normal.tau_mpmath", "τ(θ) by Appell's F₁"),
    ("inv.general", "s₃, s₅ relative invariants, J absolute (any equation, any change)"),
    ("inv.J", "J = 729 N³/((a − c)² L⁵)"),
    ("inv.s3_zero", "s₃ ≡ 0 only for a = c (n°10)"),
    ("inv.J_never_constant", "J constant for no a, b, c > 0"),
    ("inv.small_delta", "J = 729/4 + (19683/16)(b/a)²(3 sin²θ − 2) + O((b/a)³)"),
]


def _text(expr) -> str:
    return str(sp.sympify(expr))


def summary() -> dict[str, object]:
    """The results of the reduction, as SymPy strings in a, b, c, theta; {"error": reason} when a
    derivation they come from raises (its claims say which, and fail)."""
    try:
        return _results()
    except Exception as error:  # a wrong derivation fails claims, it never crashes the report
        return {"error": f"{type(error).__name__}: {' '.join(str(error).split())}"[:200]}


def _results() -> dict[str, object]:
    from reduction import invariants, n11_abel, normal_form

    abel = n11_abel.abel_in_theta()
    tr = normal_form.transformation()
    in_theta = {invariants.S: sp.sin(theta)}
    return {
        "abel": {name: _text(coef) for name, coef in zip(("f3", "f2", "f1", "f0"), abel.coefficients)},
        "s3": _text(invariants.S3),
        "s5": _text(invariants.S5),
        "J": _text(invariants.J_CLOSED.subs(in_theta)),
        "normal_form": {
            "Q": _text(tr["Q"]),
            "P": _text(tr["P"]),
            "dtau_dtheta": "f3*P**2",
            "I": "s3/(f3*P)**3",
        },
        "classes": {
            "s3_identically_zero": "a = c (n°10)",
            "J_constant": "none with a, b, c > 0",
            "delta_to_zero": "J -> 729/4 (separable z' = z**3 - z**2), J - 729/4 = O((b/a)**2)",
        },
    }


def steps(rows: list[dict]) -> list[tuple[str, str, dict]]:
    """Each step of the chain with its claim's verdict (``status``, ``symbolic``, ``numeric``) from the record."""
    by_id = {row["id"]: row for row in rows}
    return [
        (step_id, text, {k: by_id[step_id][k] for k in ("status", "symbolic", "numeric")}) for step_id, text in STEPS
    ]


def as_text(steps: list[tuple[str, str, dict]], results: dict[str, object]) -> str:
    out = ["The reduction of the sliding phase, step by step (claim, status):", ""]
    for i, (step_id, text, verdict) in enumerate(steps, 1):
        out.append(f"{i:2d}. {text}")
        out.append(f"    [{step_id}: {verdict['status']}; {verdict['symbolic']}; {verdict['numeric']}]")
    if "error" in results:
        return "\n".join(out + ["", f"The reduction's results could not be derived: {results['error']}"])
    abel = results["abel"]
    out += [
        "",
        "Abel equation dz/dθ = f3 z³ + f2 z² + f1 z + f0:",
        *(f"  {name} = {value}" for name, value in abel.items()),
        f"s3 = {results['s3']}",
        f"s5 = {results['s5']}",
        f"J  = {results['J']}",
        "",
        "Integrability: s3 ≡ 0 only for a = c (n°10, contradicts δ < fR); J is constant for no a, b, c > 0,",
        "so the billiard is in neither constant-invariant class; as δ → 0, J → 729/4 (the separable classical",
        "case) with a departure of second order in b/a = Rδ/(f(R² + k²)).",
    ]
    return "\n".join(out)
