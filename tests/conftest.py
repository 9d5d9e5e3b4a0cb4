import os
from pathlib import Path

import pytest

# The simulator's compiled code: one cache for every test run and worker of this checkout (as make check
# and make test set it), not the temporary record folder below, which would compile afresh each run.
os.environ.setdefault("APPELL_NUMBA_CACHE", str(Path(__file__).resolve().parent.parent / "build" / "numba"))


@pytest.fixture(scope="session", autouse=True)
def private_record_cache(tmp_path_factory):
    """The verification record (paper.record) of a test run goes to a folder of its own, never the user's:
    $APPELL_TEST_RECORD when set (make test hands it on to `appell paper --check`), else a temporary one.
    Tests that check only some claims keep their records in folders of their own."""
    folder = os.environ.get("APPELL_TEST_RECORD") or tmp_path_factory.mktemp("appell-cache")
    previous = os.environ.get("APPELL_CACHE")
    os.environ["APPELL_CACHE"] = str(folder)
    yield folder
    if previous is None:
        del os.environ["APPELL_CACHE"]
    else:
        os.environ["APPELL_CACHE"] = previous


@pytest.fixture(scope="session")
def all_claims():
    import derivation

    return derivation.claims()
