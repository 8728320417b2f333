"""The loopback web server: the control page, meshcat's viewer script, and one websocket per page.

Runs tornado on its own thread and event loop, bound to 127.0.0.1 only (meshcat's own
server listens on every interface). The scene is kept here as meshcat commands, so a
page that connects late (or reconnects) is sent the whole scene, then live updates.
"""

from __future__ import annotations

import asyncio
import contextlib
import errno
import importlib.util
import json
import logging
import socket
import threading
from collections.abc import Callable, Iterable
from pathlib import Path
from typing import Any
from urllib.parse import urlsplit

import tornado.httpserver
import tornado.netutil
import tornado.web
import tornado.websocket
from tornado.ioloop import IOLoop

from robotmodel.errors import ViewerError

__all__ = ["ASSETS", "SceneStore", "ViewerServer", "check_port", "meshcat_dist"]

log = logging.getLogger("robotmodel.viewer")
ASSETS = Path(__file__).with_name("assets")
HOST = "127.0.0.1"
_LOOPBACK_NAMES = frozenset({"127.0.0.1", "localhost", "::1"})


def check_port(port: int | None) -> None:
    """:class:`ViewerError` for a port outside 0..65535 (the socket layer would wrap it around silently)."""
    if port is not None and not 0 <= port <= 65535:
        raise ViewerError(f"port {port} is out of range: a TCP port is 0 to 65535 (0: any free port)")


def meshcat_dist() -> Path:
    """Meshcat's bundled three.js viewer (``main.min.js``), found without importing meshcat."""
    spec = importlib.util.find_spec("meshcat")
    if spec is None or not spec.submodule_search_locations:
        raise ViewerError("the meshcat package is not installed")
    return Path(next(iter(spec.submodule_search_locations))) / "viewer" / "dist"


def _quiet(handler: tornado.web.RequestHandler) -> None:
    """Request logging off: a viewer's terminal is for its own messages."""


def _own_host(host: str, port: int) -> bool:
    """Whether a request's Host header names this server: a loopback name and its port."""
    try:
        parsed = urlsplit(f"http://{host}")
        return parsed.hostname in _LOOPBACK_NAMES and parsed.port == port
    except ValueError:
        return False


class _Asset(tornado.web.StaticFileHandler):
    def parse_url_path(self, url_path: str) -> str:
        # No file name holds a NUL; tornado would fail on it deep in os.path with a 500.
        if "\x00" in url_path:
            raise tornado.web.HTTPError(404)
        return super().parse_url_path(url_path)

    def set_extra_headers(self, path: str) -> None:
        # Cached but revalidated (ETag): a restarted viewer loads meshcat's 850 kB script,
        # already compiled, from the browser's cache; an upgraded one is fetched again.
        self.set_header("Cache-Control", "no-cache")


class SceneStore:
    """The current scene as meshcat commands: latest object, transform and property per path."""

    def __init__(self) -> None:
        self.objects: dict[str, bytes] = {}
        self.transforms: dict[str, bytes] = {}
        self.properties: dict[tuple[str, str], bytes] = {}

    def commands(self) -> list[bytes]:
        """Every command needed to rebuild the scene, objects first."""
        return [*self.objects.values(), *self.properties.values(), *self.transforms.values()]

    def drop(self, prefix: str) -> None:
        """Forget everything at or under ``prefix``."""
        def keep(path: str) -> bool:
            return path != prefix and not path.startswith(prefix + "/")
        self.objects = {k: v for k, v in self.objects.items() if keep(k)}
        self.transforms = {k: v for k, v in self.transforms.items() if keep(k)}
        self.properties = {k: v for k, v in self.properties.items() if keep(k[0])}


class _Socket(tornado.websocket.WebSocketHandler):
    def initialize(self, server: ViewerServer) -> None:
        self.server = server

    def prepare(self) -> None:
        # Checked here rather than only in check_origin: tornado (6.6) lets an Origin whose host
        # matches the Host header, or a Sec-Fetch-Site of same-origin, through without asking,
        # and a DNS-rebound name (evil.example resolving to 127.0.0.1) matches itself.
        origin = self.request.headers.get("Origin")
        if not _own_host(self.request.host, self.server.port) or (origin is not None
                                                                   and not self.check_origin(origin)):
            raise tornado.web.HTTPError(403)

    def check_origin(self, origin: str) -> bool:
        # Only this server's own page may drive it: http, a loopback name, this port, and the
        # origin the request was addressed to (no page on another loopback port gets in).
        try:
            parsed = urlsplit(origin)
            port = parsed.port
        except ValueError:
            return False
        return (parsed.scheme == "http" and parsed.hostname in _LOOPBACK_NAMES and port == self.server.port
                and parsed.netloc.lower() == self.request.host.lower())

    def open(self, *args: str, **kwargs: str) -> None:
        self.set_nodelay(True)
        self.server._clients.add(self)
        self.server._greet(self)

    def on_message(self, message: str | bytes) -> None:
        try:
            data = json.loads(message)
        except (ValueError, RecursionError):  # not JSON, or nested past Python's recursion limit
            return
        if isinstance(data, dict):
            self.server._on_message(data, self)

    def on_close(self) -> None:
        self.server._clients.discard(self)


class _Page(tornado.web.RequestHandler):
    def initialize(self, server: ViewerServer) -> None:
        self.server = server

    def get(self) -> None:
        self.set_header("Cache-Control", "no-store")
        self.set_header("Content-Type", "text/html; charset=utf-8")
        self.write(self.server.page_html())


