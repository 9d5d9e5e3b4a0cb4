"""No harm: every command that writes leaves alone what it did not write (design notes, "Safety")."""

import json
from pathlib import Path

import pytest

from paper import appendix, figures, output
from paper.cli import main


def test_a_folder_appell_did_not_write_is_refused_before_any_work(tmp_path):
    (tmp_path / "thesis.tex").write_text("mine")
    with pytest.raises(output.DestinationError, match="not empty and not written by appell"):
        output.write(tmp_path, {"main.tex": "x"})
    assert (tmp_path / "thesis.tex").read_text() == "mine" and not (tmp_path / "main.tex").exists()


def test_in_its_own_folder_appell_replaces_and_removes_only_its_files(tmp_path):
    out = tmp_path / "out"
    output.write(out, {"main.tex": "1", "generated/a.tex": "a", "generated/b.tex": "b"})
    assert output.owned(out) >= {"main.tex", "generated/a.tex", "generated/b.tex"}
    (out / "notes.txt").write_text("mine")
    (out / "generated" / "mine.tex").write_text("mine")
    output.write(out, {"main.tex": "2", "generated/a.tex": "a2"})  # b.tex is no longer produced
    assert (out / "main.tex").read_text() == "2" and (out / "generated" / "a.tex").read_text() == "a2"
    assert not (out / "generated" / "b.tex").exists()
    assert (out / "notes.txt").read_text() == "mine" and (out / "generated" / "mine.tex").read_text() == "mine"
    assert not list(out.glob(".appell-staging-*"))


def test_a_file_appell_would_write_but_did_not_is_never_overwritten(tmp_path):
    output.write(tmp_path / "out", {"main.tex": "1"})
    (tmp_path / "out" / "appendix.tex").write_text("the user's own appendix")
    with pytest.raises(output.DestinationError, match="appendix.tex: exists and was not written by appell"):
        output.write(tmp_path / "out", {"main.tex": "2", "appendix.tex": "ours"})
    assert (tmp_path / "out" / "appendix.tex").read_text() == "the user's own appendix"
    assert (tmp_path / "out" / "main.tex").read_text() == "1"


@pytest.fixture
def quick_paper(monkeypatch, tmp_path):
    """`appell paper` without the minutes of checks and figures: one claim, figures as stubs."""
    monkeypatch.setenv("APPELL_CACHE", str(tmp_path / "cache"))  # a record of one claim: not the session's
    from derivation import n7_pure_rolling
    from paper import verification

    claims = n7_pure_rolling.claims()[:1]
    results = verification.check_all(claims)
    monkeypatch.setattr(verification, "all_claims", lambda: claims)
    monkeypatch.setattr(verification, "check_all", lambda *args, **kwargs: results)
    for name in ("shots", "phases_in_time", "end_of_sliding", "work_precision"):
        monkeypatch.setattr(figures, name, lambda *args, **kw: args[-1].write_bytes(b"%PDF stub") or args[-1])


@pytest.mark.parametrize("argv", [["paper", "--out", "{dir}"], ["paper", "--check", "--out", "{dir}"]])
def test_paper_out_keeps_a_foreign_file(argv, tmp_path, capsys, quick_paper):
    folder = tmp_path / "dest"
    folder.mkdir()
    (folder / "thesis.tex").write_text("mine")
    assert main([a.replace("{dir}", str(folder)) for a in argv]) == 2
    assert "not written by appell" in capsys.readouterr().err
    assert [p.name for p in folder.iterdir()] == ["thesis.tex"] and (folder / "thesis.tex").read_text() == "mine"
    # An empty folder becomes appell's; a file the user adds later survives the next run.
    (folder / "thesis.tex").unlink()
    assert main(["paper", "--out", str(folder)]) == 0
    (folder / "thesis.tex").write_text("mine")
    (folder / "generated" / "notes.tex").write_text("mine too")
    assert main(["paper", "--out", str(folder)]) == 0
    assert (folder / "thesis.tex").read_text() == "mine" and (folder / "generated" / "notes.tex").read_text() == "mine too"


