"""The headless-browser harness of the report tests, checked on a page made by hand: one plotly figure with
plotly.js inline, an H.264 MP4 and a VP9 WebM video as base64 data URIs. The browser is the system's
Chromium, offline, with every non-local request aborted and recorded (tests/browser.py).

The videos show a yellow square moving 2 px to the right per frame on a dark ground, so a decoded frame
is checked pixel by pixel against the frame that was encoded at that time."""

from __future__ import annotations

import base64

import numpy as np
import pytest
from browser import report_browser  # noqa: F401 (the fixture)

#: Size of the test videos [px] (multiples of 16, as H.264 macroblocks want) and their frame rate [1/s].
WIDTH, HEIGHT, FPS, FRAMES = 64, 48, 25, 25
GROUND, SQUARE = (30, 30, 30), (255, 200, 0)
#: A flat colour decoded from yuv420p at the encoders' default quality is within this of the encoded one (0-255).
COLOUR_TOLERANCE = 16


def frame(k: int) -> np.ndarray:
    """Frame k: the dark ground with a 16 x 20 px yellow square whose left edge is at x = 2k."""
    image = np.empty((HEIGHT, WIDTH, 3), np.uint8)
    image[:] = GROUND
    image[10:30, 2 * k:2 * k + 16] = SQUARE
    return image


def encode(path, codec: str, output_params: list[str]) -> bytes:
    """The test frames encoded by the ffmpeg that imageio-ffmpeg ships (pixel format yuv420p)."""
    import imageio_ffmpeg

    writer = imageio_ffmpeg.write_frames(str(path), (WIDTH, HEIGHT), fps=FPS, codec=codec, pix_fmt_out="yuv420p",
                                         output_params=output_params, macro_block_size=16)
    writer.send(None)
    for k in range(FRAMES):
        writer.send(frame(k))
    writer.close()
    return path.read_bytes()


@pytest.fixture(scope="module")
def page_file(tmp_path_factory):
    """A self-contained page: a plotly figure (plotly.js inline) and the two videos as data URIs."""
    import plotly.graph_objects as go

    folder = tmp_path_factory.mktemp("page")
    mp4 = encode(folder / "square.mp4", "libx264", ["-movflags", "+faststart"])
    webm = encode(folder / "square.webm", "libvpx-vp9", ["-crf", "32", "-b:v", "0"])
    figure = go.Figure(go.Scatter(x=[0.0, 0.01, 0.02], y=[0.0, 1.5, 0.5], mode="lines"))
    figure.update_layout(xaxis_title="time [s]", yaxis_title="force [N]")
    videos = "".join(f'<video id="{name}" src="data:{mime};base64,{base64.b64encode(data).decode()}" muted '
                     'playsinline></video>' for name, mime, data in (("mp4", "video/mp4", mp4),
                                                                     ("webm", "video/webm", webm)))
    html = (f"<!doctype html><html><head><meta charset='utf-8'><title>page</title></head><body>"
            f"{figure.to_html(include_plotlyjs=True, full_html=False)}{videos}</body></html>")
    path = folder / "page.html"
    path.write_text(html, encoding="utf-8")
    return path


@pytest.fixture(scope="module")
def opened(report_browser, page_file):  # noqa: F811 (the fixture imported above)
    return report_browser.open_report(page_file)


def test_the_plot_renders_with_its_axis_titles(opened):
    assert opened.plots == 1
    titles = opened.page.eval_on_selector_all(".plotly-graph-div svg.main-svg .g-xtitle, "
                                              ".plotly-graph-div svg.main-svg .g-ytitle",
                                              "nodes => nodes.map(n => n.textContent)")
    assert titles == ["time [s]", "force [N]"]
    # the line is drawn: a path with a non-empty outline
    assert opened.page.eval_on_selector(".plotly-graph-div .scatterlayer path.js-line",
                                        "p => p.getAttribute('d').length") > 10


@pytest.mark.parametrize("index, selector", [(0, "#mp4"), (1, "#webm")], ids=["h264-mp4", "vp9-webm"])
def test_the_video_plays_and_shows_the_encoded_frames(report_browser, opened, index, selector):  # noqa: F811
    state = opened.videos[index]
    assert state["error"] == 0 and state["readyState"] >= 2
    assert (state["videoWidth"], state["videoHeight"]) == (WIDTH, HEIGHT)
    assert "playError" not in state and state["end"] > state["start"] + 0.1  # played for 0.4 s
    # at t = 0.5 s, frame 12: the square spans x = 24 .. 39, y = 10 .. 29
    time = (12 + 0.5) / FPS
    inside = report_browser.video_pixel(opened.page, selector, time, 32, 20)
    outside = report_browser.video_pixel(opened.page, selector, time, 8, 20)
    np.testing.assert_allclose(inside[:3], SQUARE, atol=COLOUR_TOLERANCE)
    np.testing.assert_allclose(outside[:3], GROUND, atol=COLOUR_TOLERANCE)


