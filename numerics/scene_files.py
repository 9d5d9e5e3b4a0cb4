"""Scene files, one or many: what `appell simulate` reads, through the rules of `numerics.validation`.

* one scene: a JSON object (`numerics.scene`);
* many scenes: a JSON list of scene objects, or states with shared params —
  a ``.csv`` whose header names the columns xi, eta, vxi, veta, p, q, r (in any
  order), or a ``.npz`` holding an array ``states`` of shape (n, 7).

Many scenes are read in full and every bad one is reported, by index, not
only the first: `read` returns the good scenes grouped for the batch path and
the errors beside them, and the caller decides whether to stop or skip.
"""

from __future__ import annotations

import csv
import io
import os
import re
import zipfile
from dataclasses import dataclass, field
from decimal import Decimal

import numpy as np

from numerics.scene import MAX_TIMES, STATE_FIELDS, Params, Scene, parse, parse_params, read_json, read_text
from numerics import validation
from numerics.validation import SceneError, decimal_beyond_float, describe, real


# A CSV cell that is a number as a table writes it (spaces around allowed; inf and nan are read, then refused by name).
NUMBER = re.compile(r"\s*[+-]?(?:(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][+-]?[0-9]+)?|inf(?:inity)?|nan)\s*", re.IGNORECASE)


@dataclass
class SceneSet:
    """Many scenes as read: the good ones, each with its params, model and times, and every bad one with its
    reason (its field within the scene: `validation.in_scene` names it in the list).

    ``params`` is one `Params` for every good scene (states with --params) or a list, one each (a JSON list).
    """

    params: Params | list
    states: np.ndarray  # (n good, 7)
    models: list[str]
    times: list[tuple]
    index: np.ndarray  # of each good scene in the input
    total: int
    errors: list[tuple[int, SceneError]] = field(default_factory=list)

    def params_of(self, k: int) -> Params:
        """The params of the ``k``-th good scene."""
        return self.params[k] if isinstance(self.params, list) else self.params


READ_EVERY = 1000  # scenes of a JSON list between two calls of ``progress``: checking one takes ~0.1 ms


def read(path, params_path=None, model: str | None = None, progress=None) -> Scene | SceneSet:
    """One `Scene` (a JSON object) or a `SceneSet` (a JSON list, .csv or .npz states with ``params_path``).

    ``model`` overrides each scene's model.  A file that cannot be read at all is a SceneError.
    ``progress(done, total)`` is called every `READ_EVERY` scenes of a JSON list as they are checked
    (100,000 scenes took 10 s, silent: a user audit).
    """
    if model is not None:
        validation.model(model)
    name = str(path)
    if name.lower().endswith((".csv", ".npz")):  # STATES.CSV as states.csv
        if params_path is None:
            raise SceneError(name, "states without params: give the params file (--params PARAMS.json)")
        params = parse_params(read_json(params_path))
        states, errors = _csv_states(path) if name.lower().endswith(".csv") else (_npz_states(path), [])
        return _checked_states(params, model or "appell", states, errors)
    data = read_json(path)
    if isinstance(data, list):
        return _scene_list(data, model, progress)
    scene = parse(data)
    return scene if model is None else Scene(scene.params, scene.state, scene.times, model)


def _scene_list(items: list, model: str | None, progress=None) -> SceneSet:
    if not items:
        raise SceneError("scenes", "no scenes (an empty list)")
    # Every scene's t together, before any is checked: 500 scenes of 100,000 times each took 83 s and 2.4 GB to
    # check, for times that only --json reports (an audit).  The bound of one scene's states, MAX_TIMES.
    asked = sum(len(item["t"]) for item in items if isinstance(item, dict) and isinstance(item.get("t"), list))
    if asked > MAX_TIMES:
        raise SceneError("t", f"at most {MAX_TIMES:,} times in a list of scenes (every scene's t together), got "
                              f"{asked:,}; Motion.states in Python takes any number")
    good, errors = [], []
    for i, item in enumerate(items):
        if progress is not None and i and i % READ_EVERY == 0:
            progress(i, len(items))
        try:
            good.append((i, parse(item)))
        except SceneError as error:
            errors.append((i, error))
    return SceneSet(
        [s.params for _, s in good], np.array([s.state.row() for _, s in good]).reshape(-1, len(STATE_FIELDS)),
        [model or s.model for _, s in good], [s.times for _, s in good], np.array([i for i, _ in good], dtype=int),
        len(items), errors,
    )