def test_paper_writes_its_own_committed_folder_under_its_manifest():
    owned = output.owned(appendix.PAPER)
    assert owned is not None and "main.tex" in owned and "appendix.tex" in owned
    assert not any(name.endswith(".py") or name.startswith("data/") for name in owned)


def test_bench_writes_only_its_results(tmp_path, monkeypatch, capsys):
    from numerics import bench

    data, figs = tmp_path / "data", tmp_path / "figures"
    data.mkdir()
    figs.mkdir()
    (data / "mine.json").write_text("{}")
    (figs / "mine.pdf").write_bytes(b"mine")
    monkeypatch.setattr(figures, "DATA", data)
    monkeypatch.setattr(figures, "FIGURES", figs)
    report = bench.Report(
        rows=[bench.Row("batch", "tol 1e-09", 2e-5, 5e-10, 5e-10, 1e-11, 1e-11, 30)],
        scaling=[(10, 1e-3)], machine={"cpu": "x", "cores": 2, "python": "3.11", "numpy": "2", "quick": False},
    )
    monkeypatch.setattr(bench, "run", lambda quick, progress: report)
    assert main(["bench"]) == 0
    assert json.loads((data / "bench.json").read_text())["rows"]
    assert (data / "mine.json").read_text() == "{}" and (figs / "mine.pdf").read_bytes() == b"mine"
    assert sorted(p.name for p in figs.iterdir()) == ["mine.pdf", "work_precision.pdf"]
    assert sorted(p.name for p in data.iterdir()) == ["bench.json", "mine.json"]  # no temporary file left


@pytest.mark.parametrize("entry", ["../victim.txt", "{victim}", "link/victim.txt", "sub/../../victim.txt", "./a.tex",
                                   "sub//a.tex", "loop/a.tex"])
def test_a_manifest_naming_a_file_outside_its_folder_is_refused_and_nothing_is_removed(tmp_path, capsys, entry):
    """appell removes the files its manifest lists and no longer produces: a manifest it did not write (naming
    the user's file beside the folder, by "..", absolutely or through a link; or a name not as appell writes it,
    "./a.tex", which would not match the a.tex just written and be removed) must not make it delete."""
    victim = tmp_path / "victim.txt"
    victim.write_text("mine")
    folder = tmp_path / "out"
    folder.mkdir()
    (folder / "link").symlink_to(tmp_path, target_is_directory=True)
    (folder / "loop").symlink_to(folder / "loop")  # a link to itself: resolve() raises
    (folder / output.MANIFEST).write_text(output.HEADER + entry.format(victim=victim) + "\n", encoding="utf-8")
    with pytest.raises(output.DestinationError, match="not a file of"):
        output.write(folder, {"a.tex": "x"})
    assert main(["paper", "--out", str(folder)]) == 2
    err = capsys.readouterr().err
    assert "not a manifest appell wrote" in err and len(err.strip().splitlines()) == 1
    assert victim.read_text() == "mine" and not (folder / "a.tex").exists()


def test_a_manifest_that_is_not_text_is_refused_in_one_line(tmp_path, capsys):
    folder = tmp_path / "out"
    folder.mkdir()
    (folder / output.MANIFEST).write_bytes(b"\xff\n")
    assert main(["paper", "--out", str(folder)]) == 2
    err = capsys.readouterr().err
    assert "not a manifest appell wrote" in err and len(err.strip().splitlines()) == 1


def test_a_damaged_data_file_is_one_line_naming_it(tmp_path, monkeypatch, capsys):
    damaged = tmp_path / "bench.json"
    damaged.write_text('{"rows": [')
    with pytest.raises(output.DataError, match="bench.json: not readable as the JSON appell writes"):
        output.read_data(damaged, "run appell bench", appendix.BENCH_KEYS)
    for other in ("{}", "[]", '{"rows": {}, "machine": {}}'):  # valid JSON of another shape (a review)
        damaged.write_text(other)
        with pytest.raises(output.DataError, match="bench.json: not the JSON appell writes .no 'rows'"):
            output.read_data(damaged, "run appell bench", appendix.BENCH_KEYS)
    damaged.write_text('{"rows": [')
    monkeypatch.setattr(figures, "DATA", tmp_path)
    from paper import verification

    monkeypatch.setattr(verification, "recorded", lambda quiet: {})
    monkeypatch.setattr(verification, "results_from", lambda kept: [])
    monkeypatch.setattr(appendix, "generate", lambda *a, **k: appendix.figure("work_precision"))
    assert main(["paper", "--out", str(tmp_path / "out")]) == 2
    err = capsys.readouterr().err
    assert "bench.json: not readable" in err and "appell bench" in err and len(err.strip().splitlines()) == 1


