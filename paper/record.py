"""The verification record, kept between runs: `appell errata` and `appell reduce` answer from it.

Checking every claim takes a minute; the errata and the reduction's results
change only when the package's source or the versions of what computes them
change.  So the record of the last `appell verify` (the verdicts, the errata,
the reduction's results) is kept in the user's cache folder under a key that
hashes every source file of derivation/, reduction/ and numerics/ (and the
transcription) with the versions of Python, SymPy, mpmath and NumPy.  A
record under another key is never read.  The cache folder is
``$APPELL_CACHE``, else ``$XDG_CACHE_HOME/appell``, else ``~/.cache/appell``;
only files named ``record-<key>.json`` are written there.
"""

from __future__ import annotations

import hashlib
import json
import os
import sys
from pathlib import Path

from numerics.files import replace_file

ROOT = Path(__file__).resolve().parent.parent
SOURCES = ("derivation", "reduction", "numerics")


def source_key() -> str:
    """A hash of every source file a verdict depends on (derivation/, reduction/, numerics/ and the
    transcription): the appendix names it, so that a reader can tell which source it comes from."""
    digest = hashlib.sha256()
    for package in SOURCES:
        for path in sorted((ROOT / package).rglob("*")):
            if path.suffix in (".py", ".txt") and "__pycache__" not in path.parts:
                digest.update(str(path.relative_to(ROOT)).encode() + b"\0" + path.read_bytes() + b"\0")
    return digest.hexdigest()[:20]


def measured_from(recorded: str | None, current: str, code=str) -> str:
    """Which source a saved measurement (`appell bench`, `appell costs`) was taken from, against the source
    ``current`` it is shown with: a timing from an earlier source is said to be one, never passed off as this
    source's (the files keep the key they were measured on).  ``code`` typesets the earlier key; None leaves it
    out (a caption's plain text would set a hex key as a product of symbols)."""
    if recorded is None:
        return "from a source not recorded"
    if recorded == current:
        return "from this source"
    return f"from an earlier source (key {code(recorded)})" if code else "from an earlier source than this appendix's"


def key() -> str:
    """A hash of everything a verdict depends on: the source and the versions of the arithmetic."""
    import mpmath
    import numpy
    import sympy

    digest = hashlib.sha256(source_key().encode() + b"\0")
    for version in (sys.version, sympy.__version__, mpmath.__version__, numpy.__version__):
        digest.update(version.encode() + b"\0")
    return digest.hexdigest()[:20]


def folder() -> Path:
    if os.environ.get("APPELL_CACHE"):
        return Path(os.environ["APPELL_CACHE"])
    base = os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache"
    return Path(base) / "appell"


def unwritable() -> str | None:
    """Why the cache folder cannot keep a record (None: it can, as far as can be told before writing): said
    before the minutes of checking, not after (an audit: a file named as $APPELL_CACHE was found only then)."""
    where = folder()
    probe = where
    while not probe.exists() and probe != probe.parent:  # `replace_file` makes the missing folders
        probe = probe.parent
    if not probe.is_dir():
        return f"{probe} is not a folder"
    if not os.access(probe, os.W_OK | os.X_OK):
        return f"{probe} cannot be written"
    return None


def path(record_key: str | None = None) -> Path:
    return folder() / f"record-{record_key or key()}.json"


MAX_BYTES = 16 * 2**20  # a record is about 70 kB: one far larger is not one appell wrote


def load() -> dict | None:
    """The record for the current source and versions, or None."""
    kept = path()
    try:
        if not kept.is_file():  # a named pipe or a device put there would block, or never end (an audit: /dev/zero)
            return None
        with open(kept, "rb") as handle:
            raw = handle.read(MAX_BYTES + 1)
        if len(raw) > MAX_BYTES:
            return None
        data = json.loads(raw.decode("utf-8"))
    except (OSError, ValueError):
        return None
    # A record is a cache: one not in the shape `save` writes (truncated, edited, another program's) is a miss.
    if not (isinstance(data, dict) and data.get("key") == key() and isinstance(data.get("verify"), dict)
            and isinstance(data["verify"].get("claims"), list) and all(isinstance(row, dict) and "id" in row
                                                                         for row in data["verify"]["claims"])
            and isinstance(data.get("errata"), list)):
        return None
    return data


def save(data: dict) -> Path | None:
    """Write the record whole or not at all (`numerics.files.replace_file`: a full disk or Ctrl-C leaves no
    half-written file behind); None when the cache folder cannot be written (then nothing is kept)."""
    data = {**data, "key": key()}
    target = path(data["key"])
    try:
        replace_file(target, json.dumps(data, ensure_ascii=False))
    except OSError:
        return None
    return target
