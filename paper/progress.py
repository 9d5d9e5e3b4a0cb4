"""Progress of long work on stderr, only when stderr is a terminal: piped or ``--quiet``, nothing.

Two shapes: `Progress`, a counter rewritten in place (``12/150 claims checked, 20 s``),
for work of known size; `Notes`, one line per stage (``scipy solve_ivp DOP853``), for
work in stages of unknown length.  Results go to stdout; these never do.
"""

from __future__ import annotations

import sys
import time


def shown(quiet: bool = False, stream=None) -> bool:
    """Whether progress goes to ``stream`` (stderr): a terminal, and not ``quiet``."""
    stream = stream or sys.stderr
    try:
        return not quiet and stream.isatty()
    except (AttributeError, ValueError):  # no isatty, or a closed stream
        return False


class Progress:
    """``done/total what, elapsed`` on stderr while the work runs; silent when piped or ``quiet``."""

    def __init__(self, total: int, what: str, quiet: bool = False, stream=None):
        self.stream = stream or sys.stderr
        self.total, self.what = total, what
        self.show = shown(quiet, self.stream)
        self.start = time.perf_counter()

    def update(self, done: int, total: int | None = None) -> None:
        if self.show:
            elapsed = time.perf_counter() - self.start
            print(f"\r{done}/{total or self.total} {self.what}, {elapsed:.0f} s", end="", file=self.stream, flush=True)

    def close(self) -> None:
        if self.show:
            print("\r\033[K", end="", file=self.stream, flush=True)  # clear the line: the result follows


class Notes:
    """Called with a line: prints it on stderr (with the time since the start) when progress is shown."""

    def __init__(self, quiet: bool = False, stream=None):
        self.stream = stream or sys.stderr
        self.show = shown(quiet, self.stream)
        self.start = time.perf_counter()

    def __call__(self, line: str) -> None:
        if self.show:
            print(f"[{time.perf_counter() - self.start:5.0f} s] {line}", file=self.stream, flush=True)