class ViewerServer:
    """Serves the page on ``http://127.0.0.1:<port>/`` from a background thread.

    ``config`` returns the panel's JSON config for each new page; ``on_message`` gets
    every JSON message a page sends and the page's handle (on the server's thread).
    """

    def __init__(self, store: SceneStore, *, title: str, config: Callable[[], dict[str, Any]],
                 on_message: Callable[[dict[str, Any], object], None], port: int | None = None) -> None:
        self.store = store
        self.title = title
        self._config = config
        self._on_message = on_message
        self._clients: set[_Socket] = set()
        self._seq = 0
        self._ready = threading.Event()
        self._error: BaseException | None = None
        self._loop: IOLoop | None = None
        self._http: tornado.httpserver.HTTPServer | None = None
        self.port = 0
        check_port(port)
        self._thread = threading.Thread(target=self._run, args=(port,), name="robotmodel-viewer", daemon=True)
        self._thread.start()
        self._ready.wait()
        if self._error is not None:
            raise self._error

    @property
    def url(self) -> str:
        """The page's address."""
        return f"http://{HOST}:{self.port}/"

    def page_html(self) -> str:
        """The control page with the robot's name filled in."""
        from html import escape

        return (ASSETS / "page.html").read_text(encoding="utf-8").replace("__TITLE__", escape(self.title))

    def _bind(self, port: int | None) -> list[socket.socket]:
        # An explicit port is used as given; the default tries 7000 upwards, as meshcat does.
        candidates: Iterable[int] = [port] if port is not None else range(7000, 7100)
        last: OSError | None = None
        for candidate in candidates:
            try:
                return tornado.netutil.bind_sockets(candidate, address=HOST, family=socket.AF_INET)
            except OSError as exc:
                if exc.errno != errno.EADDRINUSE:
                    raise ViewerError(f"cannot listen on {HOST}:{candidate}: {exc.strerror}") from None
                last = exc
        where = f"port {port}" if port is not None else "ports 7000-7099"
        raise ViewerError(f"cannot listen on {HOST}: {where} in use ({last.strerror if last else ''})")

    def _run(self, port: int | None) -> None:
        loop = asyncio.new_event_loop()
        asyncio.set_event_loop(loop)
        try:
            sockets = self._bind(port)
            app = tornado.web.Application([
                (r"/", _Page, {"server": self}),
                (r"/ws", _Socket, {"server": self}),
                (r"/assets/(.*)", _Asset, {"path": str(ASSETS)}),
                (r"/meshcat/(.*)", _Asset, {"path": str(meshcat_dist())}),
            ], websocket_max_message_size=1 << 20, log_function=_quiet)
            self._http = tornado.httpserver.HTTPServer(app)
            self._http.add_sockets(sockets)
            self.port = sockets[0].getsockname()[1]
            self._loop = IOLoop.current()
        except BaseException as exc:
            self._error = exc
            self._ready.set()
            loop.close()
            return
        self._ready.set()
        try:
            loop.run_forever()
        finally:
            loop.close()

    # Everything below runs on the server's thread unless it says otherwise.

    def call_soon(self, fn: Callable[[], None]) -> None:
        """Run ``fn`` on the server's thread (safe from any thread)."""
        if self._loop is not None:
            self._loop.add_callback(fn)

    def call_later(self, delay: float, fn: Callable[[], None]) -> None:
        """Run ``fn`` on the server's thread after ``delay`` seconds (call on the server's thread)."""
        if self._loop is not None:
            self._loop.call_later(delay, fn)

    def _greet(self, client: _Socket) -> None:
        self._send_text(client, {"type": "config", **self._config()})
        for command in self.store.commands():
            _write(client, command, binary=True)
        self._seq += 1
        self._send_text(client, {"type": "synced", "seq": self._seq})

    def _send_text(self, client: _Socket, message: dict[str, Any]) -> None:
        with contextlib.suppress(tornado.websocket.WebSocketClosedError):
            _write(client, json.dumps(message))

    def broadcast(self, commands: Iterable[bytes], token: int | None = None) -> None:
        """Send commands to every page, then a ``synced`` marker telling it to draw."""
        commands = list(commands)
        self._seq += 1
        marker = json.dumps({"type": "synced", "seq": self._seq, "token": token})
        for client in list(self._clients):
            try:
                for command in commands:
                    _write(client, command, binary=True)
                _write(client, marker)
            except tornado.websocket.WebSocketClosedError:
                self._clients.discard(client)

    def broadcast_text(self, message: dict[str, Any], *, exclude: object = None) -> None:
        """Send one JSON message to every page but ``exclude``."""
        for client in list(self._clients):
            if client is not exclude:
                self._send_text(client, message)

    @property
    def client_count(self) -> int:
        """Number of connected pages."""
        return len(self._clients)

    def close(self) -> None:
        """Stop serving and join the thread (safe from any thread, idempotent)."""
        loop = self._loop
        if loop is None:
            return
        self._loop = None

        async def stop() -> None:
            for client in list(self._clients):
                client.close()
            if self._http is not None:
                self._http.stop()
                # Kept-alive browser connections too: left open with nobody reading, a reload
                # against a viewer restarted on the same port would wait on them forever.
                with contextlib.suppress(asyncio.TimeoutError):
                    await asyncio.wait_for(self._http.close_all_connections(), 2.0)
            asyncio.get_event_loop().stop()

        loop.add_callback(stop)
        self._thread.join(timeout=5)


def _write(client: _Socket, message: bytes | str, *, binary: bool = False) -> None:
    """Queue ``message``; a page that goes away mid-write is not an error worth a traceback.

    tornado returns a future that fails when the connection closes before the bytes are out;
    left unread, asyncio prints "Task exception was never retrieved" with a traceback at exit.
    """
    client.write_message(message, binary=binary).add_done_callback(_read_outcome)


def _read_outcome(future: Any) -> None:
    if not future.cancelled():
        future.exception()
