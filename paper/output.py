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

Files are first written into a fresh staging folder inside the destination
and then moved into place one by one, so an interrupted run leaves either the
old file or the new one.  The manifest is written before anything else moves:
a new folder gets one at once, the staging folder is named in it (a killed
run's is removed by the next), and before the moves it lists every file about
to arrive, so a run killed at any point (SIGKILL, power) leaves a folder that
the next run takes as appell's, not one it refuses.

What pdflatex writes beside the sources (`PDF_PRODUCTS`, the hosts' too) is
listed apart, in ``.appell-pdf``, when `--pdf` is about to compile: the
manifest of the sources stays the same whether or not a PDF was made (paper/
commits it), and a main.pdf of the user's in a folder appell wrote without
`--pdf` is refused, not overwritten.
"""

from __future__ import annotations

import errno
import json
import os
import re
import secrets
import shutil
import tempfile
from pathlib import Path, PurePosixPath

from numerics.files import replace_file  # noqa: F401  (appell's data files: bench.json, costs.json)

MANIFEST = ".appell-paper"
# What pdflatex leaves beside main.tex when `--pdf` compiles it: appell's once --pdf has claimed them.
PDF_MANIFEST = ".appell-pdf"
PDF_PRODUCTS = ("main.aux", "main.log", "main.out", "main.pdf")
HEADER = "# Files written by `appell paper`: it replaces or removes these, and nothing else here.\n"
PDF_HEADER = "# Files pdflatex wrote for `appell paper --pdf`: it replaces these, and nothing else here.\n"
# The staging folder of a run, named in the manifest while the run lasts ("# staging: NAME").
STAGING = ".appell-staging-"
STAGING_LINE = re.compile(r"# staging: (\.appell-staging-[0-9a-f]{16})")
# What writing into a folder that is there and writable can still meet.
DISK_FULL = {errno.ENOSPC, errno.EDQUOT, errno.EFBIG, errno.EROFS, errno.EIO}


class DestinationError(ValueError):
    """A folder appell may not write into: the message is one line naming it."""


def _resolves_inside(path: Path, inside: Path) -> bool:
    """``path``, its links followed, lies in the folder ``inside`` (resolved); a loop of links does not."""
    try:
        return path.resolve().is_relative_to(inside)
    except (OSError, RuntimeError):  # a loop of links
        return False


def _lines(manifest: Path) -> list[str]:
    try:
        return manifest.read_text(encoding="utf-8").splitlines()
    except (OSError, UnicodeDecodeError) as error:
        raise DestinationError(f"{manifest}: not a manifest appell wrote ({error}): refused") from None


def owned(folder: Path, manifest: str = MANIFEST) -> set[str] | None:
    """The files appell wrote in ``folder`` (relative paths), or None when it has no manifest.  A manifest that
    is not text, or names a file outside ``folder`` (absolute, through "..", or through a link out of it), was not
    written by appell: refused, since appell removes the files its manifest lists and no longer produces.
    ``manifest``: `PDF_MANIFEST` for what pdflatex wrote there."""
    manifest = Path(folder) / manifest
    if not manifest.is_file():
        return None
    names = {line for line in _lines(manifest) if line and not line.startswith("#")}
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


def _write_manifest(folder: Path, names, staging: str | None = None) -> None:
    """The manifest listing ``names`` (and the staging folder of a run under way), replaced whole."""
    text = HEADER + (f"# staging: {staging}\n" if staging else "") + "".join(name + "\n" for name in sorted(names))
    replace_file(folder / MANIFEST, text)


def _remove_staging_left(folder: Path) -> None:
    """A staging folder that a killed run left, named in the manifest: appell's own, so it goes."""
    for line in _lines(folder / MANIFEST):
        match = STAGING_LINE.fullmatch(line)
        place = folder / match.group(1) if match else None
        if place is not None and place.is_dir() and not place.is_symlink():
            shutil.rmtree(place)


def _new_staging(folder: Path, before: set[str]) -> Path:
    """A fresh staging folder, named in the manifest before it is made (a kill between the two leaves nothing
    unnamed)."""
    while True:
        staging = folder / (STAGING + secrets.token_hex(8))
        _write_manifest(folder, before, staging.name)
        try:
            staging.mkdir(mode=0o700)
            return staging
        except FileExistsError:  # not ours: another name
            continue


def write(folder: Path, files: dict[str, bytes | str], make=None, products: tuple = PDF_PRODUCTS) -> list[Path]:
    """Write ``files`` (relative path -> content) and whatever ``make(staging)`` writes under ``staging`` into
    ``folder`` under the rules above; return the final paths, the manifest last.  ``products`` are the files a
    later step (pdflatex) writes there: never removed here (`claim_products` lists them; a manifest of an earlier
    appell that listed them in the manifest of the sources hands them on to ``.appell-pdf``)."""
    folder = Path(folder)
    check_destination(folder)
    try:
        return _write(folder, files, make, products)
    except OSError as error:  # a full disk was "cannot write to standard output" (an audit): name the folder
        if error.errno in DISK_FULL or (error.filename and _resolves_inside(Path(error.filename), folder.resolve())):
            raise DestinationError(f"{folder}: cannot write into the folder ({error.strerror or error})") from None
        raise


def _write(folder: Path, files, make, products) -> list[Path]:
    before = owned(folder)
    if before is None:  # new or empty: appell's from now, so that a run killed in what follows can be rerun
        before = set()
        _write_manifest(folder, before)
    _remove_staging_left(folder)
    staging = _new_staging(folder, before)
    try:
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
    except BaseException:  # an error, Ctrl-C or SIGTERM before anything moved: the folder as it was
        shutil.rmtree(staging, ignore_errors=True)
        _write_manifest(folder, before)
        raise
    handed_on = sorted(name for name in before & set(products) if (folder / name).exists())
    if handed_on:
        _write_products(folder, (owned(folder, PDF_MANIFEST) or set()) | set(handed_on))
    # Listed before they move: whatever stops the run from here, every file of appell's in the folder is listed.
    _write_manifest(folder, before | set(produced), staging.name)
    for name in produced:
        target = folder / name
        target.parent.mkdir(parents=True, exist_ok=True)
        os.replace(staging / name, target)
    for name in sorted(before - set(produced) - set(products)):  # appell's own files that are no longer produced
        path = folder / name
        if path.is_file():
            path.unlink()
    shutil.rmtree(staging)
    _write_manifest(folder, produced)
    return [folder / name for name in produced + [MANIFEST]]


def _write_products(folder: Path, names) -> None:
    replace_file(folder / PDF_MANIFEST, PDF_HEADER + "".join(name + "\n" for name in sorted(names)))


def check_products(folder: Path, products) -> None:
    """Refuse, before any work, to compile where pdflatex would overwrite a file appell did not write: a main.pdf
    of the user's in a folder appell wrote without `--pdf` (its products were once listed in advance)."""
    folder = Path(folder)
    # An earlier appell listed them with the sources, made or not: taken as its own (`write` hands them on).
    mine = (owned(folder, PDF_MANIFEST) or set()) | (set(products) & (owned(folder) or set()))
    foreign = [name for name in products if ((folder / name).exists() or (folder / name).is_symlink()) and name not in mine]
    if foreign:
        raise DestinationError(f"{folder / foreign[0]}: exists and was not written by appell: not overwritten by pdflatex")


def claim_products(folder: Path, products) -> None:
    """List ``products`` in ``.appell-pdf`` before pdflatex writes them (after `check_products`)."""
    check_products(folder, products)
    _write_products(folder, (owned(folder, PDF_MANIFEST) or set()) | set(products))


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
    if str(path) == "":  # Path("") is the current folder: said as one, not as the empty name it is (an audit)
        raise DestinationError(f"{flag}: an empty file name; give the file to write")
    if str(path).endswith(("/", os.sep)):  # Path() would drop the slash, and the write fail after the work
        raise DestinationError(f"{flag} {path}: names a folder; give a file name")
    path = Path(path)
    try:
        if path.is_dir():  # said as a folder, not a missing suffix or a file in the way (an audit)
            raise DestinationError(f"{flag} {path}: names a folder; give a file name")
        if path.exists() or path.is_symlink():
            raise DestinationError(f"{flag} {path}: exists; appell does not overwrite it (remove it or give another name)")
    except OSError as error:  # a name too long for the file system was "cannot write to" it, not naming the flag
        raise DestinationError(f"{flag} {path}: cannot write it ({error.strerror or error})") from None
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
