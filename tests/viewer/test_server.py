"""The viewer's server without a browser: redraw rate, coalescing to the latest state, origin check."""

from __future__ import annotations

import asyncio
import json
import time

import numpy as np
import pytest
import umsgpack
from conftest import ERD_ROBOTS
from tornado.httpclient import HTTPClientError, HTTPRequest
from tornado.websocket import websocket_connect

from robotmodel.kinematics import KinematicModel, joint_transforms
from robotmodel.model import load
from robotmodel.viewer import Viewer

PANDA = ERD_ROBOTS / "panda_description" / "urdf" / "panda.urdf"


async def _burst(viewer: Viewer, joint: str, values: list[float], period: float) -> tuple[int, float, list[bytes]]:
    """Connect like a page, send a burst of display() calls; (redraws, seconds, binary commands)."""
    ws = await websocket_connect(HTTPRequest(f"ws://127.0.0.1:{viewer.port}/ws",
                                             headers={"Origin": f"http://127.0.0.1:{viewer.port}"}))
    while True:  # the greeting: config, the scene, one synced marker
        message = await ws.read_message()
        if isinstance(message, str) and json.loads(message)["type"] == "synced":
            break
    start = time.monotonic()
    for value in values:
        viewer.display({joint: value})
        await asyncio.sleep(period)
    elapsed = time.monotonic() - start
    synced, commands = 0, []
    while True:
        try:
            message = await asyncio.wait_for(ws.read_message(), 0.5)
        except TimeoutError:
            break
        if isinstance(message, bytes):
            commands.append(message)
        elif json.loads(message)["type"] == "synced":
            synced += 1
    ws.close()
    return synced, elapsed, commands


def test_redraws_are_capped_at_30_hz_and_coalesce_to_the_latest() -> None:
    desc = load(PANDA)
    with Viewer(desc, port=0) as viewer:
        values = [(i + 1) * 0.002 for i in range(200)]
        synced, elapsed, commands = asyncio.run(_burst(viewer, "panda_joint2", values, 0.002))
    assert 2 <= synced <= elapsed * 30 + 3, (synced, elapsed)
    assert len(commands) == synced  # one joint moved: one transform per redraw
    last = umsgpack.unpackb(commands[-1])
    drawn = np.frombuffer(last["matrix"].data, np.float32).reshape(4, 4).T
    model = KinematicModel(desc)
    positions = model.default_positions() | {"panda_joint2": values[-1]}
    moved = joint_transforms(model, positions)
    expected = moved.matrices()[moved.children.index("panda_link2")]
    np.testing.assert_allclose(drawn, expected, atol=1e-6)


def test_pages_from_other_origins_are_refused() -> None:
    with Viewer(load(PANDA), port=0) as viewer:
        async def connect() -> None:
            await websocket_connect(HTTPRequest(f"ws://127.0.0.1:{viewer.port}/ws",
                                                headers={"Origin": "http://evil.example"}))
        with pytest.raises(HTTPClientError):
            asyncio.run(connect())


def test_close_drops_kept_alive_connections() -> None:
    # A browser keeps its HTTP connection open; if closing the viewer left it open with
    # nobody reading, a reload against a restarted viewer on the same port would hang.
    import http.client

    viewer = Viewer(load(PANDA), port=0)
    conn = http.client.HTTPConnection("127.0.0.1", viewer.port, timeout=10)
    conn.request("GET", "/")
    response = conn.getresponse()
    assert response.status == 200
    response.read()
    sock = conn.sock
    assert sock is not None
    viewer.close()
    sock.settimeout(5)
    try:
        data = sock.recv(1)
    except TimeoutError:
        pytest.fail("the connection was left open after close()")
    except ConnectionResetError:
        data = b""
    assert data == b""
    conn.close()
