"""A folder `appell paper` writes into: it deletes or overwrites only what it wrote there itself.

The rule (design notes, "Safety"): a command never deletes or overwrites a
file it did not create.  A folder appell writes carries a manifest,
``.appell-paper``, listing every file appell wrote there.  Writing:

* a missing or empty folder becomes appell's (created, manifest written);
* a folder with a manifest: files listed in it may be replaced, and those no
  longer produced are removed; any other file is left alone, and a file appell
  would write that the manifest does not list is refused, not overwritten;
* a non-empty folder without a manifest, a path that is a file, or a folder
  that cannot be written is refused before any work (`DestinationError`);
  so is a manifest appell did not write (not text, or naming a file outside
  the folder), since appell removes what its manifest lists.

Files are first written into a fresh temporary folder inside the destination
and then moved into place one by one, so an interrupted run leaves either the
old file or the new one.
"""

from __future__ import annotations

import json
import os
import tempfile
from pathlib import Path, PurePosixPath

from numerics.files import replace_file  # noqa: F401  (appell's data files: bench.json, costs.json)

MANIFEST = ".appell-paper"
# What pdflatex leaves beside main.tex when `--pdf` compiles it: appell's too.
PDF_PRODUCTS = ("main.aux", "main.log", "main.out", "main.pdf")
HEADER = "# Files written by `appell paper` (and pdflatex): it replaces or removes these, and nothing else here.\n"


class DestinationError(ValueError):
    """A folder appell may not write into: the message is one line naming it."""


def _resolves_inside(path: Path, inside: Path) -> bool:
    """``path``, its links followed, lies in the folder ``inside`` (resolved); a loop of links does not."""
    try:
        return path.resolve().is_relative_to(inside)
    except (OSError, RuntimeError):  # a loop of links
        return False


def owned(folder: Path) -> set[str] | None:
    """The files appell wrote in ``folder`` (relative paths), or None when it has no manifest.  A manifest that
    is not text, or names a file outside ``folder`` (absolute, through "..", or through a link out of it), was not
    written by appell: refused, since appell removes the files its manifest lists and no longer produces."""
    manifest = Path(folder) / MANIFEST
    if not manifest.is_file():
        return None
    try:
        lines = manifest.read_text(encoding="utf-8").splitlines()
    except (OSError, UnicodeDecodeError) as error:
        raise DestinationError(f"{manifest}: not a manifest appell wrote ({error}): refused") from None
    names = {line for line in lines if line and not line.startswith("#")}
    inside = Path(folder).resolve()
    for name in sorted(names):
        # As `write` lists them: relative, "/"-separated, no "." or ".." (a "./main.tex" would not match the
        # "main.tex" just written, and `write` would remove it), and inside the folder once links are followed.
        canonical = name == PurePosixPath(name).as_posix() and not {"", ".", ".."} & set(name.split("/"))
        if not (canonical and not Path(name).is_absolute() and _resolves_inside(inside / name, inside)):
            raise DestinationError(f"{manifest}: names {name!r}, not a file of {folder}: not a manifest appell wrote, refused")
    return names


def check_destination(folder: Path) -> None:
    """Refuse, before any work, a destination appell may not write into."""
    folder = Path(folder)
    if folder.exists() and not folder.is_dir():
        raise DestinationError(f"{folder}: is a file, not a folder")
    if folder.is_dir():
        if owned(folder) is None and any(folder.iterdir()):
            raise DestinationError(
                f"{folder}: not empty and not written by appell (no {MANIFEST} manifest): give a new or empty folder"
            )
    else:
        try:
            folder.mkdir(parents=True)
        except OSError as error:
            raise DestinationError(f"{folder}: cannot create the folder ({error.strerror or error})") from None
    try:
        with tempfile.TemporaryFile(dir=folder):
            pass
    except OSError as error:
        raise DestinationError(f"{folder}: cannot write into the folder ({error.strerror or error})") from None


def _no_link_out(folder: Path, names) -> None:
    """Refuse to write ``names`` into ``folder`` when one would land outside it: a subfolder that links out of it
    (generated -> elsewhere) took 22 files there, an audit found.  (A file that is a link is replaced, not
    followed: `os.replace`.)"""
    inside = folder.resolve()
    for name in names:
        place = (folder / name).parent
        if not _resolves_inside(place, inside):
            raise DestinationError(f"{place}: a link out of {folder}; appell writes only inside the folder given")