def test_a_file_that_cannot_be_written_whole_is_not_left_half_written(tmp_path, monkeypatch):
    """A full disk (found on a 1 MiB tmpfs): `--csv` left a truncated file, which then blocked the next run as an
    existing file, and the error named "standard output".  The file appell created is removed, and named."""
    import errno

    real_open = open

    class Full:
        def __init__(self, path, mode):
            self.file = real_open(path, mode)

        def __enter__(self):
            return self

        def __exit__(self, *exc):
            self.file.close()

        def write(self, data):
            self.file.write(data[:10])
            raise OSError(errno.ENOSPC, "No space left on device")

    monkeypatch.setattr(output, "open", Full, raising=False)
    target = tmp_path / "out.csv"
    # As a Path and as the command line gives it, a str (whose missing .unlink was a traceback, the half file left:
    # an audit on a full tmpfs).
    for given in (target, str(target)):
        with pytest.raises(output.DestinationError, match=r"--csv .*out\.csv: cannot write it \(No space left on device\)"):
            output.write_new_file(given, b"x" * 100, "--csv")
        assert not target.exists()


def test_a_new_file_is_refused_before_any_work_where_it_could_not_be_written(tmp_path):
    with pytest.raises(output.DestinationError, match="names a folder"):
        output.check_new_file(f"{tmp_path}/newdir/", "--csv")
    (tmp_path / "link").symlink_to(tmp_path / "nowhere")  # a dangling link: opening it would create its target
    with pytest.raises(output.DestinationError, match="exists"):
        output.check_new_file(tmp_path / "link", "--csv")
    long = tmp_path / ("a" * 300 + ".csv")  # longer than a file name may be: named with its flag (an audit)
    with pytest.raises(output.DestinationError, match=r"^--csv .*a\.csv: cannot write it \(File name too long\)$"):
        output.check_new_file(str(long), "--csv")


def test_a_subfolder_that_links_out_of_the_destination_is_refused(tmp_path):
    """A folder of appell's with a subfolder that links elsewhere: `appell paper --out` wrote 22 files there (an
    audit).  Refused (before any work when the manifest names files there), and nothing is written there."""
    outside = tmp_path / "outside"
    outside.mkdir()
    out = tmp_path / "out"
    output.write(out, {"main.tex": "1", "generated/a.tex": "a"})
    (out / "generated" / "a.tex").unlink()
    (out / "generated").rmdir()
    (out / "generated").symlink_to(outside, target_is_directory=True)
    with pytest.raises(output.DestinationError, match="not a manifest appell wrote"):  # its own files': before work
        output.check_destination(out)
    (out / "generated").unlink()
    output.write(out, {"main.tex": "1"})  # the manifest now names main.tex only
    (out / "hosts").symlink_to(outside, target_is_directory=True)  # the user's link: allowed to be there
    output.check_destination(out)
    with pytest.raises(output.DestinationError, match="a link out of"):  # but nothing is written through it
        output.write(out, {"main.tex": "2", "hosts/a.tex": "a"})
    assert list(outside.iterdir()) == [] and (out / "main.tex").read_text() == "1"
    (out / "hosts").unlink()
    (out / "generated").mkdir()  # a real folder is the user's to have: written into
    output.write(out, {"main.tex": "2", "generated/a.tex": "a"})
    assert (out / "generated" / "a.tex").read_text() == "a"


