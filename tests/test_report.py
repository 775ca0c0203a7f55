"""Reports (`jointplay report`, `write_report`, `Results.report`): the HTML is read back as a reader's tools would
(an HTML parser, plotly's figure data) and compared with the model file, `Results.summary()` and the saved channels.

The runs are short (3 ms of the Flores slider-crank, 1 ms of its lubricated variant); the animation is the
animation package's, replaced here by a function returning a small real MP4 encoded by imageio-ffmpeg.
"""

from __future__ import annotations

import base64
import re
import sys
import types
from html.parser import HTMLParser
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

import jointplay
from jointplay.cli import app
from jointplay.errors import ModelError
from jointplay.report import write_report
from jointplay.report.blocks import Plot, Section, Text
from jointplay.report.figures import MAX_POINTS, SPANS, history_figure, keep_indices
from jointplay.report.run import run_sections
from jointplay.results import Results

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = ROOT / "examples"


def simulate(name: str, t_end: float, folder: Path) -> Results:
    """A short run of an example with its own options, saved as ``<name>.nc`` and read back from the file (as a
    report reads it)."""
    path = folder / f"{name}.nc"
    model = jointplay.load(EXAMPLES / f"{name}.toml")
    model.simulate(t_end, **{k: v for k, v in model.simulation.items() if k != "t_end"}).save(path)
    return jointplay.open_results(path)


@pytest.fixture(scope="module")
def folder(tmp_path_factory) -> Path:
    return tmp_path_factory.mktemp("report")


@pytest.fixture(scope="module")
def dry(folder) -> Results:
    return simulate("flores_slider_crank_dry", 3e-3, folder)


@pytest.fixture(scope="module")
def ideal(folder) -> Results:
    return simulate("flores_slider_crank_ideal", 3e-3, folder)


@pytest.fixture(scope="module")
def lubricated(folder) -> Results:
    return simulate("flores_slider_crank_lubricated", 1e-3, folder)


@pytest.fixture(scope="module")
def dry_html(dry, folder) -> str:
    return write_report(dry, folder / "dry.html", animation=False).read_text(encoding="utf-8")


class Page(HTMLParser):
    """What a reader's tools see in a report: its tables (caption, header, rows of cell texts), the attributes
    of every element, and the text of every script."""

    def __init__(self, html: str):
        super().__init__()
        self.tables: list[dict] = []
        self.elements: list[tuple[str, dict]] = []
        self.scripts: list[str] = []
        self._cell: list[str] | None = None
        self._where = ""
        self.feed(html)

    def handle_starttag(self, tag, attrs):
        self.elements.append((tag, dict(attrs)))
        if tag == "table":
            self.tables.append({"caption": "", "columns": [], "rows": []})
        elif tag == "tr" and self.tables:
            self.tables[-1]["rows"].append([])
        elif tag in ("td", "th", "caption"):
            self._cell, self._where = [], tag
        elif tag == "script":
            self.scripts.append("")

    def handle_endtag(self, tag):
        if tag in ("td", "th", "caption") and self._cell is not None:
            text = "".join(self._cell).strip()
            table = self.tables[-1]
            if tag == "caption":
                table["caption"] = text
            elif tag == "th":
                table["columns"].append(text)
            else:
                table["rows"][-1].append(text)
            self._cell = None

    def handle_data(self, data):
        if self._cell is not None:
            self._cell.append(data)
        if self.lasttag == "script" and self.scripts:
            self.scripts[-1] += data

    def table(self, caption: str) -> dict:
        found = [t for t in self.tables if t["caption"].startswith(caption)]
        assert len(found) == 1, f"no single table captioned {caption!r}: {[t['caption'] for t in self.tables]}"
        found[0]["rows"] = [r for r in found[0]["rows"] if r]  # the header row holds th cells only
        return found[0]

    def rows_by_first_cell(self, caption: str) -> dict[str, list[str]]:
        return {row[0]: row[1:] for row in self.table(caption)["rows"]}


def plots_of(sections: list[Section]) -> list[Plot]:
    return [b for s in sections for b in s.blocks if isinstance(b, Plot)]


# the model ------------------------------------------------------------------

