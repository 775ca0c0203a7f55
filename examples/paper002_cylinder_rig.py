"""Paper 002's hydraulic cylinder rig: a cylinder inclined 5 deg between a fixed support and a slider, held
at both ends by spatial revolute joints with radial and axial clearance, driven by a sine force on the slider.

Paper 002: the dynamics of a hydraulic cylinder with 3D revolute clearance joints (its §2.2, §3, §4). The
model is defined once, in examples/paper002_cylinder_rig.toml, whose header lists what comes from the paper
and what is CHOSEN (its Tables 1-2 are lost: an XE60D-class middle-arm cylinder, masses from steel volumes,
the pins' dimensions, the start pressures). Here the file's document is read and varied: the input force's
amplitude and frequency, the radial and axial clearance of both joints, and the variant with ideal
revolute joints in place of the clearance joints (``--ideal``), which paper 002 compares with, and the
rod's eye turned about the cylinder's axis (``--eye-clocking DEG``, CHOSEN: a threaded rod eye screwed in a
little off), which tilts the rod-end journal in its bore: the rig as the file has it is symmetric about its
plane of motion, so its journals stay aligned and never move along their axes. Nothing here is a
reproduction of the paper's numbers.

What to look at, as the paper's figures: the journal axis in both bores (ends A, B and middle, on the
bore's section, coloured by motion mode: Figs. 15-16, 18); the rod's displacement in the barrel z_rod, the
stroke relative to its start (Fig. 19); the contact forces of both joints and the piston force (Fig. 18);
the axial position of the journals and the flange forces (Fig. 21); the point cloud of the journal centre
over the bore's length (Fig. 20); the time fractions of the motion modes (Figs. 24, 27, 30). The 48-case
study of the fractions against force, frequency and clearance: examples/paper002_cylinder_study.py.

Run: python examples/paper002_cylinder_rig.py [--out DIR] [--t-end S] [--force N] [--frequency HZ]
     [--clearance M] [--ideal | --eye-clocking DEG]
(the full run: 10 s, as the paper; --out writes the figures, the NetCDF results and the mode fractions)
"""

from __future__ import annotations

import argparse
import copy
from pathlib import Path

import numpy as np

import jointplay as jp
from jointplay.modelfile import from_document, read_document

MODEL_FILE = Path(__file__).resolve().with_name("paper002_cylinder_rig.toml")
#: The two clearance joints: the barrel's pin in the fixed support, the rod's pin in the slider.
JOINTS = ("base", "rod_end")
#: The hydraulic cylinder force element (its ``stroke`` channel gives z_rod).
CYLINDER = "cylinder"
#: The element type of the clearance joints in the model file.
CLEARANCE_TYPE = "spatial_clearance_revolute"
#: Two periods of the 10 Hz input in the steady state, the window of paper 002's Fig. 15 [s].
PAPER_WINDOW = (5.35, 5.55)
#: Note carried by every figure's title.
CHOSEN_NOTE = "Dimensions CHOSEN (paper 002's tables are lost): not a reproduction of its figures."


