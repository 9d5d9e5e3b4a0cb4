"""Property-based tests (Hypothesis) of the command line: whatever the file and the flags, exit 0 with a
result or exit 2 with one line on stderr — never a traceback, a hang or a NaN in the output."""

import contextlib
import io
import json
import math
import tempfile
from pathlib import Path

from hypothesis import event, given
from hypothesis import strategies as st
from strategies import SETTINGS, physical_params, states, time_limit

from paper.cli import main
FLAGS = st.lists(
    st.sampled_from([["--json"], ["--tol", "1e-8"], ["--tol", "0"], ["--tol", "nan"], ["--at", "0.3"], ["--at", "-1"],
                     ["--model", "classical"], ["--samples", "3"], ["--samples", "0"], ["--workers", "1"],
                     ["--workers", "0"], ["--skip-bad"], ["--bogus"]]),
    max_size=3,
).map(lambda groups: [flag for group in groups for flag in group])


def run(argv):
    out, err = io.StringIO(), io.StringIO()
    with time_limit(), contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        status = main(argv)
    return status, out.getvalue(), err.getvalue()


def check_answer(status, out, err):
    assert status in (0, 2), (status, err)
    event(f"exit {status}")
    if status == 2:  # one line; for many scenes, one per bad scene and a last one that counts them
        lines = err.splitlines()
        assert lines and all(line.startswith("appell: error: ") for line in lines), err
        assert len(lines) == 1 or lines[-1].endswith("(listed above; --skip-bad runs the good ones)"), err
    else:
        assert "Traceback" not in err and "nan" not in out.lower().replace("nanosecond", ""), out[:500]


def _file(folder: Path, content) -> str:
    path = folder / "scene.json"
    if isinstance(content, bytes):
        path.write_bytes(content)
    else:
        path.write_text(content if isinstance(content, str) else json.dumps(content))
    return str(path)


@SETTINGS
@given(content=st.one_of(st.binary(max_size=300), st.text(max_size=300)), flags=FLAGS)
def test_any_bytes_as_a_scene_file(content, flags):
    with tempfile.TemporaryDirectory() as tmp:
        check_answer(*run(["simulate", _file(Path(tmp), content), *flags]))


@SETTINGS
@given(params=physical_params(), state=states(), flags=FLAGS, many=st.booleans())
def test_physical_scenes_through_the_command_line(params, state, flags, many):
    scene = {"params": params, "state": state}
    with tempfile.TemporaryDirectory() as tmp:
        status, out, err = run(["simulate", _file(Path(tmp), [scene, scene] if many else scene), *flags])
    check_answer(status, out, err)
    if status == 0 and "--json" in flags:
        record = json.loads(out)
        for row in record if many else [record]:
            assert "error" in row or (row["t_slide_end"] >= 0 and math.isfinite(row["t_slide_end"]))