def _checked_states(params: Params, model: str, states: np.ndarray, errors: list) -> SceneSet:
    from numerics.batch import bad_rows, state_array

    states = state_array(states)
    seen = {i for i, _ in errors}
    found = [(i, e) for i, e in bad_rows(params, states) if i not in seen]
    errors = sorted(errors + found, key=lambda ie: ie[0])
    good = np.ones(len(states), dtype=bool)
    good[[i for i, _ in errors]] = False
    n = int(good.sum())
    return SceneSet(params, states[good], [model] * n, [()] * n, np.flatnonzero(good), len(states), errors)


def _csv_states(path) -> tuple[np.ndarray, list]:
    """States from a CSV whose header names the seven columns (any order), and the rows that are not
    numbers (NaN in the array, their reason in the list)."""
    text = read_text(path)
    try:  # newline=None: lines may end in \n, \r\n or \r (old Mac files)
        rows = [row for row in csv.reader(io.StringIO(text, newline=None)) if any(cell.strip() for cell in row)]
    except csv.Error as error:  # a cell longer than csv's field limit (128 KiB), a stray quote
        raise SceneError(str(path), f"not a CSV table ({error})") from None
    if not rows:
        raise SceneError(str(path), "empty: the first line must name the columns " + ",".join(STATE_FIELDS))
    header = [cell.strip() for cell in rows[0]]
    if sorted(header) != sorted(STATE_FIELDS):
        raise SceneError(
            str(path), f"the first line must name the columns {','.join(STATE_FIELDS)} (any order), got {describe(','.join(header))}"
        )
    if len(rows) == 1:
        raise SceneError(str(path), "no scenes (a header and no rows)")
    order = [header.index(name) for name in STATE_FIELDS]
    states = np.full((len(rows) - 1, len(STATE_FIELDS)), np.nan)
    errors = []
    for i, row in enumerate(rows[1:]):
        if len(row) != len(header):
            errors.append((i, SceneError("scene", f"must have {len(header)} values, got {len(row)}")))
            continue
        for j, column in enumerate(order):
            try:
                if not NUMBER.fullmatch(row[column]):  # float() also reads "1_0" and other scripts' digits as 10
                    raise ValueError(row[column])
                number = decimal_beyond_float(row[column].strip())  # 1e-400 read as 0 once: a ball set still
                states[i, j] = real(number, f"state.{STATE_FIELDS[j]}") if isinstance(number, Decimal) else number
            except SceneError as error:
                errors.append((i, error))
                break
            except ValueError:
                errors.append((i, SceneError(f"state.{STATE_FIELDS[j]}", f"must be a number, got {describe(row[column])}")))
                break
    return states, errors


def _npz_states(path) -> np.ndarray:
    where = str(path)
    if os.path.exists(path) and not os.path.isfile(path):  # a FIFO: np.load waited for a writer for ever (an audit)
        raise SceneError(where, "not a regular file: a .npz archive is read from a file")
    try:
        data = np.load(path, allow_pickle=False)
    except FileNotFoundError:
        raise SceneError(where, "cannot read (No such file or directory)") from None
    except (OSError, ValueError, EOFError, zipfile.BadZipFile) as error:
        raise SceneError(where, f"not a .npz archive ({describe(str(error))})") from None
    if not isinstance(data, np.lib.npyio.NpzFile):
        raise SceneError(where, "a bare .npy array, not a .npz archive: save with numpy.savez(path, states=array)")
    with data:
        if "states" not in data.files:
            raise SceneError(where, f"no array 'states' (n rows of {', '.join(STATE_FIELDS)})")
        try:
            states = data["states"]
        except MemoryError:  # a header declaring more than memory holds (crafted, or not a states array)
            raise SceneError(f"{where}: states", "larger than this machine's memory") from None
        except Exception as error:  # noqa: BLE001  a corrupt archive fails in zlib, NumPy's header parser, …: one line
            raise SceneError(f"{where}: states", f"cannot be read ({type(error).__name__}: {describe(str(error))})") from None
    return states