def write(folder: Path, files: dict[str, bytes | str], make=None, products: tuple = PDF_PRODUCTS) -> list[Path]:
    """Write ``files`` (relative path -> content) and whatever ``make(staging)`` writes under ``staging`` into
    ``folder`` under the rules above; return the final paths, the manifest last.  ``products`` are the files a
    later step (pdflatex) writes there: listed in the manifest as appell's too."""
    folder = Path(folder)
    check_destination(folder)
    before = owned(folder) or set()
    with tempfile.TemporaryDirectory(dir=folder, prefix=".appell-staging-") as tmp:
        staging = Path(tmp)
        for name, content in files.items():
            path = staging / name
            path.parent.mkdir(parents=True, exist_ok=True)
            if isinstance(content, str):
                path.write_text(content, encoding="utf-8")
            else:
                path.write_bytes(content)
        if make is not None:
            make(staging)
        produced = sorted(str(p.relative_to(staging)) for p in staging.rglob("*") if p.is_file())
        foreign = [name for name in produced if (folder / name).exists() and name not in before]
        if foreign:
            raise DestinationError(f"{folder / foreign[0]}: exists and was not written by appell: not overwritten")
        _no_link_out(folder, produced)  # a subfolder may have become a link since the check
        manifest = sorted(set(produced) | set(products))
        (staging / MANIFEST).write_text(HEADER + "".join(name + "\n" for name in manifest), encoding="utf-8")
        for name in produced + [MANIFEST]:
            target = folder / name
            target.parent.mkdir(parents=True, exist_ok=True)
            os.replace(staging / name, target)
    for name in sorted(before - set(manifest)):  # appell's own files that are no longer produced
        path = folder / name
        if path.is_file():
            path.unlink()
    return [folder / name for name in produced + [MANIFEST]]


class SettingError(ValueError):
    """An environment variable appell reads ($APPELL_JOBS) set to what it cannot mean: one line naming it."""


class DataError(ValueError):
    """A data file appell reads (paper/data/*.json) that is not what it wrote: the message is one line naming it."""


def read_data(path: Path, remedy: str, keys: dict):
    """The JSON object in one of appell's data files, with each of ``keys`` (name -> type); a missing, unreadable
    or other-shaped one is a `DataError` saying ``remedy``."""
    try:
        data = json.loads(Path(path).read_text(encoding="utf-8"))
    except (OSError, ValueError) as error:
        raise DataError(f"{path}: not readable as the JSON appell writes ({error}): {remedy}") from None
    missing = [name for name, kind in keys.items() if not (isinstance(data, dict) and isinstance(data.get(name), kind))]
    if missing:
        raise DataError(f"{path}: not the JSON appell writes (no {missing[0]!r} of type {keys[missing[0]].__name__}): {remedy}")
    return data


def check_new_file(path, flag: str) -> Path:
    """A file a command is asked to write (``--csv FILE``): refused, before any work, when it exists (appell
    overwrites nothing it did not create; a dangling link too, which opening would follow), names a folder, or its
    folder is missing or cannot be written (an audit found the last two refused only after the work)."""
    if str(path).endswith(("/", os.sep)):  # Path() would drop the slash, and the write fail after the work
        raise DestinationError(f"{flag} {path}: names a folder; give a file name")
    path = Path(path)
    if path.exists() or path.is_symlink():
        raise DestinationError(f"{flag} {path}: exists; appell does not overwrite it (remove it or give another name)")
    if not path.parent.is_dir():
        raise DestinationError(f"{flag} {path}: no folder {path.parent}")
    if not os.access(path.parent, os.W_OK | os.X_OK):
        raise DestinationError(f"{flag} {path}: cannot write into {path.parent} (permission denied)")
    return path


def write_new_file(path: Path, data: bytes, flag: str) -> None:
    """Write ``data`` to a file that must not exist: opened for exclusive creation ("xb"), so a file that
    appeared since `check_new_file` is refused, never replaced."""
    path = Path(path)  # --csv and --npz give a str: on a full disk its .unlink was a traceback, the half file left
    try:
        out = open(path, "xb")
    except FileExistsError:
        raise DestinationError(f"{flag} {path}: exists; appell does not overwrite it (remove it or give another name)") from None
    except OSError as error:
        raise DestinationError(f"{flag} {path}: cannot write it ({error.strerror or error})") from None
    try:
        with out:
            out.write(data)
    except OSError as error:  # a full disk: the half-written file is ours (created above), so it goes
        path.unlink(missing_ok=True)
        raise DestinationError(f"{flag} {path}: cannot write it ({error.strerror or error}); nothing was kept") from None
