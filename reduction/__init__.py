"""Appell (1911), n°9–n°11: the reduction of the sliding phase to an Abel equation, and beyond."""