def test_nothing_was_fetched_and_nothing_failed(opened):
    assert opened.requests == []
    assert opened.errors == []


def test_a_request_to_the_network_is_aborted_and_recorded(report_browser, tmp_path):  # noqa: F811
    """The harness can fail a report that loads anything from a network."""
    path = tmp_path / "remote.html"
    path.write_text("<!doctype html><html><body><img src='https://cdn.plot.ly/logo.png'></body></html>")
    opened = report_browser.open_report(path)
    assert opened.requests == ["https://cdn.plot.ly/logo.png"]
    assert any("ERR_INTERNET_DISCONNECTED" in e or "Failed to load resource" in e for e in opened.errors)


def test_the_study_reports_figures_render_offline(report_browser, tmp_path):  # noqa: F811
    """Every figure of a study's report (subplots, a contour, bars) drawn in the browser with its axis titles."""
    from jointplay.report.blocks import Plot
    from jointplay.report.study import study_sections
    from jointplay.study import load_study

    from test_report_study import DATA

    load_study(DATA / "throw_study.toml").run(tmp_path / "study")
    figures = [b.figure for s in study_sections(tmp_path / "study")[1] for b in s.blocks if isinstance(b, Plot)]
    divs = "".join(f.to_html(include_plotlyjs=k == 0, full_html=False) for k, f in enumerate(figures))
    path = tmp_path / "figures.html"
    path.write_text(f"<!doctype html><html><head><meta charset='utf-8'></head><body>{divs}</body></html>",
                    encoding="utf-8")
    opened = report_browser.open_report(path)
    assert opened.plots == len(figures) == 6 and opened.errors == [] and opened.requests == []
    titles = opened.page.eval_on_selector_all("svg.main-svg .g-xtitle, svg.main-svg .g-x2title, svg.main-svg "
                                              ".g-ytitle", "nodes => nodes.map(n => n.textContent)")
    assert {"speed [m/s]", "g [m/s^2]", "final_height [m]", "height [m]"} <= set(titles)
    colorbar = opened.page.eval_on_selector_all(".colorbar .cbtitle", "nodes => nodes.map(n => n.textContent)")
    assert colorbar == ["height [m]", "final_height [m]"]


# the reports jointplay writes -----------------------------------------------------------------------------

#: The embedded animations of these tests: small and short, so that the tests stay fast.
SMALL_ANIMATION = {"fps": 10, "duration": 1.0, "size": (640, 360)}


@pytest.fixture(scope="module")
def written_reports(tmp_path_factory):
    """A run's report and a comparison's (dry and ideal Flores slider-crank, 5 ms, their real animations) and a
    study's report (the suite's small throw study), as `write_report` writes them."""
    from jointplay.report import write_report
    from jointplay.study import load_study

    from test_report import simulate
    from test_report_study import DATA

    folder = tmp_path_factory.mktemp("written")
    dry, ideal = (simulate(name, 5e-3, folder) for name in ("flores_slider_crank_dry", "flores_slider_crank_ideal"))
    load_study(DATA / "throw_study.toml").run(folder / "study")
    return {"run": write_report(dry.path, folder / "run.html", animation=SMALL_ANIMATION),
            "comparison": write_report([dry.path, ideal.path], folder / "comparison.html", animation=SMALL_ANIMATION),
            "study": write_report(folder / "study", folder / "study.html")}


#: Videos each report embeds: the run's animation, one per run compared, none in a study's report.
VIDEOS = {"run": 1, "comparison": 2, "study": 0}


@pytest.mark.parametrize("kind", list(VIDEOS))
def test_a_written_report_draws_every_plot_and_plays_its_videos_offline(report_browser, written_reports, kind):  # noqa: F811
    path = written_reports[kind]
    opened = report_browser.open_report(path)
    html = path.read_text(encoding="utf-8")
    assert opened.plots == html.count('class="plotly-graph-div"') > 0  # (the browser waited for each to draw)
    drawn = opened.page.eval_on_selector_all(".plotly-graph-div", "divs => divs.map(d => d.querySelectorAll("
                                             "'.scatterlayer .trace path, .barlayer path, .contourlayer path, "
                                             ".heatmaplayer image').length)")
    assert all(count > 0 for count in drawn)  # every plot has drawn marks, not only its axes
    assert len(opened.videos) == VIDEOS[kind]
    for state in opened.videos:
        assert state["error"] == 0 and state["readyState"] >= 2
        assert (state["videoWidth"], state["videoHeight"]) == SMALL_ANIMATION["size"]
        assert "playError" not in state and state["end"] > state["start"] + 0.1  # it played
    assert opened.requests == [] and opened.errors == []
