"""The rclpy tf2 tutorial programs (examples/rclpy_tf2_*.py) as real processes on a private zenoh bus.

Real tf2_ros for rclpy has no wheel (PyPI has rclpy, not tf2_ros), so these programs cannot
run against the real library here; what they print is checked against values derived by
hand from the broadcaster's formula instead: the carrot circles ``world`` at the ``radius``
parameter, angle = stamp * pi / 5, so x = r cos(angle), y = r sin(angle) at the stamp the
listener prints. That each program differs from what an rclpy user writes only in its
imports is checked on the text. Every program ends within 2 s of SIGINT (status 0), of
SIGTERM (status 0) and of an uncaught exception in a callback (status 1, the traceback on
stderr) while its TransformListener is alive.
"""

from __future__ import annotations

import math
import re
import signal
import sys
import textwrap
import time
from collections.abc import Iterator
from pathlib import Path

import pytest
from livebus import Bus, Proc

from robotmodel import rclpy
from robotmodel.rclpy.context import Context
from robotmodel.rclpy.node import Node
from robotmodel.rclpy.parameter import Parameter
from robotmodel.rclpy.parameter_client import AsyncParameterClient

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
DEADLINE_S = 30.0
EXIT_S = 2.0
REAL_IMPORTS = {
    "from robotmodel import rclpy": "import rclpy",
    "from robotmodel.msgs.geometry_msgs.msg import": "from geometry_msgs.msg import",
    "from robotmodel.rclpy.": "from rclpy.",
    "from robotmodel.tf2_ros": "from tf2_ros",
}
CARROT = re.compile(r"\[carrot_listener\]: carrot at x=(-?[\d.]+) y=(-?[\d.]+), ([\d.]+) m from world "
                    r"\(stamp (\d+)\.(\d{9})\)")


@pytest.fixture
def bus(tmp_path: Path) -> Iterator[Bus]:
    b = Bus(tmp_path)
    b.env["RMW_IMPLEMENTATION"] = "rmw_zenoh_cpp"  # the wire, named (not left to the default)
    try:
        yield b
    finally:
        b.reap()


def example(bus: Bus, name: str, *args: str) -> Proc:
    return bus.start(sys.executable, str(EXAMPLES / name), *args)


@pytest.mark.parametrize("name", ["rclpy_tf2_broadcaster.py", "rclpy_tf2_listener.py"])
def test_only_the_imports_differ_from_an_rclpy_program(name: str) -> None:
    text = (EXAMPLES / name).read_text()
    real = text
    for ours, theirs in REAL_IMPORTS.items():
        real = real.replace(ours, theirs)
    assert "robotmodel" not in real.split('"""', 2)[2]
    body = [line for line in text.splitlines() if not line.startswith(("import ", "from "))]
    assert [line for line in real.splitlines() if not line.startswith(("import ", "from "))] == body


def carrots(proc: Proc, count: int) -> list[tuple[float, float, float, float]]:
    """(x, y, distance, stamp in s) of the listener's next ``count`` carrot lines."""
    start = len(proc.err)
    proc.wait_for(lambda: sum(bool(CARROT.search(line)) for line in proc.err[start:]) >= count, DEADLINE_S,
                  f"{count} carrot lines")
    found = [CARROT.search(line) for line in proc.err[start:]]
    return [(float(m[1]), float(m[2]), float(m[3]), int(m[4]) + int(m[5]) / 1e9) for m in found if m][:count]


def test_listener_and_broadcaster_with_a_parameter_set_on_the_fly(bus: Bus) -> None:
    listener = example(bus, "rclpy_tf2_listener.py")
    # Started first, it catches tf2_ros's LookupException in the three-exception block.
    listener.wait_line(r"\[carrot_listener\]: Could not transform world to carrot: LookupException", DEADLINE_S,
                       stream="err")
    broadcaster = example(bus, "rclpy_tf2_broadcaster.py", "--ros-args", "-p", "radius:=3.0")
    broadcaster.wait_line(r"\[carrot_broadcaster\]: broadcasting carrot at radius 3.0", DEADLINE_S, stream="err")
    for x, y, distance, stamp in carrots(listener, 2):
        angle = stamp * math.pi / 5
        assert (x, y, distance) == pytest.approx((3 * math.cos(angle), 3 * math.sin(angle), 3.0), abs=1.5e-3)
    # The broadcaster's parameter services, answered by its executor between timer callbacks.
    ctx = Context()
    ctx.init([], backend="zenoh", domain_id=int(bus.env["ROS_DOMAIN_ID"]),
             connect=[f"tcp/127.0.0.1:{bus.env['ROBOTMODEL_ZENOH_PORT']}"])
    try:
        node = Node("radius_setter", context=ctx)
        client = AsyncParameterClient(node, "carrot_broadcaster")
        assert client.wait_for_services(DEADLINE_S)
        future = client.set_parameters([Parameter("radius", value=1.5)])
        rclpy.spin_until_future_complete(node, future, rclpy.executors.SingleThreadedExecutor(context=ctx),
                                         DEADLINE_S)
        assert [r.successful for r in future.result().results] == [True]
    finally:
        ctx.try_shutdown()
    listener.wait_for(lambda: any(", 1.500 m from world" in line for line in listener.err), DEADLINE_S,
                      "the carrot at the new radius")
    for x, y, _distance, stamp in carrots(listener, 1):
        angle = stamp * math.pi / 5
        assert (x, y) == pytest.approx((1.5 * math.cos(angle), 1.5 * math.sin(angle)), abs=1.5e-3)
    for proc, sig in ((listener, signal.SIGINT), (broadcaster, signal.SIGTERM)):
        start = time.monotonic()
        assert proc.stop(sig, timeout=10.0) == 0, proc.err[-10:]
        assert time.monotonic() - start < EXIT_S


def test_an_uncaught_exception_in_a_callback_ends_the_program(bus: Bus, tmp_path: Path) -> None:
    program = tmp_path / "crash.py"
    program.write_text(textwrap.dedent("""
        from robotmodel import rclpy
        from robotmodel.rclpy.node import Node
        from robotmodel.tf2_ros.buffer import Buffer
        from robotmodel.tf2_ros.transform_listener import TransformListener

        rclpy.init()
        node = Node("crasher")
        buffer = Buffer()
        listener = TransformListener(buffer, node)

        def boom():
            print("crashing", flush=True)
            raise RuntimeError("a bug in a timer callback")

        node.create_timer(0.2, boom)
        rclpy.spin(node)
        """))
    proc = bus.start(sys.executable, str(program))
    proc.wait_line("crashing", DEADLINE_S)
    start = time.monotonic()
    proc.wait_for(lambda: proc.popen.poll() is not None, EXIT_S + 8.0, "exit after the exception")
    assert time.monotonic() - start < EXIT_S
    assert proc.popen.returncode == 1
    proc.wait_line("RuntimeError: a bug in a timer callback", 5.0, stream="err")
