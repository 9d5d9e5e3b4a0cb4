"""Replacing one of appell's own files (a cache, a data file) whole or not at all.

Written into a temporary file beside it and renamed over it: an interrupted run
leaves the old file or the new one, never half of one, and no temporary file.
The file keeps its permissions (a new one gets the umask's, as open() gives).
"""

from __future__ import annotations

import os
import secrets
import stat
from pathlib import Path


def replace_file(path, text: str | bytes) -> None:
    """Write ``text`` (str as UTF-8, or bytes: a figure) as the whole of ``path``, atomically; a symbolic link at
    ``path`` is replaced, never written through (matplotlib's savefig wrote a figure into a link's target)."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    # Created as open() creates a file (0666 less the umask; mkstemp's 0600 would make bench.json private), by name
    # beside it, exclusively: never another's file.
    temporary = path.parent / f".{path.name}-{secrets.token_hex(6)}"
    descriptor = os.open(temporary, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o666)
    try:
        with (os.fdopen(descriptor, "wb") if isinstance(text, bytes) else os.fdopen(descriptor, "w", encoding="utf-8")) as out:
            out.write(text)
        if path.exists() and not path.is_symlink():  # the file keeps its own permissions (a link's target is not ours)
            os.chmod(temporary, stat.S_IMODE(path.stat().st_mode))
        os.replace(temporary, path)
    except BaseException:  # an error or Ctrl-C: the old file stays, and nothing of ours beside it
        temporary.unlink(missing_ok=True)
        raise
