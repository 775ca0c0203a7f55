"""The slider-crank of paper 001 with a dry revolute clearance joint between
the connecting rod (journal) and the slider (bearing).

From the paper: crank 50 mm, connecting rod 300 mm; masses 0.194 / 1.062 /
0.281 kg (crank / rod / slider); rod inertia 0.034 kg m^2; E 207 GPa, nu 0.3
for journal and bearing; restitution 0.5; friction coefficient 0.01; crank
at 500 rpm; radial clearance 0.5 mm; crank and rod start aligned.

CHOSEN here because the paper's table of joint properties did not survive
(these are not the paper's values): bearing radius 10 mm and length 40 mm;
crank inertia 4.0e-5 kg m^2 (a slender 50 mm bar of 0.194 kg); slider
inertia 1e-4 kg m^2 (irrelevant: the slider does not rotate); the contact
law of Flores et al. 2011 (it holds for a restitution as low as 0.5,
Lankarani-Nikravesh does not); Ambrosio's modified Coulomb friction with
v0 = 1e-4 m/s and v1 = 1e-3 m/s; gravity 9.81 m/s^2 along -y. The same model
is examples/paper001_slider_crank_dry.toml. The results are therefore not a
reproduction of the paper's figures.

Run: python examples/paper001_slider_crank_dry.py [--out DIR] [--revolutions N] [--clearance MM]
"""

from __future__ import annotations

import argparse
from pathlib import Path

import jointplay as jp
from jointplay import functions as fn
from jointplay import laws
from jointplay.mechanisms import slider_crank

CRANK_SPEED = fn.rpm(500.0)  # rad/s


def build_model(clearance: float = 0.5e-3, crank_speed: float = CRANK_SPEED) -> jp.Model:
    """Paper 001's slider-crank with a dry clearance joint of radial clearance ``clearance`` [m]."""
    return slider_crank(
        name="paper001_slider_crank_dry",
        crank_length=0.050, rod_length=0.300, masses=(0.194, 1.062, 0.281),
        inertias=(4.0e-5, 0.034, 1e-4),  # crank and slider inertias chosen, rod from the paper
        crank_speed=crank_speed,
        clearance=dict(
            bearing_radius=0.010, clearance=clearance, length=0.040,  # radius and length chosen
            contact=laws.flores(0.5),  # law chosen
            friction=laws.ambrosio(0.01, v0=1e-4, v1=1e-3),  # velocity band chosen
        ),
    )


def main(argv: list[str] | None = None) -> jp.Results:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=None, help="folder for the figures and the NetCDF file")
    parser.add_argument("--revolutions", type=float, default=2.0)
    parser.add_argument("--clearance", type=float, default=0.5, help="radial clearance [mm]")
    args = parser.parse_args(argv)
    t_end = args.revolutions * 2 * 3.141592653589793 / CRANK_SPEED
    # the paper integrates with a variable-step predictor-corrector and a maximum step of 1e-4 s
    results = build_model(args.clearance * 1e-3).simulate(t_end, method="adams", rtol=1e-8, atol=1e-11,
                                                          max_step=1e-4, output_step=t_end / 2000)
    summary = results.summary()
    joint = summary["clearance_joints"]["B"]
    print(results)
    print(f"impacts {joint['impacts']}, contact fraction {joint['contact_fraction']:.3f}, "
          f"peak contact force {summary['peaks']['B.fn']:.4g} N, "
          f"peak slider acceleration {summary['peaks']['slider.ax']:.4g} m/s^2")
    if args.out is not None:
        from jointplay import plots

        args.out.mkdir(parents=True, exist_ok=True)
        results.save(args.out / "paper001_dry.nc")
        for path in plots.standard_figures(results, args.out, crank="crank"):
            print(f"wrote {path}")
    return results


if __name__ == "__main__":
    main()