def test_run_report_lists_the_clearance_joint_parameters_in_their_units(dry_html):
    # the values of examples/flores_slider_crank_dry.toml, as written there
    joint = Page(dry_html).rows_by_first_cell("Joint B (clearance_revolute)")
    assert joint["clearance"] == ["0.5", "mm"]
    assert joint["bearing_radius"] == ["10", "mm"]
    assert joint["length"] == ["40", "mm"]
    assert joint["bearing_material.youngs_modulus"] == ["2.07e+11", "Pa"]
    assert joint["contact.law"] == ["lankarani_nikravesh", ""]
    assert joint["contact.restitution"] == ["0.9", ""]
    assert joint["friction.law"] == ["ambrosio", ""]
    assert joint["friction.v0"] == ["0.0001", "m/s"]
    assert joint["friction.v1"] == ["0.001", "m/s"]


def test_run_report_lists_bodies_points_and_the_driver_in_units(dry_html):
    page = Page(dry_html)
    bodies = page.table("Rigid bodies")
    assert bodies["columns"] == ["body", "mass [kg]", "inertia about the centre of mass [kg m^2]",
                                 "initial position [mm]"]
    assert bodies["rows"][1] == ["rod", "0.21", "0.00025", "(110, 0)"]
    assert page.rows_by_first_cell("Named points of rod") == {"A": ["(-60, 0)"], "B": ["(60, 0)"]}
    motor = page.rows_by_first_cell("Driver motor")
    assert float(motor["function.rate"][0]) == pytest.approx(5000 * 2 * np.pi / 60, rel=1e-6)  # 5000 rpm
    assert motor["function.rate"][1] == "rad/s"


# run and summary ------------------------------------------------------------

def test_run_report_summary_equals_the_results_summary(dry, dry_html):
    summary = dry.summary()
    page = Page(dry_html)
    peaks = page.table("Peaks of forces")
    assert peaks["columns"] == ["channel", "unit", "peak |value|", "time [s]"]
    assert len(peaks["rows"]) == len(summary["peaks"]) > 10
    for name, unit, peak, at in peaks["rows"]:
        assert unit == dry.unit(name)
        assert float(peak) == pytest.approx(summary["peaks"][name], rel=1e-5)  # six significant digits
        assert float(at) == pytest.approx(summary["peak_times"][name], rel=1e-5, abs=1e-12)
    joint = page.table("Clearance joints")
    row = dict(zip(joint["columns"], joint["rows"][0]))
    expected = summary["clearance_joints"]["B"]
    assert row["clearance joint"] == "B"
    assert int(row["impacts"]) == expected["impacts"] > 0
    assert float(row["contact_fraction [-]"]) == pytest.approx(expected["contact_fraction"], rel=1e-5)
    assert float(row["max_penetration [mm]"]) == pytest.approx(expected["max_penetration"] * 1e3, rel=1e-5)


def test_run_report_states_the_options_and_statistics(dry, dry_html):
    page = Page(dry_html)
    options = page.rows_by_first_cell("Options of the run")
    assert options["method"] == ["dopri5", ""]
    assert float(options["rtol"][0]) == dry.options["rtol"]
    statistics = page.rows_by_first_cell("Integrator statistics")
    assert int(statistics["accepted_steps"][0]) == dry.statistics["accepted_steps"]
    run = page.rows_by_first_cell("The run")
    assert run["status"] == ["completed", ""]
    assert run["saved samples"] == [str(len(dry)), ""]


# plots ----------------------------------------------------------------------

def test_run_report_has_one_plot_div_per_plot_and_plotly_js_once(dry, dry_html):
    plots = plots_of(run_sections(dry, animation=False))
    titles = [p.figure.layout.title.text for p in plots]
    assert "Journal-centre orbit in B (eccentricity, mm)" in titles
    assert "Contact in B" in titles and "Joint reactions and driver efforts" in titles
    page = Page(dry_html)
    divs = [a["id"] for tag, a in page.elements if tag == "div" and "plotly-graph-div" in a.get("class", "")]
    assert divs == [f"plot-{k}" for k in range(1, len(plots) + 1)]
    assert dry_html.count("plotly.js v") == 1
    assert sum(len(script) > 1_000_000 for script in page.scripts) == 1  # the library, inlined once
    for title in titles:
        assert f'"text":"{title}"' in dry_html.replace(": ", ":")


