"""The Flores-Ambrosio slider-crank with ideal joints: the reference the
clearance variants are compared with. Same parameters as
``flores_slider_crank_dry.py``; the joint between rod and slider is an ideal
revolute joint. Two crank revolutions at 5000 rpm.

Run: python examples/flores_slider_crank_ideal.py [--out DIR] [--revolutions N]
"""

from __future__ import annotations

import argparse
from pathlib import Path

import jointplay as jp
from flores_slider_crank_dry import build_model, revolutions_to_time


def build_ideal_model() -> jp.Model:
    """The ideal slider-crank (clearance joint B replaced by an ideal pin)."""
    model = build_model().idealized()
    model._spec["name"] = "flores_slider_crank_ideal"
    return model


def main(argv: list[str] | None = None) -> jp.Results:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=None, help="folder for the NetCDF file")
    parser.add_argument("--revolutions", type=float, default=2.0)
    args = parser.parse_args(argv)
    results = build_ideal_model().simulate(revolutions_to_time(args.revolutions), rtol=1e-8, atol=1e-11,
                                           output_step=revolutions_to_time(1.0) / 720)
    summary = results.summary()
    print(results)
    print(f"peak slider acceleration {summary['peaks']['slider.ax']:.4g} m/s^2, "
          f"peak force at B {summary['peaks']['B.f']:.4g} N, peak motor torque {summary['peaks']['motor.torque']:.4g} N m")
    if args.out is not None:
        args.out.mkdir(parents=True, exist_ok=True)
        results.save(args.out / "flores_ideal.nc")
    return results


if __name__ == "__main__":
    main()
