"""The benchmark's fixed, seeded scenes and their 40-digit mpmath reference, cached on disk.

Scenes: the realistic pool shots of `classical_vs_appell`, every hard case
of `hard_cases`, seeded random general shots, and seeded fast, high-spin
shots on random cloths (each with its own parameters).  The reference is
`reference_motion.reference` at 40 digits (no closed form); each scene's
entry is stored under a hash of the scene and the digits, so a rerun only
computes what changed, and deleting the file regenerates everything.
"""

from __future__ import annotations

import dataclasses
import hashlib
import json
import os
from pathlib import Path

import mpmath
import numpy as np

from numerics import classical_vs_appell, hard_cases, reference_motion
from numerics.files import replace_file
from numerics.scene import Params, Scene, State
from numerics.workers import fork_pool

REFERENCE_DIGITS = 40
CACHE = Path(__file__).resolve().parent.parent / "paper" / "data" / "bench_reference.json"
N_RANDOM = 12
N_FAST = 12
SEED = 1911


def random_states(n: int, seed: int = SEED) -> np.ndarray:
    """General shots (ξ, η, ξ', η', p, q, r): speeds to 4 m/s, spins to 150 rad/s, in any direction."""
    rng = np.random.default_rng(seed)
    return np.column_stack([
        np.zeros(n), np.zeros(n), rng.uniform(0.2, 4.0, n), rng.uniform(-1.0, 1.0, n),
        rng.uniform(-150, 150, n), rng.uniform(-150, 150, n), rng.uniform(-50, 50, n),
    ])


def fast_scenes(n: int = N_FAST, seed: int = SEED + 940) -> dict[str, Scene]:
    """Fast, high-spin shots on random cloths, each with its own parameters: f 0.1–0.3, δ 0.1–1.2 mm,
    ε to 1 mm, speeds to 8 m/s, spins to 300 rad/s about either horizontal axis and 100 about the vertical.
    Where a tolerance is most easily missed (a scene like these, 6.8 m/s, δ = 1 mm, once was)."""
    rng = np.random.default_rng(seed)
    out = {}
    for i in range(n):
        params = Params(f=rng.uniform(0.1, 0.3), delta=rng.uniform(0.1e-3, 1.2e-3), epsilon=rng.uniform(0, 1e-3), R=0.028575)
        speed, angle = rng.uniform(0.5, 8.0), rng.uniform(0, 2 * np.pi)
        state = State(0.0, 0.0, speed * np.cos(angle), speed * np.sin(angle), *rng.uniform(-300, 300, 2), rng.uniform(-100, 100))
        out[f"fast {i:02d}"] = Scene(params, state, ())
    return out


def scenes() -> dict[str, Scene]:
    out = {f"shot: {name}": Scene(classical_vs_appell.POOL, s, ()) for name, s in classical_vs_appell.SHOTS.items()}
    out.update({f"hard: {name}": dataclasses.replace(s, times=()) for name, s in hard_cases.hard_cases().items()})
    for i, row in enumerate(random_states(N_RANDOM)):
        out[f"random {i:02d}"] = Scene(classical_vs_appell.POOL, State(*map(float, row)), ())
    out.update(fast_scenes())
    return out


def key(scene: Scene, digits: int) -> str:
    text = json.dumps([dataclasses.asdict(scene.params), dataclasses.asdict(scene.state), scene.model, digits])
    return hashlib.sha256(text.encode()).hexdigest()[:16]


def _as_text(x, digits: int = REFERENCE_DIGITS) -> str | None:
    return None if x is None else mpmath.nstr(x, digits + 5)


def compute(scene: Scene, digits: int = REFERENCE_DIGITS) -> dict:
    """The reference quantities of one scene, as decimal strings (digits + 5 significant digits)."""
    ref = reference_motion.reference(scene, digits=digits)
    end = ref.slide_end

    def text(x):
        return _as_text(x, digits)

    return {
        "t_slide_end": text(ref.t_slide_end),
        "t_roll_end": text(ref.t_roll_end),
        "t_pivot_end": text(ref.t_pivot_end),
        "rest": None if ref.rest is None else [text(x) for x in ref.rest],
        "omega_end": [text(scene.state.p), text(scene.state.q)] if end is None else [text(end.p), text(end.q)],
    }


def _compute_item(item):
    name, scene, digits = item
    return name, compute(scene, digits)


CALIBRATION_CACHE = CACHE.with_name("calibration_reference.json")
CALIBRATION_DIGITS = 20  # enough for tolerances down to 1e-13


def calibration_scenes() -> dict[str, Scene]:
    """120 more fast, high-spin shots on random cloths (`fast_scenes`, two other seeds): the set the engine's
    TOL_SAFETY and ESTIMATE_MARGIN were measured on, and that `appell bench` and the tests keep measuring."""
    shots = list(fast_scenes(80, seed=4242).values()) + list(fast_scenes(40, seed=777).values())
    return {f"calibration {i:03d}": s for i, s in enumerate(shots)}


def references(progress=None, workers: int | None = None, calibration: bool = False) -> dict[str, dict]:
    """Name -> reference of every scene (of `scenes`, or of `calibration_scenes`), from the cache or computed
    (in worker processes) and cached."""
    chosen, digits, path = (calibration_scenes(), CALIBRATION_DIGITS, CALIBRATION_CACHE) if calibration else \
        (scenes(), REFERENCE_DIGITS, CACHE)
    try:
        cache = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError):  # missing or damaged: computed again (and the file rewritten whole)
        cache = {}
    todo = {name: s for name, s in chosen.items() if key(s, digits) not in cache}
    if todo:
        workers = workers or len(os.sched_getaffinity(0))
        with fork_pool(workers) as pool:
            for name, entry in pool.imap_unordered(_compute_item, [(n, s, digits) for n, s in todo.items()]):
                cache[key(todo[name], digits)] = {"scene": name, **entry}
                replace_file(path, json.dumps(dict(sorted(cache.items())), indent=1) + "\n")
                if progress:
                    progress(name)
    return {name: cache[key(s, digits)] for name, s in chosen.items()}