def document(*, force: float | None = None, frequency: float | None = None, clearance: float | None = None,
             axial_clearance: float | None = None, ideal: bool = False, eye_clocking: float = 0.0) -> dict:
    """The model file's document with the input's amplitude ``force`` [N] and ``frequency`` [Hz], the radial
    ``clearance`` and ``axial_clearance`` [m] of both joints changed where given; ``ideal``: both joints
    ideal revolute joints between the same markers (bore first, pin second); ``eye_clocking`` [deg]: the
    rod's eye turned by that much about the cylinder's axis, its journal tilted so in the bore at the start
    (the joints then start where the bodies are, not locked centred and aligned)."""
    doc = copy.deepcopy(read_document(MODEL_FILE))
    if eye_clocking:
        if ideal:
            raise ValueError("an ideal pin cannot hold a clocked eye: its axis would cross the other pin's")
        axes = doc["bodies"]["rod"]["points"]["pin"]["axes"]
        axes["angle"] = f"{90.0 + eye_clocking!r} deg"
        for name in JOINTS:
            doc["joints"][name]["lock_at_assembly"] = False
    sine = doc["forces"]["input"]["force"][0]
    if force is not None:
        sine["amplitude"] = f"{force!r} N"
    if frequency is not None:
        sine["frequency"] = f"{frequency!r} Hz"
    for name in JOINTS:
        joint = doc["joints"][name]
        if joint["type"] != CLEARANCE_TYPE:
            continue
        if clearance is not None:
            joint["clearance"] = f"{clearance!r} m"
        if axial_clearance is not None:
            joint["axial_clearance"] = f"{axial_clearance!r} m"
        if ideal:
            doc["joints"][name] = {"type": "revolute", "first": joint["bearing"], "second": joint["journal"]}
    return doc


def build_model(**variant) -> jp.Model:
    """The rig as a Model, with the changes of :func:`document`."""
    return from_document(document(**variant), name=MODEL_FILE.name, base=MODEL_FILE.parent)


def simulate(model: jp.Model, t_end: float | None = None) -> jp.Results:
    """Runs ``model`` with the model file's [simulation] options, to ``t_end`` [s] (default: the file's)."""
    options = dict(model.simulation)
    end = options.pop("t_end")
    return model.simulate(end if t_end is None else t_end, **options)


def rod_displacement(results: jp.Results) -> np.ndarray:
    """z_rod [m]: the stroke relative to its start, > 0 when the rod extends (paper 002's Fig. 19)."""
    stroke = results[f"{CYLINDER}.stroke"]
    return stroke - stroke[0]


def has_clearance(results: jp.Results) -> bool:
    """Whether the run's joints are the clearance joints (else the ideal variant)."""
    return f"{JOINTS[0]}.mode" in results


def report(results: jp.Results) -> str:
    """Headline numbers: z_rod's range, peak forces of the joints and the piston, and per clearance joint
    its mode fractions, largest tilt and largest radial penetration."""
    z = rod_displacement(results) * 1e3
    peaks = results.summary()["peaks"]
    lines = [f"{results}",
             f"z_rod between {z.min():.4f} and {z.max():.4f} mm; cylinder force peak "
             f"{peaks.get(f'{CYLINDER}.force', float('nan')):.1f} N; seal sticking "
             f"{np.mean(results[f'{CYLINDER}.stick']):.3f} of the samples"]
    for joint in JOINTS:
        lines.append(f"{joint}: peak force {peaks.get(f'{joint}.f', float('nan')):.1f} N")
        if has_clearance(results):
            from jointplay.plots_spatial_clearance import mode_fractions

            fractions = ", ".join(f"{k} {v:.3f}" for k, v in mode_fractions(results, joint).items())
            tilt = np.degrees(np.max(np.abs(results[f"{joint}.tilt"])))
            lines.append(f"  modes: {fractions}; largest tilt {tilt:.4f} deg")
    return "\n".join(lines)


def window_of(results: jp.Results) -> tuple[float, float] | None:
    """Paper 002's window of two periods when the run reaches it, else the last 0.2 s (or the whole run)."""
    end = float(results.time[-1])
    if end >= PAPER_WINDOW[1]:
        return PAPER_WINDOW
    return (max(0.0, end - 0.2), end)


