"""What the command line and the figures show stays true: times in the unit that fits, a progress bar
with the time left, tables that never cut a number at any terminal width, figures of a stopped run
that say when and why it stopped, titles that fit, a comparison that says when runs share nothing
and draws its first run visibly."""

from __future__ import annotations

import io
import re
from collections import Counter
from pathlib import Path
from types import SimpleNamespace

import matplotlib.image
import numpy as np
import pytest
from matplotlib.text import Text
from rich.console import Console
from typer.testing import CliRunner

import jointplay as jp
from jointplay import cli, compare, plots
from jointplay.display import WallTimeColumn, format_duration, format_time, print_table, table

ROOT = Path(__file__).resolve().parents[1]
DRY = ROOT / "examples" / "flores_slider_crank_dry.toml"
MODEL_FILES = sorted((ROOT / "examples").glob("*.toml")) + [ROOT / "tests" / "fixtures" / "every_key.toml"]


# times ---------------------------------------------------------------------------------------

@pytest.mark.parametrize(("seconds", "span", "shown"), [
    (4.518e-8, None, "45.18 ns"),
    (2.514e-4, None, "251.4 µs"),
    (2.514e-4, 0.024, "0.2514 ms"),  # a time of a 24 ms run reads in ms
    (0.024, None, "24 ms"),
    (100.0, None, "100 s"),          # up to 2 min in s
    (600.0, None, "10 min"),
    (2.67e4, 1e5, "7.417 h"),        # the run of the issue: 2.67e+04 / 1e+05 ms before
    (0.0, 0.024, "0 ms"),
    (9.97e-10, 0.024, "0.997 ns"),   # not 9.97e-07 ms: a time that needs a power of ten takes its own unit
])
def test_a_time_is_shown_in_the_unit_that_fits(seconds, span, shown):
    assert format_time(seconds, span) == shown


@pytest.mark.parametrize(("t", "end", "shown"), [
    (2.67e4, 1e5, "t = 7.417 / 27.78 h"),
    (0.012, 0.024, "t = 12 / 24 ms"),
    (12.5, 20.0, "t = 12.5 / 20 s"),
    (3e-4, 5e-4, "t = 300 / 500 µs"),
])
def test_progress_shows_the_simulated_time_in_the_unit_of_the_end_time(t, end, shown):
    assert cli.progress_time(t, end) == shown


@pytest.mark.parametrize(("seconds", "shown"), [(0.42, "0.4 s"), (12.3, "12 s"), (185, "3 min 05 s"),
                                                 (4830, "1 h 20 min")])
def test_a_wall_clock_duration_reads_in_hours_minutes_and_seconds(seconds, shown):
    assert format_duration(seconds) == shown


def test_the_progress_column_shows_the_time_elapsed_and_the_time_left():
    column = WallTimeColumn()
    running = SimpleNamespace(elapsed=12.0, time_remaining=100.0, finished=False)
    assert column.render(running).plain == "(12 s elapsed, about 1 min 40 s left)"
    starting = SimpleNamespace(elapsed=0.3, time_remaining=None, finished=False)
    assert column.render(starting).plain == "(0.3 s elapsed, estimating the time left)"


def test_the_progress_bar_of_a_long_run_shows_hours_and_the_time_left():
    console = Console(file=io.StringIO(), width=120, force_terminal=False)
    bar = cli.progress_bar(console)
    task = bar.add_task("run", total=1e5, t=cli.progress_time(0.0, 1e5))
    bar.update(task, completed=2.67e4, t=cli.progress_time(2.67e4, 1e5))
    console.print(bar.get_renderable())
    shown = console.file.getvalue()
    assert "t = 7.417 / 27.78 h" in shown
    assert "elapsed" in shown and "left" in shown
    assert " ms" not in shown