def test_every_axis_of_a_run_report_states_its_unit(dry):
    for plot in plots_of(run_sections(dry, animation=False)):
        layout = plot.figure.layout
        axes = [layout[k] for k in layout if k.startswith(("xaxis", "yaxis"))]
        titled = [a.title.text for a in axes if a.title.text]
        assert titled, plot.figure.layout.title.text
        for text in titled:
            assert re.search(r"\[[^\]]+\]$", text), text


def test_orbit_plot_draws_the_saved_eccentricity_in_mm_inside_the_clearance_circle(dry):
    plot = next(p for p in plots_of(run_sections(dry, animation=False)) if "orbit" in p.figure.layout.title.text)
    path, circle = plot.figure.data[0], plot.figure.data[1]
    np.testing.assert_allclose(path.x, dry["B.ex"] * 1e3)
    np.testing.assert_allclose(path.y, dry["B.ey"] * 1e3)
    np.testing.assert_allclose(np.hypot(circle.x, circle.y), 0.5)  # c = 0.5 mm
    assert "clearance c = 0.5 mm" == circle.name


def test_lubricated_run_report_has_film_plots_and_the_lubricant(lubricated, folder):
    sections = run_sections(lubricated, animation=False)
    film = next(p for p in plots_of(sections) if p.figure.layout.title.text == "Lubricant film in B")
    lines = [trace for trace in film.figure.data if trace.mode == "lines"]
    assert [trace.name for trace in lines] == ["B.film_min", "B.fh", "B.peak_pressure"]
    np.testing.assert_allclose(lines[0].y, lubricated["B.film_min"])
    # the thinnest film tracked at every accepted step is marked at its value and time
    joint = lubricated.summary()["clearance_joints"]["B"]
    peaks = [trace for trace in film.figure.data if trace.mode == "markers"]
    assert peaks[0].yaxis == "y" and peaks[0].y[0] == pytest.approx(joint["min_film"], rel=1e-12)
    assert peaks[0].y[0] <= lubricated["B.film_min"].min()
    axis_titles = [film.figure.layout[f"yaxis{k}"].title.text for k in ("", "2", "3")]
    assert axis_titles == ["B.film_min [m]", "B.fh [N]", "B.peak_pressure [Pa]"]
    html = write_report(lubricated, folder / "lubricated.html", animation=False).read_text(encoding="utf-8")
    joint = Page(html).rows_by_first_cell("Joint B (clearance_revolute)")
    assert joint["lubrication.viscosity"] == ["0.4", "Pa s"]  # 400 cP in the model file
    assert joint["lubrication.model"] == ["pinkus_sternlicht_long", ""]


def test_beam_run_report_lists_the_section_in_units_and_plots_end_nodes_and_gauge(folder):
    beam_run = simulate("spin_up_beam", 1e-2, folder)
    html = write_report(beam_run, folder / "beam.html", animation=False).read_text(encoding="utf-8")
    beam = Page(html).rows_by_first_cell("Beam beam")
    # examples/spin_up_beam.toml: a 10 m beam, bending_stiffness = "1.4e4 N m^2", mass_per_length = "1.2 kg/m"
    assert beam["end"] == ["(10000, 0)", "mm"]
    assert beam["section.bending_stiffness"] == ["14000", "N m^2"]
    assert beam["section.mass_per_length"] == ["1.2", "kg/m"]
    plots = {p.figure.layout.title.text: p for p in plots_of(run_sections(beam_run, animation=False))}
    ends = [t for t in plots["Beam beam"].figure.data if t.mode == "lines"]
    assert [t.name for t in ends][:2] == ["beam.node0_x", "beam.node0_y"]
    np.testing.assert_allclose(ends[2].y, beam_run["beam.node8_x"])  # 4 quadratic elements: nodes 0-8
    gauge = [t.name for t in plots["Strain gauge root"].figure.data if t.mode == "lines"]
    assert gauge == ["root.axial_strain", "root.axial_force", "root.bending_moment"]


