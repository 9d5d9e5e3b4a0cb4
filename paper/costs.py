"""`appell costs`: what reproducing the appendix costs, measured, written to paper/data/costs.json.

The methods paragraph of the appendix quotes these times.  They are measured
here, once, by running each command as a reader would (in a fresh process,
with a private empty verification record, so that every claim is checked),
and committed; `appell paper` only reads the file, so that regeneration stays
byte-identical.  Each command is timed wall-clock on the machine it runs on;
the file records the machine (cores, processor, Python) and the source measured
(`paper.record.source_key`), which the appendix names beside the times.
"""

from __future__ import annotations

import json
import os
import platform
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from paper import output
from paper.methods import COSTS

# (what the appendix calls it, the arguments of `appell`, what it does); {tmp} is a fresh folder.
COMMANDS = (
    ("appell verify", ["verify", "--quiet"], "derives and checks every claim (the record kept is empty at first)"),
    ("appell paper", ["paper", "--out", "{tmp}/paper"], "regenerates the appendix from the kept record"),
    ("appell paper --pdf", ["paper", "--pdf", "--out", "{tmp}/pdf"],
     "regenerates it and compiles main.tex and every host document with pdflatex"),
)


def measure(progress=None) -> dict:
    """Time each of `COMMANDS`, in order, in one fresh temporary folder (its record shared by them)."""
    from numerics.bench import cpu_name
    from paper.record import source_key

    rows = []
    with tempfile.TemporaryDirectory(prefix="appell-costs-") as tmp:
        env = {**os.environ, "APPELL_CACHE": str(Path(tmp) / "record")}
        for name, args, what in COMMANDS:
            if progress:
                progress(f"measuring {name} …")
            start = time.perf_counter()
            run = subprocess.run([sys.executable, "-m", "paper", *(a.format(tmp=tmp) for a in args)],
                                 env=env, capture_output=True, text=True, check=False)
            seconds = time.perf_counter() - start
            if run.returncode != 0:  # its own last line says why; nothing is saved
                from numerics.validation import ComputationError

                said = run.stderr.strip().splitlines()[-1] if run.stderr.strip() else f"exit status {run.returncode}"
                raise ComputationError(f"{name} failed while being measured: {said}")
            rows.append({"command": name, "seconds": round(seconds, 1), "what": what})
    return {
        "machine": {"cores": len(os.sched_getaffinity(0)), "cpu": cpu_name(), "python": platform.python_version(),
                    "source": source_key()},
        "commands": rows,
    }


def save(data: dict, path: Path = COSTS) -> Path:
    output.replace_file(path, json.dumps(data, indent=1, sort_keys=True, ensure_ascii=False) + "\n")
    return path


def as_text(data: dict) -> str:
    machine = data["machine"]
    lines = [f"{machine['cores']} cores, {machine['cpu']}, Python {machine['python']}, source {machine.get('source', 'not recorded')}:"]
    lines += [f"  {row['command']:<22} {row['seconds']:7.1f} s   {row['what']}" for row in data["commands"]]
    return "\n".join(lines)
