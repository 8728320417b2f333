"""The viewer's server without a browser: redraw rate, coalescing to the latest state, origin check."""

from __future__ import annotations

import asyncio
import json
import logging
import math
import subprocess
import sys
import time
from typing import Any

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


# joint_state_publisher_gui's ranges: a revolute joint's limits narrowed by its safety controller's soft
# limits, a continuous joint -pi..pi; a mimic joint has no slider and follows its master.
_SLIDERS_URDF = """<robot name="sliders">
  <link name="base"/><link name="a"/><link name="b"/><link name="c"/>
  <joint name="j1" type="revolute"><parent link="base"/><child link="a"/><axis xyz="0 0 1"/>
    <limit lower="-1" upper="2" effort="1" velocity="1"/>
    <safety_controller k_velocity="1" soft_lower_limit="-0.5" soft_upper_limit="1.5"/></joint>
  <joint name="j2" type="continuous"><parent link="a"/><child link="b"/><axis xyz="0 0 1"/></joint>
  <joint name="j3" type="prismatic"><parent link="b"/><child link="c"/><axis xyz="1 0 0"/>
    <limit lower="-10" upper="10" effort="1" velocity="1"/><mimic joint="j1" multiplier="2" offset="0.1"/></joint>
</robot>"""


async def _page(port: int, origin: str | None = None, host: str = "127.0.0.1",
                headers: dict[str, str] | None = None) -> Any:
    request = HTTPRequest(f"ws://{host}:{port}/ws",
                          headers={"Origin": origin or f"http://{host}:{port}", **(headers or {})})
    return await websocket_connect(request)


async def _knock(port: int, origin: str | None = None, host: str = "127.0.0.1",
                 headers: dict[str, str] | None = None) -> None:
    """Open the page's socket as ``origin`` would, then close it (HTTPClientError when refused)."""
    ws = await _page(port, origin, host, headers)
    ws.close()


def test_only_the_pages_own_origin_may_open_the_socket() -> None:
    with Viewer(load(PANDA), port=0) as viewer:
        port = viewer.port
        for origin in ("http://localhost:8080", "http://127.0.0.1:9", f"https://127.0.0.1:{port}",
                       f"http://127.0.0.1:{port}.evil.example", f"http://127.0.0.1:{port + 1}", "null",
                       f"http://localhost:{port}"):  # another origin than the page's http://127.0.0.1:port
            with pytest.raises(HTTPClientError):
                asyncio.run(_knock(port, origin))
        # What a browser sends for a same-origin page, from a DNS-rebound name resolving to 127.0.0.1.
        with pytest.raises(HTTPClientError):
            asyncio.run(_knock(port, f"http://evil.example:{port}",
                               headers={"Host": f"evil.example:{port}", "Sec-Fetch-Site": "same-origin"}))
        for host in ("127.0.0.1", "localhost"):  # the page's own origin, as the browser loaded it
            asyncio.run(_knock(port, host=host))


def test_slider_values_are_clamped_as_joint_state_publisher_gui_does(caplog: pytest.LogCaptureFixture) -> None:
    from robotmodel.model import parse_urdf

    got: list[dict[str, float]] = []
    with Viewer(parse_urdf(_SLIDERS_URDF), port=0) as viewer:
        viewer.on_joints(got.append)

        async def send() -> None:
            ws = await _page(viewer.port)
            # Bad input first (none may cost the connection or print a traceback), then the values.
            await ws.write_message("[" * 100_000 + "]" * 100_000)  # nested past the recursion limit
            await ws.write_message('{"type": "joints", "positions": {"j1": ' + "9" * 400 + "}}")  # > float
            await ws.write_message(json.dumps({"type": "joints", "positions": {"j1": "x", "j2": None, "j3": 5.0}}))
            await ws.write_message(json.dumps({"type": "joints", "positions": {"j1": 1e308, "j2": -1e308,
                                                                               "j3": 5.0}, "token": 7}))
            deadline = time.monotonic() + 30
            while len(got) < 3 and time.monotonic() < deadline:
                await asyncio.sleep(0.05)
            ws.close()

        asyncio.run(send())
    assert len(got) == 3, got  # the three joints messages; the deep array is dropped
    assert got[0]["j1"] == 1.5  # an integer past float's range is clamped like any value past the limit
    assert got[-1]["j1"] == 1.5 and got[-1]["j2"] == -math.pi
    assert got[-1]["j3"] == pytest.approx(1.5 * 2 + 0.1)  # the mimic follows, its own value is ignored
    assert not [r for r in caplog.records if r.levelno >= logging.ERROR], caplog.text


