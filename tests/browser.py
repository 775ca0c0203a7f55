"""A headless browser for the tests of reports: the system's Chromium driven by playwright, networking off.

The pytest fixture :func:`report_browser` (import it into a test file) finds Chromium
(``/usr/bin/chromium`` or ``chromium-headless-shell``); when there is none and the tests run as root
with apt-get, it installs Debian's ``chromium`` first; otherwise the tests that use it are skipped with
the reason. The browser context is offline and every request to a URL that is not ``file:``,
``data:`` or ``blob:`` is aborted and recorded in :attr:`ReportBrowser.requests`, so a test can assert
that a report fetched nothing.

:meth:`ReportBrowser.open_report` loads a report, waits until every plotly figure has drawn its SVG
and every ``<video>`` has decoded a frame, plays the videos muted, and records console errors and
uncaught page errors in :attr:`OpenedReport.errors`.
"""

from __future__ import annotations

import os
import shutil
import subprocess
from dataclasses import dataclass, field
from pathlib import Path

import pytest

#: Where Debian puts Chromium's launchers, in the order tried.
CHROMIUM_CANDIDATES = ("/usr/bin/chromium", "/usr/bin/chromium-headless-shell")
#: Longest wait for apt-get update + install [s].
INSTALL_TIMEOUT = 600
#: Longest wait for a report to render its figures and videos [ms].
RENDER_TIMEOUT_MS = 15_000
#: How long a video plays before its clock is read again [ms].
PLAY_MS = 400
#: URL schemes a self-contained report may load.
LOCAL_SCHEMES = ("file:", "data:", "blob:", "about:")
#: Chromium switches for a container without a sandbox or a GPU.
CHROMIUM_ARGS = ["--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
                 "--autoplay-policy=no-user-gesture-required"]


def find_chromium() -> str | None:
    """The path of a Chromium executable on this machine, or None."""
    for path in CHROMIUM_CANDIDATES:
        if os.access(path, os.X_OK):
            return path
    for name in ("chromium", "chromium-headless-shell"):
        found = shutil.which(name)
        if found:
            return found
    return None


def install_chromium() -> str:
    """Installs Debian's chromium with apt-get when running as root; '' on success, else why not."""
    if os.geteuid() != 0 or shutil.which("apt-get") is None:
        return "no Chromium at " + " or ".join(CHROMIUM_CANDIDATES) + " and not root with apt-get to install it"
    env = {**os.environ, "DEBIAN_FRONTEND": "noninteractive"}
    for command in (["apt-get", "update"], ["apt-get", "install", "-y", "--no-install-recommends", "chromium"]):
        try:
            done = subprocess.run(command, capture_output=True, text=True, timeout=INSTALL_TIMEOUT, env=env)
        except subprocess.TimeoutExpired:
            return f"{' '.join(command)} took longer than {INSTALL_TIMEOUT} s"
        if done.returncode != 0:
            return f"{' '.join(command)} failed: {done.stderr.strip().splitlines()[-1:]}"
    return ""


def chromium_or_skip() -> str:
    """A Chromium executable, installed if it can be; skips the calling test with the reason otherwise."""
    path = find_chromium()
    if path is None:
        reason = install_chromium()
        path = find_chromium()
        if path is None:
            pytest.skip(f"no headless browser for the report tests: {reason or 'chromium not found after install'}")
    try:
        import playwright.sync_api  # noqa: F401
    except ImportError:
        pytest.skip("no headless browser for the report tests: the playwright package is not installed")
    return path


@dataclass
class OpenedReport:
    """A report loaded in the browser: the page, its console errors and uncaught errors, and what each
    ``<video>`` reported (readyState, videoWidth, videoHeight, currentTime before and after playing [s],
    error code), the number of plotly figures, and the non-local requests it tried (all aborted)."""

    page: object
    errors: list[str]
    requests: list[str] = field(default_factory=list)
    videos: list[dict] = field(default_factory=list)
    plots: int = 0