def synthetic_results(names: list[str], units: list[str], end: float = 100.0, **kwargs) -> jp.Results:
    """Results of a fictitious run: channels of ramps over ``end`` [s]."""
    time = np.linspace(0.0, end, 11)
    values = np.array([np.linspace(0.0, k + 1.0, time.size) for k in range(len(names))])
    defaults = {"statistics": {"accepted_steps": 10, "smallest_step": 1e-3, "largest_step": 20.0},
                "diagnostics": {}, "spec": {"name": "long"}, "options": {"output_step": 10.0}, "wall_time": 3725.0}
    defaults.update(kwargs)
    return jp.Results(time, names, units, [""] * len(names), values, **defaults)


def test_the_summary_of_a_long_run_shows_its_times_in_seconds_and_minutes(monkeypatch):
    console = Console(file=io.StringIO(), width=200)
    monkeypatch.setattr(cli, "out", console)
    cli.print_summary(synthetic_results(["arm.torque"], ["N m"]))
    shown = console.file.getvalue()
    assert "long: 11 samples saved (output step 10 s) up to 100 s;" in shown
    assert re.search(r"arm\.torque\s+│ 1 N m\s+│ 100 s", shown), shown  # the peak, at the end of the ramp
    assert re.search(r"smallest step\s+│ 1 ms", shown) and re.search(r"largest step\s+│ 20 s", shown)
    assert re.search(r"wall time\s+│ 62.08 min", shown)
    assert " ms " not in shown.replace("1 ms", "")


# tables --------------------------------------------------------------------------------------

NUMBER = re.compile(r"(?<![\w.+-])[-+]?\d+(?:\.\d+)?(?:e[-+]\d+)?(?![\w.])")


def numbers(text: str) -> Counter:
    """Every number written in ``text`` (not the digits inside a name such as paper001), counted."""
    return Counter(NUMBER.findall(text))


def check_output(path: Path, columns: int) -> str:
    result = CliRunner().invoke(cli.app, ["check", str(path)], env={"COLUMNS": str(columns)})
    assert result.exit_code == 0, result.output
    return result.output


@pytest.mark.parametrize("path", MODEL_FILES, ids=lambda p: p.stem)
def test_check_never_cuts_or_splits_a_number_at_any_terminal_width(path):
    wide = check_output(path, 400)
    assert "…" not in wide
    for columns in (80, 60, 40, 24):
        narrow = check_output(path, columns)
        assert "…" not in narrow, f"a cell cut at {columns} columns:\n{narrow}"
        assert numbers(narrow) == numbers(wide), f"a number split at {columns} columns:\n{narrow}"


def test_check_shows_a_small_inertia_whole_at_80_columns():
    # the rod's 0.00025 kg m^2 is what a unit slip (250 kg mm^2 read as kg m^2) would have hidden
    shown = check_output(DRY, 80)
    assert re.search(r"│ rod\s+│ 0.21 kg\s+│ 0.00025 kg m\^2", shown), shown


def test_a_table_too_wide_for_the_terminal_is_listed_row_by_row_with_every_number_whole():
    def wide_table():
        t = table("modal body", "mass", "held (Hz)", "clamped (Hz)", "free (Hz)", title="modal bodies")
        t.add_row("coupler_with_a_long_name", "0.000123456 kg", "1.2345e+04, 2.3456e+04", "123.456, 7890.12",
                  "0.001234, 5.6789e-05")
        return t

    wide = io.StringIO()
    print_table(Console(file=wide, width=300), wide_table())
    for width in (80, 50, 30, 20):
        out = io.StringIO()
        print_table(Console(file=out, width=width), wide_table())
        shown = out.getvalue()
        assert "…" not in shown
        assert numbers(shown) == numbers(wide.getvalue()) == numbers(
            "0.000123456 1.2345e+04 2.3456e+04 123.456 7890.12 0.001234 5.6789e-05"), shown
        assert max(len(line) for line in shown.splitlines()) <= max(width, len("coupler_with_a_long_name") + 20)
    out = io.StringIO()
    print_table(Console(file=out, width=30), wide_table())
    listed = "- modal body:\n  coupler_with_a_long_name\n    mass: 0.000123456 kg\n    held (Hz): 1.2345e+04,\n      2.3456e+04\n"
    assert listed in out.getvalue(), out.getvalue()


# figures -------------------------------------------------------------------------------------

