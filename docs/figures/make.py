"""Makes the README's figures with `jointplay run`, `jointplay animate` and `jointplay report` (the report's
picture is a screenshot of the page in a headless Chromium, the system's, driven by playwright).

    .venv/bin/python docs/figures/make.py            # writes docs/figures/*, the runs in out/figures/
    .venv/bin/python docs/figures/make.py --quick DIR  # the same commands on short runs, into DIR (the tests)
"""

from __future__ import annotations

import argparse
import shutil
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
FIGURES = ROOT / "docs" / "figures"
#: The figures, each made from the results of a run of an example model: (figure, model, run time, how).
#: ``how`` is "animate" and its options (a GIF, or a PNG still at --start), or "report" and the title of the
#: section the screenshot shows.
STEPS = [
    ("flores_slider_crank_dry.gif", "flores_slider_crank_dry.toml", None,
     ["animate", "--size", "560x315", "--fps", "8", "--duration", "6 s"]),
    ("paper003_breaker.png", "paper003_breaker.toml", None,
     ["animate", "--size", "960x540", "--start", "12 ms"]),
    ("flores_slider_crank_dry_report.png", "flores_slider_crank_dry.toml", None, ["report", "Plots: clearance joint B"]),
]
#: --quick: run time [s] of each model and the animations' frames, so that the tests run the same commands fast.
QUICK_RUN, QUICK_VIDEO = "14 ms", ["--fps", "2", "--duration", "1 s"]


def jointplay(*args) -> None:
    """Runs the installed `jointplay` command next to this interpreter."""
    command = [str(Path(sys.executable).with_name("jointplay")), *map(str, args)]
    subprocess.run(command, check=True, cwd=ROOT)


def make(out: Path, runs: Path, quick: bool) -> list[Path]:
    """Every figure of STEPS into ``out``, the runs' results into ``runs``; returns the figures' paths."""
    out.mkdir(parents=True, exist_ok=True)
    runs.mkdir(parents=True, exist_ok=True)
    written = []
    for figure, model, _, how in STEPS:
        results = runs / Path(model).with_suffix(".nc").name
        if not results.exists():
            jointplay("run", ROOT / "examples" / model, "-o", results, *(["--set", f"simulation.t_end={QUICK_RUN}"]
                                                                           if quick else []))
        target = out / figure
        if how[0] == "animate":
            options = [*how[1:], *(QUICK_VIDEO if quick and target.suffix == ".gif" else [])]
            jointplay("animate", results, "-o", target, "-q", *options)
        else:
            page = runs / f"{target.stem}.html"
            jointplay("report", results, "-o", page, *(["--no-animation"] if quick else []))
            screenshot(page, target, how[1])
        written.append(target)
    return written


def screenshot(page: Path, target: Path, section: str, width: int = 1100, height: int = 900) -> None:
    """The section titled ``section`` of ``page`` as the system Chromium shows it, offline, as a PNG."""
    from playwright.sync_api import sync_playwright

    chromium = shutil.which("chromium") or shutil.which("chromium-headless-shell")
    if chromium is None:
        raise SystemExit("no Chromium found: install it (apt-get install chromium) to make the report's picture")
    with sync_playwright() as playwright:
        browser = playwright.chromium.launch(executable_path=chromium, args=["--no-sandbox"])
        try:
            view = browser.new_context(offline=True, viewport={"width": width, "height": height}).new_page()
            view.goto(page.resolve().as_uri(), wait_until="load")
            view.wait_for_function("[...document.querySelectorAll('.plotly-graph-div')]"
                                   ".every(d => d.querySelector('svg.main-svg'))")
            view.locator("section.jp-section", has=view.locator("h2", has_text=section)).first.screenshot(
                path=str(target))
        finally:
            browser.close()


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", type=Path, default=None, metavar="DIR",
                        help="short runs and few frames, written into DIR (not docs/figures)")
    args = parser.parse_args(argv)
    if args.quick is not None:
        paths = make(args.quick, args.quick / "runs", quick=True)
    else:
        paths = make(FIGURES, ROOT / "out" / "figures", quick=False)
    for path in paths:
        print(f"wrote {path}")


if __name__ == "__main__":
    main()
