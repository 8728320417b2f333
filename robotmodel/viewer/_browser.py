"""Headless Chromium driven over the DevTools protocol (for screenshots and browser tests).

Chromium is started with a fresh profile and ``--remote-debugging-port=0``; it writes
the port it chose to ``DevToolsActivePort`` in the profile, and we talk to it over
a websocket with tornado's client (tornado ships with meshcat, so no new dependency).
Software WebGL (SwiftShader) draws without a GPU or a display.
"""

from __future__ import annotations

import asyncio
import base64
import contextlib
import json
import os
import shutil
import signal
import subprocess
import tempfile
import time
from pathlib import Path
from typing import Any

from robotmodel.errors import ViewerError

__all__ = ["Browser", "find_chromium"]

_CANDIDATES = ("chromium", "chromium-browser", "google-chrome", "google-chrome-stable", "chrome")
FLAGS = (
    "--headless", "--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
    "--disable-background-networking", "--disable-component-update", "--disable-sync", "--no-first-run",
    "--disable-dev-shm-usage", "--hide-scrollbars", "--mute-audio",
)


def find_chromium() -> str | None:
    """Path of a Chromium/Chrome binary: ``$ROBOTMODEL_CHROMIUM``, else the first on ``PATH``."""
    explicit = os.environ.get("ROBOTMODEL_CHROMIUM")
    if explicit:
        return explicit
    for name in _CANDIDATES:
        found = shutil.which(name)
        if found:
            return found
    return None


