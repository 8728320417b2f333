"""The viewer's state as its page sees it: what its websocket sends each new page.

A page gets the panel's ``config`` message (robot, joint values) as text, then the scene as
meshcat's msgpack commands; :func:`viewer_state` reads both, the ``--tf`` frames (paths
``/tf/<frame>``) as 4x4 matrices.
"""

from __future__ import annotations

import asyncio
import json
import time
from collections.abc import Callable
from typing import Any

import numpy as np
import tornado.httpclient
import tornado.websocket
import umsgpack

#: A page's view: the config message and the --tf frames by name.
State = tuple[dict[str, Any], dict[str, np.ndarray]]


def _tf_frames(commands: list[bytes]) -> dict[str, np.ndarray]:
    frames: dict[str, np.ndarray] = {}
    for raw in commands:
        command = umsgpack.unpackb(raw)
        path = str(command.get("path", ""))
        if command.get("type") == "set_transform" and path.startswith("/tf/") and path.count("/") == 2:
            # meshcat's matrices are float32, column-major.
            frames[path[4:]] = np.frombuffer(command["matrix"].data, dtype=np.float32).reshape(4, 4).T
    return frames


def viewer_state(url: str, predicate: Callable[[State], bool], timeout: float = 40.0) -> State:
    """Connect as a page until ``predicate((config, tf_frames))`` holds (or the deadline passes); that state."""
    async def read() -> State:
        ws_url = url.replace("http://", "ws://") + "ws"
        request = tornado.httpclient.HTTPRequest(ws_url, headers={"Origin": url.rstrip("/")})
        end = time.monotonic() + timeout
        while True:
            conn = await tornado.websocket.websocket_connect(request)
            config: dict[str, Any] = {}
            commands: list[bytes] = []
            try:
                while True:
                    message = await conn.read_message()
                    if message is None:
                        break
                    if isinstance(message, bytes):
                        commands.append(message)
                        continue
                    data = json.loads(message)
                    if data.get("type") == "config":
                        config = data
                    elif data.get("type") == "synced":
                        break  # the greeting is complete
            finally:
                conn.close()
            state = (config, _tf_frames(commands))
            if predicate(state) or time.monotonic() > end:
                return state
            await asyncio.sleep(0.2)

    return asyncio.run(read())


def viewer_config(url: str, predicate: Callable[[dict[str, Any]], bool], timeout: float = 40.0) -> dict[str, Any]:
    """The viewer page's config message (robot, joint values), read again until ``predicate`` holds."""
    return viewer_state(url, lambda state: predicate(state[0]), timeout)[0]
