"""static-transform-publisher and tf2-echo as separate processes on a real (zenoh) bus.

Expected output text: the tf2_echo block for ``1 2 3 0.5 0.1 -1.0 foo bar`` worked out by
hand from tf2's formulas (see test_echo_fmt.py), and the publisher's start-up text as ROS 2
Jazzy's program formats it.
"""

from __future__ import annotations

import signal

from cli_tf.expected import EXPECTED_STATIC

ARGS = ("1", "2", "3", "0.5", "0.1", "-1.0", "foo", "bar")
BLOCK = EXPECTED_STATIC.splitlines()


def wait_block(echo, timeout=30.0):
    """Wait for one complete printed transform on the echo's stdout; return its 10 lines."""
    def complete():
        out = echo.out
        return any(line == "At time 0.0" and len(out) - i >= len(BLOCK) for i, line in enumerate(out))

    echo.wait_for(complete, timeout, "a complete tf2_echo block")
    start = echo.out.index("At time 0.0")
    return echo.out[start:start + len(BLOCK)]


def test_static_publisher_first_then_echo(bus):
    pub = bus.robotmodel("static-transform-publisher", *ARGS)
    # Start the echo once the publisher has announced itself (its transform is out).
    # The start-up text is one log record over four lines; its last line ends the announcement.
    pub.wait_line(r"^from 'foo' to 'bar'$", stream="err")
    announced = pub.wait_line(r"Spinning until stopped - publishing transform", stream="err")
    assert announced.string.startswith("[INFO] [")
    assert "] [static_transform_publisher_" in announced.string
    assert pub.err[0].endswith("[]: Old-style arguments are deprecated; see --help for new-style arguments")
    start = pub.err.index(announced.string)
    assert pub.err[start + 1:start + 4] == [
        "translation: ('1.000000', '2.000000', '3.000000')",
        "rotation: ('-0.474792', '-0.075966', '0.240062', '0.843310')",
        "from 'foo' to 'bar'",
    ]
    echo = bus.robotmodel("tf2-echo", "foo", "bar", "5")
    assert wait_block(echo) == BLOCK
    assert echo.stop(signal.SIGINT) == 0
    assert pub.stop(signal.SIGTERM) == 0


def test_echo_first_then_static_publisher(bus):
    echo = bus.robotmodel("tf2_echo", "foo", "bar", "5")
    waiting = echo.wait_line(r"Waiting for transform", stream="err")
    assert waiting.string.endswith(
        '[tf2_echo]: Waiting for transform foo ->  bar: Invalid frame ID "foo" passed to canTransform '
        "argument target_frame - frame does not exist")
    pub = bus.robotmodel("static_transform_publisher", "--x", "1", "--y", "2", "--z", "3", "--yaw", "0.5",
                         "--pitch", "0.1", "--roll", "-1.0", "--frame-id", "foo", "--child-frame-id", "bar")
    assert wait_block(echo) == BLOCK
    assert echo.stop(signal.SIGTERM) == 0
    assert pub.stop(signal.SIGINT) == 0
    # New-style flags: no deprecation warning.
    assert not any("deprecated" in line for line in pub.err)


def test_ros1_period_form_republishes_on_tf(bus):
    pub = bus.robotmodel("static-transform-publisher", "0", "0", "1", "0", "0", "0", "1", "odom", "base", "50")
    pub.wait_line(r"Spinning until stopped", stream="err")
    echo = bus.robotmodel("tf2-echo", "odom", "base", "10")
    # On /tf with stamps of now + period: the echo prints real stamps, not 0.0.
    stamps = []

    def two_stamps():
        stamps[:] = [line for line in echo.out if line.startswith("At time ")]
        return len(stamps) >= 2

    echo.wait_for(two_stamps, 30.0, "two printed stamps")
    assert all(s != "At time 0.0" for s in stamps)
    assert echo.stop(signal.SIGINT) == 0
    assert pub.stop(signal.SIGTERM) == 0
