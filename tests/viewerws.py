"""The viewer's state as its page sees it: the config message its websocket sends each new page."""

from __future__ import annotations

import asyncio
import json
import time
from collections.abc import Callable

import tornado.httpclient
import tornado.websocket


def viewer_config(url: str, predicate: Callable[[dict[str, object]], bool], timeout: float = 40.0) -> dict[str, object]:
    """The viewer page's config message (robot, joint values), read over its websocket until ``predicate``."""
    async def read() -> dict[str, object]:
        ws_url = url.replace("http://", "ws://") + "ws"
        request = tornado.httpclient.HTTPRequest(ws_url, headers={"Origin": url.rstrip("/")})
        end = time.monotonic() + timeout
        while True:
            conn = await tornado.websocket.websocket_connect(request)
            try:
                while True:
                    message = await conn.read_message()
                    if message is None or isinstance(message, bytes):
                        continue
                    data = json.loads(message)
                    if data.get("type") == "config":
                        break
            finally:
                conn.close()
            if predicate(data) or time.monotonic() > end:
                return dict(data)
            await asyncio.sleep(0.2)

    return asyncio.run(read())
