import pytest


@pytest.fixture(scope="session", autouse=True)
def private_record_cache(tmp_path_factory):
    """The verification record (paper.record) of a test run goes to a folder of its own, never the user's:
    $APPELL_TEST_RECORD when set (make test hands it on to `appell paper --check`), else a temporary one.
    Tests that check only some claims keep their records in folders of their own."""
    import os

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
