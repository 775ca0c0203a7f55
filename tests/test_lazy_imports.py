"""`import jointplay` and `jointplay --help` load no heavy library: the unit registry and the
schemas (pint, pydantic), plots (matplotlib), results files (xarray), SciPy, and the reports' and
animations' libraries (plotly, Jinja2, imageio-ffmpeg, Pillow) load on first use.

Each check runs in a fresh interpreter, since this test session has imported everything already.
"""

from __future__ import annotations

import json
import subprocess
import sys

import pytest

HEAVY = ("pint", "pydantic", "matplotlib", "xarray", "scipy", "plotly", "jinja2", "imageio_ffmpeg", "PIL")


def loaded_after(code: str) -> list[str]:
    probe = f"{code}\nimport json, sys\nprint(json.dumps([m for m in {HEAVY!r} if m in sys.modules]), file=sys.stderr)"
    result = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, timeout=120)
    return json.loads(result.stderr.strip().splitlines()[-1])


def help_of(*command: str) -> str:
    return (f"import sys\nsys.argv = ['jointplay', *{list(command)!r}, '--help']\nfrom jointplay.cli import main\n"
            "try:\n    main()\nexcept SystemExit:\n    pass")


def test_import_jointplay_loads_no_heavy_library():
    assert loaded_after("import jointplay") == []


def test_main_help_loads_no_heavy_library():
    assert loaded_after(help_of()) == []


@pytest.mark.parametrize("command", ["run", "check", "plot", "compare", "bearing", "animate", "report"])
def test_command_help_loads_only_what_the_option_parser_needs(command):
    # typer coerces option values through pydantic, so a command's help loads it; nothing else
    assert set(loaded_after(help_of(command))) <= {"pydantic"}


def test_lazy_names_resolve_on_first_use():
    code = ("import jointplay as jp\nassert 'load' not in vars(jp)\nf = jp.load\n"
            "assert f is jp.load and callable(jp.loads) and callable(jp.open_results)\n"
            "assert {'load', 'loads', 'open_results'} <= set(dir(jp))")
    assert "pydantic" in loaded_after(code)  # the model-file schemas came with `load`


def test_an_unknown_attribute_is_still_an_attribute_error():
    import jointplay

    with pytest.raises(AttributeError, match="module 'jointplay' has no attribute 'lod'"):
        jointplay.lod  # noqa: B018