class Browser:
    """One headless Chromium with one page; always :meth:`close` it (or use ``with``)."""

    def __init__(self, *, width: int = 1280, height: int = 800, timeout: float = 30.0) -> None:
        binary = find_chromium()
        if binary is None:
            raise ViewerError("no Chromium found (install chromium, or set ROBOTMODEL_CHROMIUM)")
        self.timeout = timeout
        if not os.access(binary, os.X_OK) or Path(binary).is_dir():
            raise ViewerError(f"cannot run Chromium at '{binary}' (install chromium, or set ROBOTMODEL_CHROMIUM)")
        self._profile = tempfile.mkdtemp(prefix="robotmodel-chromium-")
        self._loop = asyncio.new_event_loop()
        self._next_id = 0
        self._ws: Any = None
        self._session: str | None = None
        #: DevTools events received so far (method and params), e.g. ``Network.requestWillBeSent``.
        self.events: list[dict[str, Any]] = []
        try:
            self._proc = subprocess.Popen(
                [binary, *FLAGS, f"--user-data-dir={self._profile}", "--remote-debugging-address=127.0.0.1",
                 "--remote-debugging-port=0", f"--window-size={width},{height}", "about:blank"],
                stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                start_new_session=True,
            )
        except OSError as exc:
            shutil.rmtree(self._profile, ignore_errors=True)
            self._loop.close()
            raise ViewerError(f"cannot run Chromium at '{binary}': {exc.strerror or exc}") from None
        try:
            self._loop.run_until_complete(self._attach(width, height))
        except BaseException:
            self.close()
            raise

    @property
    def pid(self) -> int:
        """Process id of the browser."""
        return self._proc.pid

    def _port_file(self) -> tuple[int, str]:
        deadline = time.monotonic() + self.timeout
        marker = Path(self._profile) / "DevToolsActivePort"
        while time.monotonic() < deadline:
            if self._proc.poll() is not None:
                raise ViewerError(f"Chromium exited with status {self._proc.returncode} before it was ready")
            try:
                lines = marker.read_text().split()
            except OSError:
                lines = []
            if len(lines) >= 2:
                return int(lines[0]), lines[1]
            time.sleep(0.02)
        raise ViewerError(f"Chromium did not open its DevTools port within {self.timeout:g} s")

    async def _attach(self, width: int, height: int) -> None:
        from tornado.websocket import websocket_connect

        port, path = self._port_file()
        self._ws = await asyncio.wait_for(
            websocket_connect(f"ws://127.0.0.1:{port}{path}", max_message_size=1 << 30), self.timeout)
        targets = await self._call("Target.getTargets", session=False)
        page = next(t["targetId"] for t in targets["targetInfos"] if t["type"] == "page")
        attached = await self._call("Target.attachToTarget", {"targetId": page, "flatten": True}, session=False)
        self._session = attached["sessionId"]
        await self._call("Emulation.setDeviceMetricsOverride",
                         {"width": width, "height": height, "deviceScaleFactor": 1, "mobile": False})
        await self._call("Page.enable")
        await self._call("Runtime.enable")

    async def _call(self, method: str, params: dict[str, Any] | None = None, *, session: bool = True
                    ) -> dict[str, Any]:
        self._next_id += 1
        ident = self._next_id
        message: dict[str, Any] = {"id": ident, "method": method, "params": params or {}}
        if session and self._session:
            message["sessionId"] = self._session
        await self._ws.write_message(json.dumps(message))
        deadline = time.monotonic() + self.timeout
        while True:
            remaining = deadline - time.monotonic()
            if remaining <= 0:
                raise ViewerError(f"Chromium did not answer {method} within {self.timeout:g} s")
            try:
                raw = await asyncio.wait_for(self._ws.read_message(), remaining)
            except TimeoutError:
                raise ViewerError(f"Chromium did not answer {method} within {self.timeout:g} s") from None
            if raw is None:
                raise ViewerError("Chromium closed the DevTools connection")
            reply = json.loads(raw)
            if reply.get("id") != ident:
                if "method" in reply:
                    self.events.append({"method": reply["method"], "params": reply.get("params", {})})
                continue
            if "error" in reply:
                raise ViewerError(f"{method}: {reply['error'].get('message', reply['error'])}")
            result: dict[str, Any] = reply.get("result", {})
            return result

    def call(self, method: str, params: dict[str, Any] | None = None) -> dict[str, Any]:
        """Send one DevTools command to the page and return its result."""
        return self._loop.run_until_complete(self._call(method, params))

    def navigate(self, url: str) -> None:
        """Load ``url`` in the page."""
        self.call("Page.navigate", {"url": url})

    def evaluate(self, expression: str) -> Any:
        """Evaluate a JavaScript expression in the page (promises awaited) and return its value."""
        result = self.call("Runtime.evaluate", {"expression": expression, "returnByValue": True,
                                                "awaitPromise": True})
        if "exceptionDetails" in result:
            details = result["exceptionDetails"]
            text = details.get("exception", {}).get("description") or details.get("text")
            raise ViewerError(f"page script failed: {text}")
        return result.get("result", {}).get("value")

    def wait_for(self, expression: str, timeout: float | None = None, poll: float = 0.05) -> Any:
        """Poll ``expression`` until it is truthy; returns it, or raises after ``timeout`` seconds."""
        deadline = time.monotonic() + (self.timeout if timeout is None else timeout)
        while True:
            try:
                value = self.evaluate(expression)
            except ViewerError:
                value = None  # the page may be between navigations
            if value:
                return value
            if time.monotonic() > deadline:
                raise ViewerError(f"page condition not met within {timeout or self.timeout:g} s: {expression}")
            time.sleep(poll)

    def screenshot(self) -> bytes:
        """PNG of the page as it is drawn now."""
        data = self.call("Page.captureScreenshot", {"format": "png"})["data"]
        return base64.b64decode(data)

    def close(self) -> None:
        """Stop Chromium (its whole process group) and remove the profile."""
        try:
            if self._ws is not None and not self._loop.is_closed():
                # Inside the browser's own loop: tornado makes a future for the close frame, which
                # needs a current loop (the caller's thread may have none).
                self._loop.run_until_complete(self._close_ws())
        finally:
            self._ws = None
            if self._proc.poll() is None:
                try:
                    os.killpg(self._proc.pid, signal.SIGTERM)
                    self._proc.wait(timeout=5)
                except (ProcessLookupError, subprocess.TimeoutExpired):
                    with contextlib.suppress(ProcessLookupError):
                        os.killpg(self._proc.pid, signal.SIGKILL)
                    self._proc.wait()
            self._loop.close()
            shutil.rmtree(self._profile, ignore_errors=True)

    async def _close_ws(self) -> None:
        self._ws.close()

    def __enter__(self) -> Browser:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()