def test_an_empty_out_is_refused_not_read_as_paper(tmp_path, capsys, monkeypatch):
    """`appell paper --out ""` wrote into the package's own paper/ (an audit)."""
    from paper import appendix

    monkeypatch.setattr(appendix, "generate", lambda *a, **k: pytest.fail("written"))
    assert main(["paper", "--out", ""]) == 2
    assert "--out: an empty path" in capsys.readouterr().err


def test_a_sigterm_while_writing_leaves_no_staging_folder(tmp_path, capsys, quick_paper, monkeypatch):
    """Killed by SIGTERM (`timeout`, a cancelled CI job) while writing, `appell paper --out` left its staging
    folder, and the next run refused the destination as not appell's (an audit).  It unwinds as for Ctrl-C now."""
    import os
    import signal

    folder = tmp_path / "dest"
    monkeypatch.setattr(figures, "shots", lambda path: os.kill(os.getpid(), signal.SIGTERM))
    before = signal.getsignal(signal.SIGTERM)
    assert main(["paper", "--out", str(folder)]) == 143
    assert capsys.readouterr().err.endswith("appell: terminated\n")
    # The new folder is appell's (its manifest, listing nothing), and nothing else is left in it.
    assert [p.name for p in folder.iterdir()] == [output.MANIFEST] and output.owned(folder) == set()
    assert signal.getsignal(signal.SIGTERM) is before


KILLED_WRITE = """
import os, signal, sys
from paper import output
folder, where = sys.argv[1], sys.argv[2]
def die(*args):
    os.kill(os.getpid(), signal.SIGKILL)
if where == "staging":  # while the figures are drawn
    output.write(folder, {"main.tex": "2"}, make=lambda staging: die())
else:  # after the first file has moved into place
    replace, moved = os.replace, []
    def move(source, target):
        if moved and not str(target).endswith(output.MANIFEST):
            die()
        replace(source, target)
        moved.append(target)
    os.replace = move
    output.write(folder, {"main.tex": "2", "appendix.tex": "2", "generated/a.tex": "2"})
"""


@pytest.mark.parametrize("where", ["staging", "moving"])
@pytest.mark.parametrize("new", [True, False])
def test_a_run_killed_outright_leaves_a_folder_the_next_run_takes_as_its_own(tmp_path, where, new):
    """SIGKILL (or a power cut) runs no clean-up: `appell paper --out NEW` killed while staging left a folder
    holding only `.appell-staging-*`, killed while moving one holding some files and no manifest, and every later
    run refused it as not appell's (an audit).  The manifest is written first now, naming the staging folder and,
    before the moves, the files about to arrive."""
    import subprocess
    import sys

    folder = tmp_path / "dest"
    if not new:
        output.write(folder, {"main.tex": "1", "old.tex": "1"})
    run = subprocess.run([sys.executable, "-c", KILLED_WRITE, str(folder), where], capture_output=True, text=True,
                         cwd=Path(appendix.__file__).parents[1])
    assert run.returncode == -9, run.stderr
    # Every file left is listed as appell's, or lies in the staging folder the manifest names.
    named = [line[len("# staging: "):] for line in (folder / output.MANIFEST).read_text().splitlines() if "staging" in line]
    left = {str(p.relative_to(folder)) for p in folder.rglob("*") if p.is_file()}
    assert {name for name in left if name.split("/")[0] not in named} <= output.owned(folder) | {output.MANIFEST}, left
    output.write(folder, {"main.tex": "3", "appendix.tex": "3"})  # the next run: accepted, and it tidies up
    assert {p.name for p in folder.iterdir()} == {output.MANIFEST, "main.tex", "appendix.tex"}
    assert output.owned(folder) == {"main.tex", "appendix.tex"} and (folder / "main.tex").read_text() == "3"


