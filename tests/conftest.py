import pytest


@pytest.fixture(scope="session")
def all_claims():
    import derivation

    return derivation.claims()
