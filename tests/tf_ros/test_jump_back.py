"""A TF buffer on sim time is cleared when /clock jumps back, as tf2_ros's buffer with the node's clock is
(in-process wire: the /clock messages are delivered before ``publish`` returns)."""

from __future__ import annotations

import pytest

from robotmodel.bus import Node, node_clock
from robotmodel.msgs import make_transform
from robotmodel.msgs.builtin_interfaces import Time as TimeMsg
from robotmodel.msgs.rosgraph_msgs import Clock
from robotmodel.tf import Buffer, Time
from robotmodel.tf_ros._jump import clear_on_jump_back

NS = 1_000_000_000


def _clock(sec: int) -> Clock:
    return Clock(clock=TimeMsg(sec=sec, nanosec=0))


@pytest.mark.parametrize("use_sim_time", [True, False])
def test_a_jump_back_of_clock_clears_the_dynamic_transforms(capsys: pytest.CaptureFixture[str],
                                                            use_sim_time: bool) -> None:
    buffer = Buffer()
    buffer.set_transform_static(make_transform("base", "laser", (0.2, 0, 0)), "test")
    with Node("clocked", backend="inprocess", domain_id=391 + use_sim_time) as node:
        clock = node_clock(node, use_sim_time)
        clear_on_jump_back(buffer, clock, "viewer")
        pub = node.create_publisher(Clock, "/clock", 10)
        for sec in (100, 101):  # forward: kept
            pub.publish(_clock(sec))
            buffer.set_transform(make_transform("odom", "base", (sec, 0, 0), stamp_ns=sec * NS), "test")
        assert buffer.lookup_transform("odom", "base", Time()).transform.translation.x == 101
        pub.publish(_clock(100))  # back: a looping replay
        err = capsys.readouterr().err
        if not use_sim_time:  # the system clock: /clock means nothing, the newest transform stays
            assert buffer.lookup_transform("odom", "base", Time()).transform.translation.x == 101 and not err
            return
        assert clock.now() == Time(seconds=100)
        assert buffer.can_transform("odom", "base", Time()) is False
        assert buffer.lookup_transform("base", "laser", Time()).transform.translation.x == 0.2  # statics stay
        assert "[WARN]" in err and "[viewer]: Detected jump back in time. Clearing TF buffer." in err, err