@pytest.fixture(scope="module")
def dry_runs(tmp_path_factory):
    """The dry example run whole, and stopped by max_steps = 300 (its results read from the
    .partial.nc it left)."""
    folder = tmp_path_factory.mktemp("runs")
    model = jp.load(DRY)
    options = dict(model.simulation)
    end = options.pop("t_end")
    whole = model.simulate(end, output_file=folder / "dry.nc", **options)
    with pytest.raises(jp.SimulationError) as stopped:
        model.simulate(end, output_file=folder / "short.nc", **{**options, "max_steps": 300})
    partial = jp.open_results(folder / "short.partial.nc")
    return whole, partial, stopped.value


@pytest.fixture(scope="module")
def spun():
    """The spinning beam of the examples, run for 4 s."""
    beam = jp.load(ROOT / "examples" / "spin_up_beam.toml")
    options = {key: value for key, value in beam.simulation.items() if key != "t_end"}
    return beam.simulate(4.0, **options)


@pytest.fixture
def drawn(monkeypatch):
    """The figures that plots and compare save, kept to be inspected."""
    figures = []
    save = plots._save

    def keep(fig, path):
        figures.append(fig)
        return save(fig, path)

    monkeypatch.setattr(plots, "_save", keep)
    monkeypatch.setattr(compare, "_save", keep)
    return figures


def texts(fig) -> list[Text]:
    return [t for t in fig.findobj(Text) if t.get_visible() and t.get_text().strip()]


def all_text(fig) -> str:
    return " ".join(" ".join(t.get_text().split()) for t in texts(fig))


def test_every_figure_of_a_stopped_run_says_when_and_why_it_stopped(dry_runs, drawn, tmp_path):
    whole, partial, error = dry_runs
    assert partial.error is not None and partial.path.name == "short.partial.nc"
    note = f"run stopped at t = {error.time:.6g} s: the run exceeded max_steps = 300 attempted steps"
    paths = plots.standard_figures(partial, tmp_path / "plot", channels=["B.fn", "slider.ax"])
    assert len(paths) == len(drawn) == 3  # time histories, orbit, contact force against the crank angle
    for path, fig in zip(paths, drawn):
        assert note in all_text(fig), path.name
    drawn.clear()
    compare.compare_figures([whole, partial], ["whole", "short"], tmp_path / "compare", channels=["B.fn"])
    shown = all_text(drawn[0])
    assert f"run short stopped at t = {error.time:.6g} s: the run exceeded max_steps" in shown
    assert "run whole stopped" not in shown
    drawn.clear()
    plots.standard_figures(whole, tmp_path / "whole", channels=["B.fn"])
    assert not any("stopped" in all_text(fig) for fig in drawn)


def titles_and_labels(fig) -> list[Text]:
    """The figure's title and texts, and each axes' titles, axis labels and legend entries."""
    found = [fig._suptitle, *fig.texts] if fig._suptitle is not None else list(fig.texts)
    for ax in fig.axes:
        found += [ax.title, ax._left_title, ax._right_title, ax.xaxis.label, ax.yaxis.label]
        if ax.get_legend() is not None:
            found += ax.get_legend().get_texts()
    return [t for t in found if t.get_visible() and t.get_text().strip()]


def assert_texts_inside(fig, name: str) -> None:
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    box = fig.bbox
    for t in titles_and_labels(fig):
        extent = t.get_window_extent(renderer)
        assert (extent.x0 >= box.x0 - 1 and extent.x1 <= box.x1 + 1 and extent.y0 >= box.y0 - 1
                and extent.y1 <= box.y1 + 1), f"{name}: {t.get_text()!r} leaves the figure ({extent} in {box})"


