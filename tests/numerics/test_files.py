"""numerics.files: appell's own files replaced whole or not at all, keeping their permissions."""

import json
import os
import stat

import pytest

from numerics import files


def test_a_file_is_replaced_whole_or_not_at_all_and_leaves_nothing_beside_it(tmp_path, monkeypatch):
    path = tmp_path / "bench.json"
    files.replace_file(path, '{"old": 1}')
    assert json.loads(path.read_text()) == {"old": 1}

    def interrupted(src, dst):
        raise KeyboardInterrupt
    monkeypatch.setattr(files.os, "replace", interrupted)
    with pytest.raises(KeyboardInterrupt):
        files.replace_file(path, '{"new": 2}')
    assert json.loads(path.read_text()) == {"old": 1}
    assert [p.name for p in tmp_path.iterdir()] == ["bench.json"]  # the temporary file went too (a review)


def test_a_replaced_file_keeps_its_permissions_and_a_new_one_gets_the_umasks(tmp_path):
    """mkstemp makes 0600 files: renamed over bench.json (0644), it had made it private (a review)."""
    path = tmp_path / "costs.json"
    path.write_text("{}")
    os.chmod(path, 0o644)
    files.replace_file(path, '{"a": 1}')
    assert stat.S_IMODE(path.stat().st_mode) == 0o644 and path.read_text() == '{"a": 1}'
    umask = os.umask(0o022)
    try:
        files.replace_file(tmp_path / "new.json", "{}")
    finally:
        os.umask(umask)
    assert stat.S_IMODE((tmp_path / "new.json").stat().st_mode) == 0o644


def test_a_link_at_the_path_is_replaced_never_written_through(tmp_path):
    """`appell bench` drew its figure through a link at paper/figures/work_precision.pdf into the link's target, a
    file appell did not create (an audit): the link is replaced; bytes (a figure) as text."""
    target = tmp_path / "users.pdf"
    target.write_text("the user's own file")
    link = tmp_path / "figure.pdf"
    link.symlink_to(target)
    files.replace_file(link, b"%PDF drawn")
    assert target.read_text() == "the user's own file"
    assert not link.is_symlink() and link.read_bytes() == b"%PDF drawn"