def test_pdflatex_never_overwrites_a_pdf_appell_did_not_write(tmp_path, capsys):
    """`appell paper --out X` without --pdf listed main.pdf (and the hosts' .log, .pdf) as its own in advance, so a
    later `--pdf` replaced the user's main.pdf put there meanwhile (an audit).  pdflatex's files are claimed only
    when --pdf is about to compile (.appell-pdf), and one present that appell did not write is refused."""
    folder = tmp_path / "out"
    output.write(folder, {"main.tex": "1"}, products=appendix.pdf_products())
    assert not set(appendix.pdf_products()) & output.owned(folder)
    (folder / "main.pdf").write_text("the user's own")
    with pytest.raises(output.DestinationError, match="main.pdf: exists and was not written by appell"):
        output.check_products(folder, appendix.pdf_products())
    with pytest.raises(output.DestinationError, match="main.pdf: exists and was not written by appell"):
        appendix.compile_pdf(folder)  # refused before pdflatex runs
    assert (folder / "main.pdf").read_text() == "the user's own" and not (folder / output.PDF_MANIFEST).exists()
    # Once --pdf has claimed them, pdflatex's files stay appell's across a regeneration without --pdf.
    (folder / "main.pdf").unlink()
    output.claim_products(folder, appendix.pdf_products())
    (folder / "main.pdf").write_text("%PDF compiled by appell")
    output.write(folder, {"main.tex": "2"}, products=appendix.pdf_products())
    output.check_products(folder, appendix.pdf_products())
    assert (folder / "main.pdf").exists()


def test_an_earlier_manifest_listing_pdflatex_files_hands_them_on(tmp_path):
    """A folder an earlier appell wrote and compiled: its manifest of the sources listed main.pdf.  The next run
    lists it in .appell-pdf (only if there), so --pdf may replace it; the sources' manifest no longer does."""
    folder = tmp_path / "out"
    folder.mkdir()
    (folder / output.MANIFEST).write_text(output.HEADER + "main.tex\nmain.pdf\nmain.log\n", encoding="utf-8")
    (folder / "main.tex").write_text("1")
    (folder / "main.pdf").write_text("%PDF compiled by an earlier appell")
    output.write(folder, {"main.tex": "2"}, products=appendix.pdf_products())
    assert output.owned(folder) == {"main.tex"} and output.owned(folder, output.PDF_MANIFEST) == {"main.pdf"}
    assert (folder / "main.pdf").exists()
    output.check_products(folder, appendix.pdf_products())


def test_a_full_disk_names_the_folder_and_leaves_it_as_it_was(tmp_path, capsys, quick_paper, monkeypatch):
    """A full disk under --out was reported as "cannot write to standard output" (an audit)."""
    import errno

    folder = tmp_path / "dest"
    assert main(["paper", "--out", str(folder)]) == 0
    before = {p: p.read_bytes() for p in folder.rglob("*") if p.is_file()}
    capsys.readouterr()

    def full(*args, **kwargs):
        raise OSError(errno.ENOSPC, "No space left on device")

    monkeypatch.setattr(figures, "shots", full)
    assert main(["paper", "--out", str(folder)]) == 2
    assert capsys.readouterr().err.endswith(f"\nappell: error: {folder}: cannot write into the folder (No space left on device)\n")
    assert {p: p.read_bytes() for p in folder.rglob("*") if p.is_file()} == before


@pytest.mark.parametrize("flags", [[], ["--check"], ["--check", "--out", "{out}"]])
def test_an_installed_copy_asks_for_out(tmp_path, capsys, monkeypatch, flags):
    """Installed (pip install ., not -e), paper/ is the package's modules and no appendix: `appell paper` alone
    said it was 'not written by appell' and `--check` would call it stale; both ask for --out, before any work."""
    from paper import appendix, verification

    installed = tmp_path / "site-packages" / "paper"
    installed.mkdir(parents=True)
    (installed / "cli.py").write_text("")
    monkeypatch.setattr(appendix, "PAPER", installed)
    monkeypatch.setattr(verification, "recorded", lambda *a, **k: pytest.fail("the record was read"))
    assert main(["paper", *(flag.format(out=tmp_path / "out") for flag in flags)]) == 2
    err = capsys.readouterr().err
    assert "an installed copy of appell holds no appendix" in err and "'appell paper --out DIR'" in err
    assert len(err.splitlines()) == 1 and not (tmp_path / "out").exists()
    assert sorted(path.name for path in installed.iterdir()) == ["cli.py"]