def test_long_runs_are_thinned_keeping_every_span_extremes():
    rng = np.random.default_rng(1)
    n = 200_001
    values = rng.normal(size=n)
    values[123_457] = 50.0  # one sharp peak between two others
    values[77_777] = -40.0
    rows = keep_indices([values])
    assert rows.size <= MAX_POINTS
    assert rows[0] == 0 and rows[-1] == n - 1 and np.all(np.diff(rows) > 0)
    assert 123_457 in rows and 77_777 in rows
    # every span of n / SPANS samples keeps its own extremes
    edges = np.linspace(0, n, SPANS + 1).astype(int)
    for start, stop in zip(edges[:-1:97], edges[1::97]):
        kept = values[rows[(rows >= start) & (rows < stop)]]
        assert kept.max() == values[start:stop].max() and kept.min() == values[start:stop].min()
    assert np.array_equal(keep_indices([values[:MAX_POINTS]]), np.arange(MAX_POINTS))


def test_a_long_run_is_drawn_thinned_and_its_caption_says_how():
    t = np.linspace(0.0, 1.0, 50_001)
    signal = np.sin(40 * t)
    signal[31_416] = 7.0
    long_run = Results(t, ["body.ax"], ["m/s^2"], [""], signal[None, :], {}, {}, spec={"name": "long"})
    figure, was_thinned = history_figure(long_run, "long", [["body.ax"]])
    trace = figure.data[0]
    assert was_thinned and len(trace.y) <= MAX_POINTS
    assert max(trace.y) == 7.0 and min(trace.y) == pytest.approx(-1.0, abs=1e-3)
    from jointplay.report.plots import history_plot

    plot = history_plot(long_run, "long", [["body.ax"]], "A long run.")
    assert f"at most {MAX_POINTS} points per trace" in plot.caption and "true height" in plot.caption


# offline ----------------------------------------------------------------------

def test_run_report_fetches_nothing_from_a_network(dry_html):
    assert not re.search(r"<script[^>]*\ssrc\s*=", dry_html, re.IGNORECASE)
    assert not re.search(r"<link[^>]*href\s*=", dry_html, re.IGNORECASE)
    assert "@import" not in dry_html
    assert not re.search(r"url\(\s*['\"]?https?:", dry_html, re.IGNORECASE)
    at = dry_html.index("plotly.js v")
    start, end = dry_html.rindex("<script", 0, at), dry_html.index("</script>", at)
    rest = dry_html[:start] + dry_html[end:]  # the page and its plots, the plotly.js library left out
    assert re.findall(r"(?:https?:)?//[a-z0-9.-]+\.[a-z]{2,}/", rest, re.IGNORECASE) == []
    assert "mathjax.js" not in rest.lower()
    for tag, attributes in Page(dry_html).elements:  # real elements; text inside scripts is not an element
        for key in ("src", "href", "data", "poster"):
            value = attributes.get(key)
            assert value is None or value.startswith(("#", "data:")), (tag, key, value)


# animation --------------------------------------------------------------------

def tiny_mp4(path: Path) -> bytes:
    """A real MP4 of eight 64 x 48 frames, encoded by imageio-ffmpeg's own encoder."""
    import imageio_ffmpeg

    writer = imageio_ffmpeg.write_frames(str(path), (64, 48), fps=8, codec="libx264", pix_fmt_out="yuv420p",
                                         macro_block_size=16)
    writer.send(None)
    for k in range(8):
        frame = np.zeros((48, 64, 3), dtype=np.uint8)
        frame[:, 8 * k: 8 * k + 8] = 255
        writer.send(frame.tobytes())
    writer.close()
    return path.read_bytes()


@pytest.fixture
def fake_animation(monkeypatch, tmp_path):
    """``jointplay.animation.video_bytes`` replaced by a function recording its calls and returning a real MP4."""
    data = tiny_mp4(tmp_path / "tiny.mp4")
    calls = []

    def video_bytes(results, *, mime="video/mp4", **options):
        calls.append((results, mime, options))
        return data

    try:
        import jointplay.animation as animation
        monkeypatch.setattr(animation, "video_bytes", video_bytes)
    except ImportError:
        module = types.ModuleType("jointplay.animation")
        module.video_bytes = video_bytes
        monkeypatch.setitem(sys.modules, "jointplay.animation", module)
    return data, calls


