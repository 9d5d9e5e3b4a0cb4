"""The kept verification record: read only under the key of the current source and versions."""

import json
import os

import pytest

from paper import record


def test_a_record_is_read_back_only_under_its_key(tmp_path, monkeypatch):
    monkeypatch.setenv("APPELL_CACHE", str(tmp_path))
    assert record.load() is None
    written = record.save({"verify": {"claims": []}, "errata": []})
    assert written == tmp_path / f"record-{record.key()}.json"
    assert record.load()["errata"] == []
    monkeypatch.setattr(record, "key", lambda: "another-source")
    assert record.load() is None


def test_the_key_follows_every_source_file(tmp_path, monkeypatch):
    for package in record.SOURCES:
        (tmp_path / package).mkdir()
        (tmp_path / package / "a.py").write_text("x = 1\n")
    monkeypatch.setattr(record, "ROOT", tmp_path)
    before = record.key()
    (tmp_path / "numerics" / "a.py").write_text("x = 2\n")
    assert record.key() != before
    (tmp_path / "numerics" / "a.py").write_text("x = 1\n")
    assert record.key() == before


def test_an_unwritable_cache_keeps_nothing_and_says_nothing(tmp_path, monkeypatch):
    blocker = tmp_path / "file"
    blocker.write_text("")
    monkeypatch.setenv("APPELL_CACHE", str(blocker / "cache"))
    assert record.save({"verify": {}}) is None and record.load() is None


@pytest.mark.parametrize("interruption", [OSError(28, "No space left on device"), KeyboardInterrupt()])
def test_a_record_cut_short_leaves_nothing_behind(tmp_path, monkeypatch, interruption):
    """A full disk or Ctrl-C while the record is written: no record, and no half-written file in the cache."""
    monkeypatch.setenv("APPELL_CACHE", str(tmp_path))

    def cut_short(*args):
        raise interruption

    monkeypatch.setattr(os, "replace", cut_short)
    if isinstance(interruption, OSError):
        assert record.save({"verify": {"claims": []}, "errata": []}) is None
    else:
        with pytest.raises(KeyboardInterrupt):
            record.save({"verify": {"claims": []}, "errata": []})
    assert list(tmp_path.iterdir()) == []


def test_errata_answers_from_the_record_and_says_so(tmp_path, monkeypatch, capsys):
    from paper import verification
    from paper.cli import main

    monkeypatch.setenv("APPELL_CACHE", str(tmp_path))
    entry = {"id": "eq10", "where": "n°7, eq. (10)", "kind": "mathematical", "class": "mathematical erratum",
             "printed": "p", "corrected": "c", "reason": "r", "status": "erratum"}
    record.save({"verify": {"claims": []}, "errata": [entry]})
    monkeypatch.setattr(verification, "all_claims", lambda: [])  # the record's claims are the package's
    monkeypatch.setattr(verification, "check_all", lambda *a, **k: 1 / 0)  # nothing may be checked again
    assert main(["errata", "--json"]) == 0
    out = capsys.readouterr()
    assert json.loads(out.out)["errata"] == [entry]
    assert "answering from the verification record" in out.err


def test_a_record_not_in_the_shape_save_writes_is_a_miss(tmp_path, monkeypatch):
    """Found by an adversarial audit: '[]' or a bare key under the record's name made `appell errata` raise."""
    monkeypatch.setenv("APPELL_CACHE", str(tmp_path))
    for text in ("[]", json.dumps({"key": record.key()}), json.dumps({"key": record.key(), "verify": {"claims": [1]},
                                                                      "errata": []}), '{"key": "' + record.key()):
        record.path().write_text(text, encoding="utf-8")
        assert record.load() is None, text
    record.save({"verify": {"claims": [{"id": "eq1"}]}, "errata": []})
    assert record.load()["verify"]["claims"] == [{"id": "eq1"}]


def test_a_record_that_is_a_pipe_or_a_device_is_a_miss_at_once(tmp_path, monkeypatch):
    """An audit: a named pipe under the record's name made `appell errata` wait for ever, a link to /dev/zero read
    6.5 GB in 20 s.  Only a regular file of a record's size is read."""
    monkeypatch.setenv("APPELL_CACHE", str(tmp_path))
    os.mkfifo(record.path())
    assert record.load() is None
    record.path().unlink()
    record.path().symlink_to("/dev/zero")
    assert record.load() is None
    record.path().unlink()
    monkeypatch.setattr(record, "MAX_BYTES", 10)
    record.save({"verify": {"claims": []}, "errata": []})
    assert record.load() is None


def test_a_record_that_cannot_be_kept_is_said_once(tmp_path, monkeypatch, capsys):
    """An unusable $APPELL_CACHE made every later `appell errata`, `reduce` or `paper` check every claim again,
    without a word (an audit)."""
    from paper import verification

    blocker = tmp_path / "file"
    blocker.write_text("")
    monkeypatch.setenv("APPELL_CACHE", str(blocker / "cache"))
    monkeypatch.setattr(verification, "all_claims", lambda: [])
    verification.verify(quiet=True)
    assert capsys.readouterr().err == (f"appell: cannot keep the verification record in {blocker / 'cache'} ($APPELL_CACHE "
                                       "sets the folder): the next command checks every claim again\n")


def test_a_cache_that_cannot_keep_the_record_is_said_before_the_checking(tmp_path, monkeypatch, capsys):
    """An audit: with $APPELL_CACHE a file, or a folder that cannot be written, the first-run notice promised
    "kept for the next run" and the minutes of checking ran before anything said otherwise."""
    from paper import verification

    monkeypatch.setattr(verification, "all_claims", lambda: [])
    monkeypatch.setattr(verification, "verify", lambda quiet: [])
    blocker = tmp_path / "file"
    blocker.write_text("")
    for cache, why in ((blocker, f"{blocker} is not a folder"), (blocker / "sub" / "cache", f"{blocker} is not a folder")):
        monkeypatch.setenv("APPELL_CACHE", str(cache))
        verification.recorded()
        assert f"(a minute or two; not kept: {why}, and $APPELL_CACHE sets the folder)\n" in capsys.readouterr().err
    monkeypatch.setenv("APPELL_CACHE", str(tmp_path / "new" / "cache"))  # made when the record is saved
    verification.recorded()
    assert "(a minute or two; kept for the next run)\n" in capsys.readouterr().err
    monkeypatch.setattr(record.os, "access", lambda path, mode: False)  # (root writes any folder: its access said no)
    verification.recorded()
    assert f"not kept: {tmp_path} cannot be written" in capsys.readouterr().err
