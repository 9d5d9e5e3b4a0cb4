"""Replacing one of appell's own files (a cache, a data file) whole or not at all.

Written into a temporary file beside it and renamed over it: an interrupted run
leaves the old file or the new one, never half of one, and no temporary file.
The file keeps its permissions (a new one gets the umask's, as open() gives).
"""

from __future__ import annotations

import os
import stat
import tempfile
from pathlib import Path


def replace_file(path, text: str) -> None:
    """Write ``text`` (UTF-8) as the whole of ``path``, atomically."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    try:
        mode = stat.S_IMODE(path.stat().st_mode)
    except FileNotFoundError:
        umask = os.umask(0)
        os.umask(umask)
        mode = 0o666 & ~umask
    with tempfile.NamedTemporaryFile("w", dir=path.parent, prefix=f".{path.name}-", delete=False, encoding="utf-8") as out:
        temporary = out.name
    try:  # mkstemp's file is 0600: given the file's own mode before it takes the file's place
        Path(temporary).write_text(text, encoding="utf-8")
        os.chmod(temporary, mode)
        os.replace(temporary, path)
    except BaseException:  # an error or Ctrl-C: the old file stays, and nothing of ours beside it
        Path(temporary).unlink(missing_ok=True)
        raise
