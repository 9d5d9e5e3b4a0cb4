from derivation import seed


def test_the_transcription_is_the_paper():
    assert "Sur le mouvement d'une bille de billard" in seed.text()
    assert "z' = z^3 - z^2 + \\lambda z(1 - z)^2" in seed.text()


def test_quotes_ignore_whitespace_only():
    assert seed.quotes(r"u = V \cos \alpha,   \quad v = V \sin \alpha")
    assert not seed.quotes(r"u = V \sin \alpha")


def test_every_printed_form_is_quoted_verbatim():
    from paper import verification

    claims = verification.all_claims()  # n°2–n°11 and the numeric checks, not only derivation/
    missing = [c.id for c in claims if c.printed_tex is not None and not seed.quotes(c.printed_tex)]
    assert missing == []
    assert sum(c.printed_tex is not None for c in claims) >= 89  # the quoted ones, of 126
