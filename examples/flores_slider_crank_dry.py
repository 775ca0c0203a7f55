"""The Flores-Ambrosio slider-crank with a dry revolute clearance joint.

Crank 0.05 m and connecting rod 0.12 m; masses 0.30 / 0.21 / 0.14 kg and
inertias 1e-4 / 2.5e-4 / 1e-4 kg m^2 (crank / rod / slider); crank driven
at 5000 rpm; gravity. The joint between the connecting rod (journal) and the
slider (bearing) has a bore radius of 10 mm, a radial clearance of 0.5 mm and
a length of 40 mm; steel (E 207 GPa, nu 0.3); Lankarani-Nikravesh contact
with restitution 0.9; Ambrosio's modified Coulomb friction, mu 0.01, v0 1e-4
m/s, v1 1e-3 m/s. Crank and rod start along x with the journal centred and
the velocities of the ideal mechanism. Two crank revolutions.

Run: python examples/flores_slider_crank_dry.py [--out DIR] [--revolutions N]
(with --out: the standard figures, the results file, an animation of the mechanism and its report)
"""

from __future__ import annotations

import argparse
from pathlib import Path

import jointplay as jp
from jointplay import functions as fn
from jointplay import laws
from jointplay.mechanisms import slider_crank

CRANK_SPEED = fn.rpm(5000.0)  # rad/s
CRANK, ROD = 0.05, 0.12  # m
# The slider starts at crank + rod = 170 mm, written as the model file writes it:
# 0.05 + 0.12 rounds to 0.16999999999999998 m, and after the first impacts that
# last bit changes the impact times (free flight in the clearance is chaotic;
# see docs/getting-started.md).
SLIDER_START = 0.17  # m


def build_model(clearance: float = 0.5e-3) -> jp.Model:
    """The dry-clearance slider-crank; ``clearance`` is the radial clearance [m].

    The same model, bit for bit, as examples/flores_slider_crank_dry.toml.
    """
    model = slider_crank(
        name="flores_slider_crank_dry",
        crank_length=CRANK, rod_length=ROD, masses=(0.30, 0.21, 0.14), inertias=(1e-4, 2.5e-4, 1e-4),
        crank_speed=CRANK_SPEED,
        clearance=dict(
            bearing_radius=0.010, clearance=clearance, length=0.040,
            contact=laws.lankarani_nikravesh(0.9),
            friction=laws.ambrosio(0.01, v0=1e-4, v1=1e-3),
        ),
    )
    spec = model.to_spec()
    slider = next(b for b in spec["bodies"] if b["name"] == "slider")
    slider["position"][0] = SLIDER_START
    return jp.Model.from_spec(spec)


def revolutions_to_time(revolutions: float) -> float:
    """Simulated time [s] for a number of crank revolutions."""
    return revolutions * 2 * 3.141592653589793 / CRANK_SPEED


def simulate(model: jp.Model, revolutions: float = 2.0, **options) -> jp.Results:
    """Runs the model for ``revolutions`` crank turns (rtol 1e-6, max step 1e-4 s by default)."""
    options.setdefault("rtol", 1e-6)
    options.setdefault("atol", 1e-9)
    options.setdefault("max_step", 1e-4)
    return model.simulate(revolutions_to_time(revolutions), **options)


def main(argv: list[str] | None = None) -> jp.Results:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=None, help="folder for the figures and the NetCDF file")
    parser.add_argument("--revolutions", type=float, default=2.0)
    args = parser.parse_args(argv)
    results = simulate(build_model(), args.revolutions)
    summary = results.summary()
    joint = summary["clearance_joints"]["B"]
    print(f"{results}")
    print(f"impacts {joint['impacts']}, contact fraction {joint['contact_fraction']:.3f}, "
          f"peak contact force {summary['peaks']['B.fn']:.4g} N, "
          f"peak slider acceleration {summary['peaks']['slider.ax']:.4g} m/s^2")
    stats = results.statistics
    print(f"steps {stats['accepted_steps']} accepted / {stats['rejected_steps']} rejected, "
          f"{stats['rhs_evaluations']} rhs evaluations, wall time {results.wall_time:.3f} s")
    if args.out is not None:
        from jointplay import plots

        args.out.mkdir(parents=True, exist_ok=True)
        results.save(args.out / "flores_dry.nc")
        for path in plots.standard_figures(results, args.out, crank="crank"):
            print(f"wrote {path}")
        # the mechanism in motion, and the whole run in one page to hand on (docs/reports.md)
        print(f"wrote {results.animate(args.out / 'flores_dry.mp4')}")
        print(f"wrote {results.report(args.out / 'flores_dry.html')}")
    return results


if __name__ == "__main__":
    main()