class ReportBrowser:
    """One headless Chromium with an offline context that aborts and records every non-local request."""

    def __init__(self, executable: str):
        from playwright.sync_api import sync_playwright

        self.executable = executable
        self._playwright = sync_playwright().start()
        self._browser = self._playwright.chromium.launch(executable_path=executable, args=CHROMIUM_ARGS,
                                                         headless=True)
        self.context = self._browser.new_context(offline=True)
        #: Every request to a URL outside LOCAL_SCHEMES that a page tried (all were aborted).
        self.requests: list[str] = []
        self.context.route("**/*", self._route)

    def _route(self, route) -> None:
        url = route.request.url
        if url.startswith(LOCAL_SCHEMES):
            route.continue_()
        else:
            self.requests.append(url)
            route.abort("internetdisconnected")

    def open_report(self, path: str | Path) -> OpenedReport:
        """Loads the HTML file at ``path`` and waits until its figures are drawn and its videos play."""
        page = self.context.new_page()
        errors: list[str] = []
        before = len(self.requests)
        page.on("console", lambda message: errors.append(message.text) if message.type == "error" else None)
        page.on("pageerror", lambda error: errors.append(str(error)))
        page.goto(Path(path).resolve().as_uri(), wait_until="load")
        plots = page.evaluate("document.querySelectorAll('.plotly-graph-div').length")
        page.wait_for_function("""() => [...document.querySelectorAll('.plotly-graph-div')]
                                     .every(div => div.querySelector('svg.main-svg'))""", timeout=RENDER_TIMEOUT_MS)
        videos = self._play_videos(page)
        return OpenedReport(page, errors, self.requests[before:], videos, plots)

    @staticmethod
    def _play_videos(page) -> list[dict]:
        """Each video's state after it has decoded a frame and played muted for PLAY_MS."""
        page.wait_for_function("""() => [...document.querySelectorAll('video')]
                                     .every(v => v.error || (v.readyState >= 2 && v.videoWidth > 0))""",
                               timeout=RENDER_TIMEOUT_MS)
        return page.evaluate("""async (ms) => {
            const out = [];
            for (const v of document.querySelectorAll('video')) {
                const state = {readyState: v.readyState, videoWidth: v.videoWidth, videoHeight: v.videoHeight,
                               error: v.error ? v.error.code : 0, start: v.currentTime};
                if (!v.error) {
                    v.muted = true;
                    v.loop = true;
                    try { await v.play(); } catch (e) { state.playError = String(e); }
                    await new Promise(r => setTimeout(r, ms));
                }
                state.end = v.currentTime;
                out.push(state);
            }
            return out;
        }""", PLAY_MS)

    @staticmethod
    def video_pixel(page, selector: str, time: float, x: int, y: int) -> list[int]:
        """The RGBA colour of pixel (x, y) of the frame the video ``selector`` shows at ``time`` [s], drawn
        through a canvas: what the browser decoded, not what the file claims."""
        return page.evaluate("""async ([selector, time, x, y]) => {
            const v = document.querySelector(selector);
            v.pause();
            await new Promise(r => { v.addEventListener('seeked', r, {once: true}); v.currentTime = time; });
            const canvas = document.createElement('canvas');
            canvas.width = v.videoWidth; canvas.height = v.videoHeight;
            const context = canvas.getContext('2d');
            context.drawImage(v, 0, 0);
            return [...context.getImageData(x, y, 1, 1).data];
        }""", [selector, time, x, y])

    def close(self) -> None:
        self.context.close()
        self._browser.close()
        self._playwright.stop()


@pytest.fixture(scope="module")
def report_browser():
    """A :class:`ReportBrowser` for the tests of a module (skips them when no browser can be had)."""
    browser = ReportBrowser(chromium_or_skip())
    try:
        yield browser
    finally:
        browser.close()
