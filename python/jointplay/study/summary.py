"""What a finished study shows at a glance: failures, the best cases per response, the surfaces' quality,
and the standard figures (main effects, interactions, contours)."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ..errors import ModelError
from .worker import DONE


def failures(dataset) -> list[tuple[int, str]]:
    """(case, error) of every failed case."""
    status = dataset["status"].values
    return [(int(k), str(dataset["error"].values[k])) for k in np.flatnonzero(status != DONE)]


def best_cases(dataset, response: str, count: int = 3, goal: str = "minimize") -> list[int]:
    """The cases with the smallest (``goal="maximize"``: largest) finite values of ``response``."""
    y = np.asarray(dataset[response].values, dtype=float)
    order = [int(k) for k in np.argsort(y if goal == "minimize" else -y, kind="stable") if np.isfinite(y[k])]
    return order[:count]


def surfaces(dataset, responses: list[str]) -> dict[str, object]:
    """A fitted quadratic surface per response, or the reason it cannot be fitted (a str)."""
    from .optimize import fit_surfaces

    out = {}
    for r in responses:
        try:
            out[r] = fit_surfaces(dataset, [r])[r]
        except ModelError as exc:
            out[r] = "; ".join(p.message for p in exc.problems)
    return out


def figures(dataset, fitted: dict, folder: str | Path) -> list[Path]:
    """Main-effect plots of every response, and for each surface a contour over its first two factors
    (the others at their centre); PNG files in ``folder``."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from . import plots

    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    written = []
    factors = [str(f) for f in dataset["factor"].values]
    for response, surface in fitted.items():
        fig = plots.main_effects(dataset, response)
        written.append(_save(fig, folder / f"main_effects_{response}.png", plt))
        if len(factors) >= 2 and not isinstance(surface, str):
            fig = plots.contour(surface, factors[0], factors[1], dataset=dataset)
            written.append(_save(fig, folder / f"contour_{response}_{factors[0]}_{factors[1]}.png", plt))
            fig = plots.interactions(dataset, response, factors[0], factors[1])
            written.append(_save(fig, folder / f"interaction_{response}_{factors[0]}_{factors[1]}.png", plt))
    return written


def _save(fig, path: Path, plt) -> Path:
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def front_figure(values: np.ndarray, objectives, verified, dataset, path: str | Path) -> Path:
    """The Pareto front of the first two objectives (predicted by the surfaces), the study's cases, and the
    verified points (prediction joined to the run's value by a line)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    a, b = objectives[0].response, objectives[1 if len(objectives) > 1 else 0].response
    fig, ax = plt.subplots(figsize=(6.5, 5))
    order = np.argsort(values[:, 0])
    ax.plot(values[order, 0], values[order, 1 if len(objectives) > 1 else 0], ".", ms=3, color="0.5",
            label="front on the surfaces")
    ax.plot(dataset[a].values, dataset[b].values, "o", mfc="none", color="C0", label="cases run")
    for k, o in enumerate(verified):
        ax.plot([o.predicted[a], o.verified[a]], [o.predicted[b], o.verified[b]], "-", color="C3", lw=0.8)
        ax.plot(o.verified[a], o.verified[b], "*", ms=11, color="C3", label="verified by a run" if k == 0 else None)
    ax.set_xlabel(f"{a} [{dataset[a].attrs.get('units', '')}] ({objectives[0].goal})")
    ax.set_ylabel(f"{b} [{dataset[b].attrs.get('units', '')}] ({objectives[-1].goal})")
    ax.set_title("Pareto front of the fitted surfaces, with the cases and verifying runs")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path