def test_run_report_embeds_the_animation_as_a_data_uri_video(dry, tmp_path, fake_animation):
    data, calls = fake_animation
    html = dry.report(tmp_path / "with_video.html").read_text(encoding="utf-8")
    assert len(calls) == 1 and calls[0][0] is dry and calls[0][1] == "video/mp4"
    page = Page(html)
    videos = [a for tag, a in page.elements if tag == "video"]
    assert len(videos) == 1 and videos[0]["id"] == "video-1" and "jp-video" in videos[0]["class"]
    assert {"controls", "loop", "muted", "playsinline"} <= set(videos[0])
    source = next(a for tag, a in page.elements if tag == "source")
    assert source["type"] == "video/mp4"
    prefix = "data:video/mp4;base64,"
    assert source["src"].startswith(prefix) and base64.b64decode(source["src"][len(prefix):]) == data
    assert data[4:8] == b"ftyp"  # an MP4 container


def test_animation_false_leaves_the_section_out(dry, dry_html, fake_animation):
    _, calls = fake_animation
    assert "<video" not in dry_html
    assert "Animation" not in [s.title for s in run_sections(dry, animation=False)]
    assert calls == []


# comparison -------------------------------------------------------------------

def test_comparison_has_one_column_per_run_and_overlaid_traces(dry, ideal, folder, fake_animation):
    html = write_report([dry.path, ideal.path], folder / "compare.html").read_text(encoding="utf-8")
    page = Page(html)
    videos = [a for tag, a in page.elements if tag == "video"]
    assert [v["id"] for v in videos] == ["video-1", "video-2"]  # each run's animation, side by side
    assert 'class="jp-section jp-side-by-side"' in html
    labels = ["flores_slider_crank_dry.nc", "flores_slider_crank_ideal.nc"]
    runs = page.table("The runs compared")
    assert runs["columns"] == ["", "unit", *labels]
    assert all(len(row) == 4 for row in runs["rows"])
    assert dict((r[0], r[2:]) for r in runs["rows"])["saved samples"] == [str(len(dry)), str(len(ideal))]
    summaries = page.rows_by_first_cell("Each run's summary")
    cells = summaries["peak |slider.ax|"]
    assert cells[0] == "m/s^2"
    assert float(cells[1]) == pytest.approx(dry.summary()["peaks"]["slider.ax"], rel=1e-5)
    assert float(cells[2]) == pytest.approx(ideal.summary()["peaks"]["slider.ax"], rel=1e-5)
    differences = page.rows_by_first_cell("Model parameters that differ")
    assert differences["joints.B.type"] == ["clearance_revolute", "revolute"]
    assert differences["joints.B.clearance"] == ["0.0005", "–"]  # SI units, as the results files hold them
    assert differences["joints.B.max_penetration"] == ["none", "–"]  # unset in one, not a key of the other
    assert "bodies.rod.mass" not in differences  # the same in both


def test_comparison_overlays_each_channel_with_a_trace_per_run(dry, ideal):
    from jointplay.report.compare import compare_sections

    plots = plots_of(compare_sections([dry, ideal]))
    assert plots
    slider = next(p for p in plots if p.figure.layout.title.text == "slider.ax, each run")
    assert [t.name for t in slider.figure.data] == ["flores_slider_crank_dry.nc", "flores_slider_crank_ideal.nc"]
    np.testing.assert_allclose(slider.figure.data[1].y, ideal["slider.ax"])
    assert slider.figure.layout.yaxis.title.text == "slider.ax [m/s^2]"


def test_a_comparisons_animations_share_the_clearance_and_force_scales(dry, lubricated, fake_animation):
    from jointplay.animation.scene import Scene
    from jointplay.report.compare import compare_sections

    _, calls = fake_animation
    compare_sections([dry, lubricated], animation={"fps": 5})
    own = [Scene(r, fps=5).scales for r in (dry, lubricated)]
    assert [c[0] for c in calls] == [dry, lubricated]
    for _, _, options in calls:
        # the smaller of the two runs' own scales: both journals and both arrows fit
        assert options["clearance_scale"] == min(s["clearance"] for s in own)
        assert options["force_scale"] == min(s["force"] for s in own)
        assert options["fps"] == 5 and options.get("deformation_scale") is None
    assert own[0]["force"] != own[1]["force"]  # (the dry joint's impacts are far larger than the film's force)


# studies and bad input ------------------------------------------------------------