def test_every_title_and_label_of_the_figures_fits_inside_the_figure(dry_runs, spun, drawn, tmp_path):
    whole, partial, _ = dry_runs
    for results in (whole, partial):
        plots.standard_figures(results, tmp_path / "figures", channels=["B.fn", "B.eccentricity_ratio"])
    plots.standard_figures(spun, tmp_path / "figures")
    compare.compare_figures([whole, partial, whole], ["a label of some length", "b", "c"], tmp_path / "compare",
                            channels=["B.fn", "slider.ax"])
    assert plots.beams(spun) and len(drawn) >= 9
    for k, fig in enumerate(drawn):
        assert_texts_inside(fig, f"figure {k}: {fig.texts[0].get_text() if fig.texts else ''}")


def test_the_deformed_shape_title_is_broken_to_fit_the_figure(spun, drawn, tmp_path):
    plots.deformed_shapes(spun, plots.beams(spun)[0], tmp_path / "shapes.png")
    title = drawn[0]._suptitle.get_text()
    assert title.startswith("spin_up_beam: beam beam, nodes at the saved samples nearest the times")
    assert "largest deformation" in title and title.count("\n") >= 1
    assert_texts_inside(drawn[0], "shapes")


def pixels_near(image: np.ndarray, colour: str) -> int:
    from matplotlib.colors import to_rgb

    rgb = image[..., :3]
    return int(np.sum(np.all(np.abs(rgb - np.array(to_rgb(colour))) < 0.08, axis=-1)))


def test_the_first_run_drawn_by_compare_shows_where_the_runs_coincide(dry_runs, tmp_path):
    whole, _, _ = dry_runs
    path, = compare.compare_figures([whole, whole], ["first", "second"], tmp_path, channels=["slider.ax"])
    image = matplotlib.image.imread(path)
    first, second = pixels_near(image, "C0"), pixels_near(image, "C1")
    # the same curve twice: the first, wider and solid, shows beside and between the dashes of the second
    assert first > 0.5 * second > 0, (first, second)


def test_compare_of_runs_with_no_channel_in_common_says_so(tmp_path):
    a = synthetic_results(["arm.angle"], ["rad"], spec={"name": "a"})
    b = synthetic_results(["boom.stroke"], ["m"], spec={"name": "b"})
    message = ("nothing to compare: the runs have no channel in common, nothing to overlay "
               "(a: 1 channel (arm.angle); b: 1 channel (boom.stroke))")
    with pytest.raises(ValueError, match=re.escape(message)):
        compare.compare_figures([a, b], ["a", "b"], tmp_path)
    a.save(tmp_path / "a.nc")
    b.save(tmp_path / "b.nc")
    result = CliRunner().invoke(cli.app, ["compare", str(tmp_path / "a.nc"), str(tmp_path / "b.nc"), "-o",
                                          str(tmp_path / "figures")], env={"COLUMNS": "300"})
    assert result.exit_code == 2
    assert f"error: {message}" in result.output
    assert not (tmp_path / "figures").exists()


def test_compare_of_runs_sharing_no_key_channel_names_what_they_share(tmp_path):
    a = synthetic_results(["crank.angle", "system.energy"], ["rad", "J"], spec={"name": "a"})
    b = synthetic_results(["boom.stroke", "system.energy"], ["m", "J"], spec={"name": "b"})
    assert compare.default_compare_channels([a, b]) == []
    assert compare.nothing_to_compare([a, b], ["a", "b"]) == (
        "none of the key channels of a is in another run; the runs share 1 other channel(s) (system.energy): "
        "choose them with --channel")


def test_plot_and_compare_of_a_partial_file_say_when_and_why_the_run_stopped(dry_runs, tmp_path):
    whole, partial, error = dry_runs
    note = f"note: {partial.path}: run stopped at t = {error.time:.6g} s: the run exceeded max_steps = 300"
    result = CliRunner().invoke(cli.app, ["plot", str(partial.path), "-c", "B.fn", "-o", str(tmp_path / "plot")],
                                env={"COLUMNS": "300"})
    assert result.exit_code == 0, result.output
    assert note in result.output
    result = CliRunner().invoke(cli.app, ["compare", str(whole.path), str(partial.path), "-c", "B.fn", "-o",
                                          str(tmp_path / "compare")], env={"COLUMNS": "300"})
    assert result.exit_code == 0, result.output
    assert note in result.output and f"note: {whole.path}" not in result.output