def test_a_nul_in_an_asset_path_is_a_404_without_a_traceback(caplog: pytest.LogCaptureFixture) -> None:
    import urllib.error
    import urllib.request

    with Viewer(load(PANDA), port=0) as viewer:
        for path in ("/assets/page.html%00.js", "/meshcat/main.min.js%00", "/assets/%00"):
            with pytest.raises(urllib.error.HTTPError) as info:
                urllib.request.urlopen(f"http://127.0.0.1:{viewer.port}{path}", timeout=30)
            assert info.value.code == 404
            assert b"Traceback" not in info.value.read()
        with urllib.request.urlopen(f"http://127.0.0.1:{viewer.port}/assets/page.html", timeout=30) as ok:
            assert ok.status == 200
    assert not [r for r in caplog.records if r.levelno >= logging.ERROR], caplog.text


def test_a_port_beyond_65535_is_refused() -> None:
    from robotmodel.errors import ViewerError

    for port in (99999, 65536, -1):
        with pytest.raises(ViewerError, match=f"port {port} is out of range"):
            Viewer(load(PANDA), port=port)
    proc = subprocess.run([sys.executable, "-m", "robotmodel.cli.main", "view", str(PANDA), "--port", "99999"],
                          capture_output=True, text=True, timeout=120, check=False)
    assert proc.returncode == 2
    assert proc.stderr.splitlines()[-1] == ("robotmodel view: error: argument --port: port 99999 is out of range: "
                                            "a TCP port is 0 to 65535")
    assert "Traceback" not in proc.stderr and proc.stdout == ""


_LISTENER = """
from robotmodel.bus import Node
from robotmodel.msgs import JointState
from robotmodel.signals import stop_on_signals
stop = stop_on_signals()
def on_state(msg):
    print(" ".join(f"{n}={float(v)!r}" for n, v in zip(msg.name, msg.position)), flush=True)
with Node("listener") as node:
    node.create_subscription(JointState, "joint_states", on_state, 10)
    print("subscribed", flush=True)
    stop.wait()
"""


def test_joint_state_publisher_gui_publishes_clamped_values_and_survives_bad_pages(bus: Any) -> None:
    """What a page sends reaches /joint_states clamped to the URDF's limits; bad input costs nothing."""
    import signal
    import urllib.error
    import urllib.request
    import xml.etree.ElementTree as ET

    joint2 = next(j for j in ET.parse(PANDA).getroot().iter("joint") if j.get("name") == "panda_joint2")
    upper = min(float(joint2.find("limit").get("upper")), float(joint2.find("safety_controller").get("soft_upper_limit")))
    gui = bus.robotmodel("joint-state-publisher-gui", str(PANDA), "--port", "0")
    port = int(gui.wait_line(r"^http://127\.0\.0\.1:(\d+)/ ", timeout=120).group(1))
    listener = bus.start(sys.executable, "-c", _LISTENER)
    listener.wait_line("^subscribed$", timeout=60)
    try:
        listener.wait_line(r"panda_joint2=0\.0 ", timeout=30)
        with pytest.raises(HTTPClientError):
            asyncio.run(_knock(port, "http://localhost:8080"))

        async def send() -> None:
            ws = await _page(port)
            await ws.write_message("[" * 100_000 + "]" * 100_000)
            await ws.write_message('{"type": "joints", "positions": {"panda_joint1": ' + "9" * 400 + "}}")
            await ws.write_message(json.dumps({"type": "joints", "positions": {"panda_joint2": 1e308}}))
            await asyncio.sleep(0.5)
            ws.close()

        asyncio.run(send())
        match = listener.wait_line(r"panda_joint2=(?!0\.0 )(\S+) ", timeout=30)  # past the default's lines
        assert float(match.group(1)) == upper
        with pytest.raises(urllib.error.HTTPError) as info:
            urllib.request.urlopen(f"http://127.0.0.1:{port}/assets/page.html%00.js", timeout=30)
        assert info.value.code == 404
    finally:
        listener.stop(signal.SIGTERM)
        code = gui.stop(signal.SIGINT)
    assert code == 0, gui.err[-20:]
    assert not any("Traceback" in line or "Uncaught exception" in line for line in gui.err), gui.err