def history_figure(results: jp.Results, window: tuple[float, float] | None):
    """z_rod, the joints' contact forces and the piston force, the journals' axial positions against time
    over ``window`` (paper 002's Figs. 18-19 and 21)."""
    from jointplay.plots import _figure, _title, set_titles, stopped_note
    from jointplay.plots_spatial_clearance import window_mask

    pick = window_mask(results, window)
    t = results.time[pick]
    fig = _figure(8.0, 8.0)
    axes = fig.subplots(4 if has_clearance(results) else 2, 1, sharex=True)
    axes[0].plot(t, rod_displacement(results)[pick] * 1e3, lw=0.8)
    axes[0].set_ylabel("z_rod [mm]")
    for joint in JOINTS:
        axes[1].plot(t, results[f"{joint}.f"][pick], lw=0.8, label=f"{joint}.f")
    axes[1].plot(t, np.abs(results[f"{CYLINDER}.force"][pick]), lw=0.8, color="black", label="|cylinder.force|")
    axes[1].set_ylabel("force [N]")
    axes[1].legend(fontsize=7, loc="upper right")
    if has_clearance(results):
        for joint in JOINTS:
            axes[2].plot(t, results[f"{joint}.axial_position"][pick] * 1e3, lw=0.8, label=joint)
            axes[3].plot(t, results[f"{joint}.fn_fa"][pick] + results[f"{joint}.fn_fb"][pick], lw=0.8,
                         label=f"{joint}: flange forces")
        axes[2].set_ylabel("axial position [mm]")
        axes[3].set_ylabel("flange force [N]")
        for ax in axes[2:]:
            ax.legend(fontsize=7, loc="upper right")
    axes[-1].set_xlabel("time [s]")
    for ax in axes:
        ax.grid(alpha=0.3)
    set_titles(fig, f"{_title(results)}: rod displacement z_rod (stroke from its start), joint and piston forces"
                    f"{', axial positions and flange forces' if has_clearance(results) else ''}. {CHOSEN_NOTE}",
               [stopped_note(results)])
    return fig


def write_figures(results: jp.Results, out: Path) -> list[Path]:
    """Writes the figures of a run into ``out``: the time histories, and for a clearance run per joint the
    trajectories in the bore and the point cloud, and the mode fractions; returns their paths."""
    from jointplay import plots
    from jointplay import plots_spatial_clearance as psc

    folder = plots.figure_folder(out)
    window = window_of(results)
    figures = {"paper002_rig_histories": history_figure(results, window)}
    if has_clearance(results):
        for joint in JOINTS:
            figures[f"paper002_rig_trajectories_{joint}"] = psc.trajectories_figure(results, joint, window,
                                                                                   CHOSEN_NOTE)
            figures[f"paper002_rig_point_cloud_{joint}"] = psc.point_cloud_figure(results, joint, None, CHOSEN_NOTE)
        figures["paper002_rig_mode_fractions"] = psc.mode_fractions_figure(results, JOINTS, CHOSEN_NOTE)
    return [plots._save(fig, folder / f"{name}.png") for name, fig in figures.items()]


def main(argv: list[str] | None = None) -> jp.Results:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=None, help="folder for the figures and the NetCDF file")
    parser.add_argument("--t-end", type=float, default=None, help="end time [s] (default: the file's, 10 s)")
    parser.add_argument("--force", type=float, default=None, help="input amplitude Fmax [N] (default 3000)")
    parser.add_argument("--frequency", type=float, default=None, help="input frequency [Hz] (default 10)")
    parser.add_argument("--clearance", type=float, default=None, help="radial clearance of both joints [m]")
    parser.add_argument("--ideal", action="store_true", help="ideal revolute joints in place of the clearance")
    parser.add_argument("--eye-clocking", type=float, default=0.0,
                        help="turn of the rod's eye about the cylinder's axis [deg] (tilts the rod-end journal)")
    args = parser.parse_args(argv)
    model = build_model(force=args.force, frequency=args.frequency, clearance=args.clearance, ideal=args.ideal,
                        eye_clocking=args.eye_clocking)
    results = simulate(model, args.t_end)
    print(report(results))
    if args.out is not None:
        saved = args.out / "paper002_cylinder_rig.nc"
        for path in write_figures(results, args.out):
            print(f"wrote {path}")
        results.save(saved)
        print(f"wrote {saved}")
    return results


if __name__ == "__main__":
    main()