def test_a_study_folder_is_reported_by_the_study_sections(tmp_path, monkeypatch):
    study = tmp_path / "study"
    study.mkdir()
    (study / "study.json").write_text("{}")
    seen = []

    def study_sections(folder):
        seen.append(Path(folder))
        return "Study of a slider-crank", [Section("Design", [Text("the cases")])]

    module = types.ModuleType("jointplay.report.study")
    module.study_sections = study_sections
    monkeypatch.setitem(sys.modules, "jointplay.report.study", module)
    html = write_report(study, study / "report.html").read_text(encoding="utf-8")
    assert seen == [study]
    assert "<title>Study of a slider-crank</title>" in html and "the cases" in html


def located(call) -> list[tuple[str, str]]:
    with pytest.raises(ModelError) as caught:
        call()
    return [(p.location, p.message) for p in caught.value.problems]


def test_bad_input_raises_located_model_errors(dry, tmp_path):
    missing = tmp_path / "missing.nc"
    assert located(lambda: write_report(missing, tmp_path / "r.html")) == [
        (str(missing), "no such results file or study folder")]
    model_file = EXAMPLES / "flores_slider_crank_dry.toml"
    [(where, message)] = located(lambda: write_report(model_file, tmp_path / "r.html"))
    assert where == str(model_file) and "is not a jointplay results file" in message
    plain = tmp_path / "plain"
    plain.mkdir()
    [(where, message)] = located(lambda: write_report(plain, tmp_path / "r.html"))
    assert where == str(plain) and "without study.json" in message
    [(where, message)] = located(lambda: write_report(dry, tmp_path / "r.pdf"))
    assert where == str(tmp_path / "r.pdf") and "must end in .html" in message
    nowhere = tmp_path / "no_such_folder" / "r.html"
    assert located(lambda: write_report(dry, nowhere)) == [
        (str(nowhere), f"the folder {nowhere.parent} does not exist")]


# the command ------------------------------------------------------------------------

def invoke(*args: str):
    return CliRunner().invoke(app, list(args))


def test_cli_writes_report_html_next_to_the_results_file(dry):
    result = invoke("report", str(dry.path), "--no-animation", "--title", "Dry joint, 3 ms")
    assert result.exit_code == 0, result.output
    written = dry.path.parent / "report.html"
    assert f"wrote {written}" in result.stdout
    assert "reading" in result.stderr and "writing" in result.stderr
    assert "<title>Dry joint, 3 ms</title>" in written.read_text(encoding="utf-8")


@pytest.mark.parametrize("arguments, message", [
    (["missing.nc"], "error: missing.nc: no such results file or study folder"),
    ([str(EXAMPLES / "flores_slider_crank_dry.toml")], "is not a jointplay results file"),
    ([str(EXAMPLES), "-o", "out.html"], "without study.json: not a study folder"),
])
def test_cli_bad_input_is_one_line_with_exit_2(arguments, message, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    result = invoke("report", *arguments)
    assert result.exit_code == 2
    assert message in result.stderr
    assert len(result.stderr.strip().splitlines()) == 1 + ("reading" in result.stderr)
    assert "Traceback" not in result.output


def test_cli_refuses_a_bad_video_option_by_its_name_and_writes_nothing(dry, tmp_path):
    out = tmp_path / "long.html"
    result = invoke("report", str(dry.path), "-o", str(out), "--video-fps", "1000", "--video-duration", "1 h")
    assert result.exit_code == 2 and "Traceback" not in result.output
    assert "error: --video-duration: 1000 frames a second for 3600 s make 3600000 frames" in result.stderr
    assert not out.exists()


def test_cli_refuses_an_output_that_is_not_html(dry):
    result = invoke("report", str(dry.path), "-o", str(dry.path.with_suffix(".pdf")), "--no-animation")
    assert result.exit_code == 2
    assert result.stderr.strip() == f"error: {dry.path.with_suffix('.pdf')}: a report is an HTML file: its name " \
                                    "must end in .html"


def test_report_package_and_command_help_load_no_heavy_library():
    import subprocess

    heavy = ("plotly", "jinja2", "matplotlib", "xarray", "scipy", "imageio_ffmpeg", "PIL")
    probe = ("import sys\nsys.argv = ['jointplay', 'report', '--help']\nimport jointplay.report\n"
             "from jointplay.cli import main\ntry:\n    main()\nexcept SystemExit:\n    pass\n"
             f"print([m for m in {heavy!r} if m in sys.modules], file=sys.stderr)")
    result = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, timeout=120)
    assert "Usage: jointplay report" in result.stdout
    assert result.stderr.strip().splitlines()[-1] == "[]"
