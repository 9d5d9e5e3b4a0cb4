"""Figures for the paper, deterministic (vector PDF, headless, no timestamps): same data, same bytes."""

from __future__ import annotations

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# No creation date, a fixed font set: regenerated PDFs are byte-identical.
METADATA = {"CreationDate": None, "Producer": "appell", "Creator": "appell"}
plt.rcParams.update({"pdf.fonttype": 42, "font.family": "DejaVu Sans", "svg.hashsalt": "appell", "font.size": 9})

FIGURES = Path(__file__).resolve().parent / "figures"
DATA = Path(__file__).resolve().parent / "data"


def work_precision(bench: dict, path: Path | None = None) -> Path:
    """Log error against log time per scene, one line per method, from `appell bench --json`'s data."""
    path = path or FIGURES / "work_precision.pdf"
    fig, ax = plt.subplots(figsize=(6.0, 4.2))
    methods: dict[str, list] = {}
    for row in bench["rows"]:
        methods.setdefault(row["method"], []).append(row)
    markers = "osD^v<>p*h"
    for i, (method, rows) in enumerate(methods.items()):
        rows = sorted(rows, key=lambda r: r["seconds_per_scene"])
        xs = [r["seconds_per_scene"] for r in rows]
        ys = [max(r["rest_error"], 1e-17) for r in rows]
        ax.loglog(xs, ys, marker=markers[i % len(markers)], label=method, linewidth=1)
    ax.axhline(1e-9, color="grey", linewidth=0.6, linestyle="--")
    ax.text(ax.get_xlim()[0] * 1.5, 1.5e-9, "1e-9", color="grey", fontsize=7)
    ax.set_xlabel("wall time per scene (s)")
    ax.set_ylabel("max relative error of the rest point")
    ax.set_title("Work against precision on the benchmark scenes")
    ax.grid(True, which="major", linewidth=0.3)
    ax.legend(fontsize=7, loc="best")
    fig.tight_layout()
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, metadata=METADATA)
    plt.close(fig)
    return path
