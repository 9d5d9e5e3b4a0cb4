"""The OCR transcription of the paper, kept beside the code so every printed form can be traced.

P. Appell, *Sur le mouvement d'une bille de billard avec frottement de
roulement*, J. Math. Pures Appl. (6) 7 (1911) 85–96,
http://www.numdam.org/item?id=JMPA_1911_6_7__85_0 .  The text is the OCR
as received, glyph errors included; claims quote it verbatim.
"""

from __future__ import annotations

import re
from functools import lru_cache
from pathlib import Path

SEED_PATH = Path(__file__).with_name("appell_1911_ocr.txt")


def normalize(text: str) -> str:
    """Whitespace is not significant in a quotation of the OCR."""
    return re.sub(r"\s+", " ", text).strip()


@lru_cache(maxsize=None)
def text() -> str:
    return normalize(SEED_PATH.read_text(encoding="utf-8"))


def quotes(fragment: str) -> bool:
    """True when ``fragment`` stands verbatim (up to whitespace) in the transcription."""
    return normalize(fragment) in text()
