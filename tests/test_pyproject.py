"""pyproject.toml: what an installed copy carries besides the Python modules.

An installed appell (``pip install .``, not ``-e``) has only the files the package data names; a data file the
code reads and the package data misses makes a command fail outside the checkout (`appell bench --saved` and
`appell paper --out DIR` did: paper/data/ was not shipped)."""

import tomllib
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent

# Every data file the code reads at run time, by folder: the transcription, the example scenes, the saved runs
# and references (paper/data/, `paper.figures.DATA`).
READ_AT_RUN_TIME = {"derivation": "*.txt", "numerics": "scenes/*.json", "paper": "data/*.json"}


def _shipped(package: str) -> set[Path]:
    config = tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["setuptools"]
    patterns = config.get("package-data", {}).get(package, [])
    return {path for pattern in patterns for path in (ROOT / package).glob(pattern)}


def test_every_data_file_read_at_run_time_is_package_data():
    for package, pattern in READ_AT_RUN_TIME.items():
        needed = set((ROOT / package).glob(pattern))
        assert needed, f"{package}/{pattern}: no such files (the list above is stale)"
        missing = sorted(str(path.relative_to(ROOT)) for path in needed - _shipped(package))
        assert not missing, f"not in [tool.setuptools.package-data]: {missing}"


def test_the_saved_runs_are_where_the_code_reads_them():
    from paper import figures

    assert figures.DATA == ROOT / "paper" / "data"
    assert {"bench.json", "costs.json"} <= {path.name for path in _shipped("paper")}
