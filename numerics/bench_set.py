"""The benchmark's fixed, seeded scenes and their 40-digit mpmath reference, cached on disk.

Scenes: the realistic pool shots of `classical_vs_appell`, every hard case
of `hard_cases`, and seeded random general shots.  The reference is
`reference_motion.reference` at 40 digits (no closed form); each scene's
entry is stored under a hash of the scene and the digits, so a rerun only
computes what changed, and deleting the file regenerates everything.
"""

from __future__ import annotations

import dataclasses
import hashlib
import json
import multiprocessing
import os
from pathlib import Path

import mpmath
import numpy as np

from numerics import classical_vs_appell, hard_cases, reference_motion
from numerics.scene import Scene, State

REFERENCE_DIGITS = 40
CACHE = Path(__file__).resolve().parent.parent / "paper" / "data" / "bench_reference.json"
N_RANDOM = 12
SEED = 1911


def random_states(n: int, seed: int = SEED) -> np.ndarray:
    """General shots (ξ, η, ξ', η', p, q, r): speeds to 4 m/s, spins to 150 rad/s, in any direction."""
    rng = np.random.default_rng(seed)
    return np.column_stack([
        np.zeros(n), np.zeros(n), rng.uniform(0.2, 4.0, n), rng.uniform(-1.0, 1.0, n),
        rng.uniform(-150, 150, n), rng.uniform(-150, 150, n), rng.uniform(-50, 50, n),
    ])


def scenes() -> dict[str, Scene]:
    out = {f"shot: {name}": Scene(classical_vs_appell.POOL, s, ()) for name, s in classical_vs_appell.SHOTS.items()}
    out.update({f"hard: {name}": dataclasses.replace(s, times=()) for name, s in hard_cases.hard_cases().items()})
    for i, row in enumerate(random_states(N_RANDOM)):
        out[f"random {i:02d}"] = Scene(classical_vs_appell.POOL, State(*map(float, row)), ())
    return out


def key(scene: Scene, digits: int) -> str:
    text = json.dumps([dataclasses.asdict(scene.params), dataclasses.asdict(scene.state), scene.model, digits])
    return hashlib.sha256(text.encode()).hexdigest()[:16]


def _as_text(x) -> str | None:
    return None if x is None else mpmath.nstr(x, REFERENCE_DIGITS + 5)


def compute(scene: Scene, digits: int = REFERENCE_DIGITS) -> dict:
    """The reference quantities of one scene, as decimal strings."""
    ref = reference_motion.reference(scene, digits=digits)
    end = ref.slide_end
    return {
        "t_slide_end": _as_text(ref.t_slide_end),
        "t_roll_end": _as_text(ref.t_roll_end),
        "t_pivot_end": _as_text(ref.t_pivot_end),
        "rest": None if ref.rest is None else [_as_text(x) for x in ref.rest],
        "omega_end": [_as_text(scene.state.p), _as_text(scene.state.q)] if end is None else [_as_text(end.p), _as_text(end.q)],
    }


def _compute_item(item):
    name, scene = item
    return name, compute(scene)


def references(progress=None, workers: int | None = None) -> dict[str, dict]:
    """Name -> reference of every scene, from the cache or computed (in worker processes) and cached."""
    cache = json.loads(CACHE.read_text()) if CACHE.exists() else {}
    todo = {name: s for name, s in scenes().items() if key(s, REFERENCE_DIGITS) not in cache}
    if todo:
        workers = workers or len(os.sched_getaffinity(0))
        with multiprocessing.get_context("fork").Pool(workers) as pool:
            for name, entry in pool.imap_unordered(_compute_item, todo.items()):
                cache[key(todo[name], REFERENCE_DIGITS)] = {"scene": name, **entry}
                CACHE.parent.mkdir(parents=True, exist_ok=True)
                CACHE.write_text(json.dumps(dict(sorted(cache.items())), indent=1) + "\n")
                if progress:
                    progress(name)
    return {name: cache[key(s, REFERENCE_DIGITS)] for name, s in scenes().items()}
