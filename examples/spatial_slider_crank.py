"""Haug's spatial slider-crank, driven at one turn a second.

A crank turns about the global x axis at O = (0, 100, 120) mm; a 300 mm
connecting rod joins the crank's end B (spherical joint) to a slider C
(universal joint) that slides along the global x axis through the origin. The
crank's plane is 100 mm beside and 120 mm above the slider's line, so the rod
moves in space. Gravity acts along -z.

Source: E. J. Haug, Computer-Aided Kinematics and Dynamics of Mechanical
Systems, Allyn and Bacon, 1989 (the spatial slider-crank; data as in the course
model of simEngine3D, "sliderCrankMechanism.m, taken from ch. 12.2"). CHOSEN
here: the start with the crank pointing up, the slider's inertia and the
rod-slider joint as a universal joint (the model file
examples/spatial_slider_crank.toml says why each value is what it is).

What to look at: the slider's stroke, which the geometry alone fixes
(sqrt(L^2 - B_y^2 - B_z^2) between its extremes over a turn), and the peak
reactions of the four joints and the motor's torque.

Run: python examples/spatial_slider_crank.py [--out DIR]
(--out: writes the results as NetCDF and a figure of the slider and the motor into DIR)
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np

import jointplay as jp
from jointplay import functions as fn

T_END = 2.0  # s: two turns
#: Marker axes (rows of the matrix; its columns are the marker's x, y, z axes) whose z axis is the body's x
#: axis: the crank's pivot (global x in the ground, the crank's x axis) and the slider's guide (global x).
Z_ALONG_X = {"matrix": [[0, 0, 1], [1, 0, 0], [0, 1, 0]]}
#: The slider's marker of the universal joint: its x axis (the cross's first axis) along global z.
X_ALONG_Z = {"matrix": [[0, 1, 0], [0, 0, 1], [1, 0, 0]]}
JOINTS = ("O", "B", "C", "guide")
#: The channels the figure draws, one panel each.
FIGURE_CHANNELS = ("slider.x", "slider.vx", "motor.torque", "B.f", "C.f")


def build_model() -> jp.Model:
    """The mechanism at the start, crank pointing up. The same model, bit for bit, as
    examples/spatial_slider_crank.toml."""
    m = jp.Model("spatial_slider_crank", gravity=(0, 0, "-9.81 m/s^2"), kinematics="spatial")
    m.add_ground_point("O", (0, "100 mm", "120 mm"), axes=Z_ALONG_X)
    m.add_ground_point("guide", (0, 0, 0), axes=Z_ALONG_X)
    # crank, 80 mm: body x along the pivot axis, y from O to B, turned 90 deg about x (pointing up)
    m.add_body("crank", mass="0.12 kg", inertia={"principal": ["1e-4 kg m^2", "1e-5 kg m^2", "1e-4 kg m^2"]},
               position=(0, "100 mm", "160 mm"), orientation={"axis": [1, 0, 0], "angle": "90 deg"},
               points={"O": {"position": [0, "-40 mm", 0], "axes": Z_ALONG_X}, "B": [0, "40 mm", 0]})
    # rod, 300 mm from B = (0, 100, 200) mm to C = (200, 0, 0) mm: body x along it, (2, -1, -2)/3, y horizontal
    m.add_body("rod", mass="0.5 kg", inertia={"principal": ["4e-4 kg m^2", "4e-3 kg m^2", "4e-3 kg m^2"]},
               position=("100 mm", "50 mm", "100 mm"),
               orientation={"euler": ["-26.56505117707799 deg", "41.810314895778596 deg", 0], "sequence": "ZYX"},
               points={"B": ["-150 mm", 0, 0], "C": ["150 mm", 0, 0]})
    m.add_body("slider", mass="2 kg", inertia={"principal": ["1e-4 kg m^2", "1e-4 kg m^2", "1e-4 kg m^2"]},
               position=("200 mm", 0, 0),
               points={"C": {"position": [0, 0, 0], "axes": X_ALONG_Z},
                       "guide": {"position": [0, 0, 0], "axes": Z_ALONG_X}})
    m.add_revolute("O", "ground.O", "crank.O")
    m.add_spherical("B", "crank.B", "rod.B")
    m.add_universal("C", "slider.C", "rod.C")  # the cross: global z (in the slider) and the rod's y axis
    m.add_translational("guide", "ground.guide", "slider.guide")
    # the crank's angle from the global y axis about x: 90 deg at the start, one turn a second
    m.add_driver("motor", "O", fn.constant_speed("60 rpm", initial="90 deg"))
    return m


def simulate(model: jp.Model, t_end: float = T_END) -> jp.Results:
    """Runs the model (rtol 1e-8, atol 1e-10, samples every ms), as the model file's [simulation]."""
    return model.simulate(t_end, method="dopri5", rtol=1e-8, atol=1e-10, output_step=1e-3)


def report(results: jp.Results) -> str:
    """The slider's stroke and the peak reactions [N] of the joints and torque [N m] of the motor."""
    x = results["slider.x"]
    peaks = ", ".join(f"{joint} {np.max(results[f'{joint}.f']):.2f} N" for joint in JOINTS)
    return "\n".join([
        f"{results}",
        f"slider between {x.min() * 1e3:.3f} and {x.max() * 1e3:.3f} mm: stroke {np.ptp(x) * 1e3:.3f} mm",
        f"peak joint reactions: {peaks}",
        f"peak motor torque {np.max(np.abs(results['motor.torque'])):.4f} N m"])


def main(argv: list[str] | None = None) -> jp.Results:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=None, help="folder for the figure and the NetCDF file")
    out = parser.parse_args(argv).out
    results = simulate(build_model())
    print(report(results))
    if out is not None:
        from jointplay import plots

        results.save(plots.figure_folder(out) / "spatial_slider_crank.nc")
        print(f"wrote {plots.time_histories(results, FIGURE_CHANNELS, out / 'spatial_slider_crank.png')}")
    return results


if __name__ == "__main__":
    main()
