"""PNG screenshots of viewer pages in headless Chromium."""

from __future__ import annotations

import os
import tempfile
from pathlib import Path

from robotmodel.viewer._browser import Browser

__all__ = ["screenshot", "screenshot_html"]

# The page sets window.robotmodel.synced once the whole scene is in and drawn.
READY = "window.robotmodel && window.robotmodel.synced > 0 && window.robotmodel.renders > 0"


def screenshot(url: str, *, width: int = 1280, height: int = 800, timeout: float = 60.0) -> bytes:
    """Load ``url`` (a viewer page, live or static), wait until the scene is drawn, return a PNG."""
    with Browser(width=width, height=height, timeout=timeout) as browser:
        browser.navigate(url)
        browser.wait_for(READY)
        # One more animation frame, so what was drawn is also presented.
        browser.evaluate("new Promise(r => requestAnimationFrame(() => requestAnimationFrame(r)))")
        return browser.screenshot()


def screenshot_html(html: str, *, width: int = 1280, height: int = 800, timeout: float = 60.0) -> bytes:
    """Render a static page's HTML text from a temporary ``file://`` and return a PNG."""
    fd, name = tempfile.mkstemp(prefix="robotmodel-", suffix=".html")
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as f:
            f.write(html)
        return screenshot(Path(name).as_uri(), width=width, height=height, timeout=timeout)
    finally:
        Path(name).unlink(missing_ok=True)
