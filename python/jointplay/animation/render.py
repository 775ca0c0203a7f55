"""Drawing a :class:`~jointplay.animation.scene.Scene` with matplotlib (Agg), one frame after another.

The artists are made once and their data replaced at each frame; ``Renderer.artists`` names them
(``"body:crank"``, ``"beam:rod"``, ``"mesh:coupler"`` (nodes, markers only), ``"bore:B"``,
``"journal:B"``, ``"arrow:B"``, ``"force:lift"``, ``"guide:guide"``, ``"pins"``, ``"ground"``,
``"bore_axis:B"``, ``"journal_axis:B"``, ``"bore_rims:B"``, ``"journal_rims:B"``), so what is drawn can be read
back.
"""

from __future__ import annotations

import numpy as np

from .scene import Scene

#: Pixels per inch of the figure: its size in inches is the frame size in pixels / DPI.
DPI = 100
_AXIS_NAMES = {"xy": ("x", "y"), "xz": ("x", "z"), "yz": ("y", "z"), "iso": ("isometric, across", "isometric, up")}


class Renderer:
    """A figure of ``size`` (width, height) pixels: the mechanism on the left, the chosen channels
    over time with a cursor at the frame's time on the right, the time and the scales stated (``still``:
    the statement of a single picture rather than of a video)."""

    def __init__(self, scene: Scene, size: tuple[int, int], still: bool = False):
        from matplotlib.backends.backend_agg import FigureCanvasAgg
        from matplotlib.figure import Figure

        self.scene = scene
        self.size = size
        self.figure = Figure(figsize=(size[0] / DPI, size[1] / DPI), dpi=DPI)
        self.canvas = FigureCanvasAgg(self.figure)
        self.artists: dict = {}
        self.unit, self.per_metre = ("m", 1.0) if scene.size >= 2.0 else ("mm", 1e3)
        right = 0.56 if scene.channels else 0.97
        self.ax = self.figure.add_axes((0.07, 0.17, right - 0.07, 0.74))
        self._mechanism_axes()
        self._mechanism_artists(scene.frame(0))
        self.cursors = self._channel_axes(right + 0.08) if scene.channels else []
        self.title = self.figure.text(0.07, 0.95, "", fontsize=11, weight="bold")
        for row, line in enumerate(scene.notes(still)):
            self.figure.text(0.07, 0.06 - 0.035 * row, line, fontsize=8.5)

    # layout -----------------------------------------------------------------

    def _mechanism_axes(self) -> None:
        xmin, xmax, ymin, ymax = (v * self.per_metre for v in self.scene.limits)
        # widen one span so that a unit is as long across as up (equal aspect, the whole view shown)
        box = self.ax.get_position()
        pixels = (box.width * self.size[0]) / (box.height * self.size[1])
        if (xmax - xmin) / (ymax - ymin) < pixels:
            middle, half = 0.5 * (xmin + xmax), 0.5 * pixels * (ymax - ymin)
            xmin, xmax = middle - half, middle + half
        else:
            middle, half = 0.5 * (ymin + ymax), 0.5 * (xmax - xmin) / pixels
            ymin, ymax = middle - half, middle + half
        self.ax.set_xlim(xmin, xmax)
        self.ax.set_ylim(ymin, ymax)
        across, up = _AXIS_NAMES[self.scene.projection]
        self.ax.set_xlabel(f"{across} [{self.unit}]")
        self.ax.set_ylabel(f"{up} [{self.unit}]")
        self.ax.grid(alpha=0.25)

    def _mechanism_artists(self, g) -> None:
        from matplotlib.patches import Circle, FancyArrowPatch

        ax, a = self.ax, self.artists
        for name in g.forces:
            a[f"force:{name}"], = ax.plot([], [], "-", color="tab:orange", lw=3, alpha=0.8, solid_capstyle="round")
        for name in g.guides:
            a[f"guide:{name}"], = ax.plot([], [], "--", color="0.45", lw=1.2)
        for name in g.bodies:
            a[f"body:{name}"], = ax.plot([], [], "-", color="tab:blue", lw=4, solid_capstyle="round", alpha=0.85)
        for name in g.beams:
            a[f"beam:{name}"], = ax.plot([], [], ".-", color="tab:green", lw=3, ms=5)
        for name in g.meshes:
            a[f"mesh_lines:{name}"] = _line_collection(ax)
            a[f"mesh:{name}"], = ax.plot([], [], ".", color="tab:green", ms=5)
        a["ground"], = ax.plot([], [], "^", color="0.25", ms=11, ls="none")
        a["pins"], = ax.plot([], [], "o", mfc="white", mec="black", ms=6, ls="none")
        for name in g.bores:
            a[f"bore:{name}"] = ax.add_patch(Circle((0, 0), 1.0, fill=False, ec="black", lw=1.5, zorder=3))
            a[f"journal:{name}"] = ax.add_patch(Circle((0, 0), 1.0, fc="tab:red", ec="darkred", alpha=0.5, zorder=3))
        for name in g.bore_axes:
            a[f"bore_axis:{name}"], = ax.plot([], [], "-", color="0.3", lw=7, alpha=0.35, solid_capstyle="butt")
            a[f"journal_axis:{name}"], = ax.plot([], [], "-", color="tab:red", lw=2)
            a[f"bore_rims:{name}"], = ax.plot([], [], "-", color="black", lw=1.2)
            a[f"journal_rims:{name}"], = ax.plot([], [], "-", color="darkred", lw=1.2)
        for name in g.arrows:
            a[f"arrow:{name}"] = ax.add_patch(FancyArrowPatch((0, 0), (0, 0), arrowstyle="-|>", mutation_scale=14,
                                                              color="tab:purple", lw=2, zorder=5))

    def _channel_axes(self, left: float) -> list:
        """One axes per channel, stacked; the channel over [start, end] from the saved samples and a
        cursor (vertical line and dot) at the frame's time."""
        from ..display import time_unit

        results, scene = self.results, self.scene
        unit, seconds = time_unit(scene.end)
        window = (results.time >= scene.start) & (results.time <= scene.end)
        n = len(scene.channels)
        height = 0.74 / n
        cursors = []
        for row, name in enumerate(scene.channels):
            ax = self.figure.add_axes((left, 0.17 + (n - 1 - row) * height + 0.04, 0.97 - left, height - 0.07))
            t, values = envelope(results.time[window], results[name][window])
            ax.plot(t / seconds, values, lw=1, color="tab:blue")
            ax.set_ylabel(f"{name} [{results.unit(name)}]", fontsize=8)
            ax.tick_params(labelsize=7)
            ax.grid(alpha=0.25)
            if row == n - 1:
                ax.set_xlabel(f"time [{unit}]")
            cursors.append((ax.axvline(scene.start / seconds, color="tab:red", lw=1),
                            ax.plot([], [], "o", color="tab:red", ms=4)[0], name, seconds))
        return cursors

    @property
    def results(self):
        return self.scene.results

    # frames -----------------------------------------------------------------

    def draw(self, k: int) -> None:
        """Sets every artist to frame k (no rasterising)."""
        from ..display import format_time

        g, a, s = self.scene.frame(k), self.artists, self.per_metre
        for kind, shapes in (("body", g.bodies), ("beam", g.beams), ("mesh", g.meshes), ("force", g.forces),
                             ("guide", g.guides), ("bore_axis", g.bore_axes), ("journal_axis", g.journal_axes),
                             ("bore_rims", g.bore_rims), ("journal_rims", g.journal_rims)):
            for name, points in shapes.items():
                a[f"{kind}:{name}"].set_data(points[:, 0] * s, points[:, 1] * s)
        for name, nodes in g.meshes.items():
            edges = self.scene.model.edges.get(name, np.zeros((0, 2), dtype=int))
            a[f"mesh_lines:{name}"].set_segments(nodes[edges] * s)
        a["ground"].set_data(g.ground[:, 0] * s, g.ground[:, 1] * s)
        a["pins"].set_data(g.pins[:, 0] * s, g.pins[:, 1] * s)
        for kind, circles in (("bore", g.bores), ("journal", g.journals)):
            for name, (centre, radius) in circles.items():
                a[f"{kind}:{name}"].set_center(tuple(centre * s))
                a[f"{kind}:{name}"].set_radius(radius * s)
        for name, (start, vector) in g.arrows.items():
            a[f"arrow:{name}"].set_positions(tuple(start * s), tuple((start + vector) * s))
        for line, dot, name, seconds in self.cursors:
            line.set_xdata([g.time / seconds, g.time / seconds])
            dot.set_data([g.time / seconds], [self.scene.sampled.at(k, name)])
        self.title.set_text(f"{self.results.spec.get('name', '')}   t = {format_time(g.time, self.scene.end)}")

    def rgb(self, k: int) -> np.ndarray:
        """Frame k as an (height, width, 3) uint8 image."""
        self.draw(k)
        self.canvas.draw()
        return np.asarray(self.canvas.buffer_rgba())[:, :, :3].copy()

    def close(self) -> None:
        self.figure.clear()


#: Columns of a channel's plot beyond which its samples are drawn as the envelope of each column.
ENVELOPE_COLUMNS = 2000


def envelope(time: np.ndarray, values: np.ndarray, columns: int = ENVELOPE_COLUMNS) -> tuple[np.ndarray, np.ndarray]:
    """The samples to draw of a channel: all of them up to ``2 * columns``, else the smallest and the largest
    value of each of ``columns`` runs of consecutive samples, in time order (every peak kept, redrawn fast)."""
    if time.size <= 2 * columns:
        return time, values
    runs = np.array_split(np.arange(time.size), columns)
    picked = []
    for run in runs:
        low, high = run[np.argmin(values[run])], run[np.argmax(values[run])]
        picked += sorted((low, high))
    picked = np.array(picked)
    return time[picked], values[picked]


def _line_collection(ax):
    from matplotlib.collections import LineCollection

    return ax.add_collection(LineCollection([], colors="tab:green", linewidths=2))
