"""The README's figures come from `jointplay animate` and `jointplay report`: docs/figures/make.py makes each
one, and its commands run here (on short runs, into a temporary folder) so that they keep working."""

from __future__ import annotations

import importlib.util
import re
from pathlib import Path

from browser import chromium_or_skip

ROOT = Path(__file__).resolve().parents[1]


def make_module():
    spec = importlib.util.spec_from_file_location("make_figures", ROOT / "docs" / "figures" / "make.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_every_readme_figure_is_made_by_the_script_and_is_there():
    shown = set(re.findall(r"\]\(docs/figures/([^)]+)\)", (ROOT / "README.md").read_text()))
    made = {figure for figure, *_ in make_module().STEPS}
    assert shown == made
    assert all((ROOT / "docs" / "figures" / name).stat().st_size > 10_000 for name in made)


def test_the_scripts_commands_make_every_figure(tmp_path):
    from PIL import Image

    chromium_or_skip()  # the report's picture is a screenshot
    module = make_module()
    module.main(["--quick", str(tmp_path)])
    for figure, *_ in module.STEPS:
        with Image.open(tmp_path / figure) as image:
            assert image.size[0] >= 320 and image.size[1] >= 240
            if figure.endswith(".gif"):
                assert image.n_frames == 2  # --quick: 2 frames
