"""TCPROS against real ROS 1 (Debian 12's rospy, rostopic): both directions, latching, md5 refusals.

A publisher killed and restarted, and a master restarted: test_recovery.py (through the bus layer)."""

from __future__ import annotations

import logging

import pytest
from ros1helpers import GroupProc, Ros1World, wait_until

from robotmodel.ros1 import message_type, typestore

TYPES = typestore().types


def _string(text: str) -> object:
    return TYPES["std_msgs/msg/String"](data=text)


def _tf(child: str, sec: int, nsec: int, x: float) -> object:
    t = TYPES
    header = t["std_msgs/msg/Header"](seq=0, stamp=t["builtin_interfaces/msg/Time"](sec=sec, nanosec=nsec),
                                      frame_id="world")
    transform = t["geometry_msgs/msg/Transform"](
        translation=t["geometry_msgs/msg/Vector3"](x=x, y=0.0, z=0.0),
        rotation=t["geometry_msgs/msg/Quaternion"](x=0.0, y=0.0, z=0.0, w=1.0))
    stamped = t["geometry_msgs/msg/TransformStamped"](header=header, child_frame_id=child, transform=transform)
    return t["tf2_msgs/msg/TFMessage"](transforms=[stamped])


def test_rostopic_echo_and_rospy_receive_robotmodels_string_and_tf(ros1: Ros1World) -> None:
    node = ros1.node("rm_talker")
    chatter = node.advertise("/chatter", "std_msgs/String", latch=True)
    chatter.publish(_string("hello from robotmodel"))
    echoed = ros1.tool("rostopic", "echo", "-n", "1", "/chatter")
    assert 'data: "hello from robotmodel"' in echoed, echoed

    tf = node.advertise("/tf", "tf2_msgs/TFMessage")
    listener = ros1.rospy("sub", "/tf", "tf2_msgs/TFMessage")
    listener.wait_line("^ready")
    wait_until(lambda: tf.subscriber_count >= 1, 30, "rospy's connection to /tf")
    for i in range(3):
        tf.publish(_tf(f"link{i}", 1700000000, 123456789 + i, 0.5 * i))
    for i in range(3):
        listener.wait_line(rf"^got world->link{i}@1700000000\.{123456789 + i:09d}:{0.5 * i:.3f}$")


def test_robotmodel_receives_rospys_messages(ros1: Ros1World) -> None:
    got: list[str] = []
    node = ros1.node("rm_listener")
    sub = node.subscribe("/chatter", "std_msgs/String", lambda m: got.append(m.data))
    talker = ros1.rospy("pub", "/chatter", "std_msgs/String", "--text", "from rospy")
    talker.wait_line("^ready")
    wait_until(lambda: len(got) >= 3, 30, "three messages from rospy")
    numbers = [int(text.rsplit(" ", 1)[1]) for text in got[:3]]
    assert all(text.startswith("from rospy ") for text in got)
    assert numbers == sorted(numbers) and len(set(numbers)) == 3  # in order, no duplicates
    assert sub.publisher_uris and sub.publisher_uris[0].startswith("http://127.0.0.1:")


def test_late_robotmodel_subscriber_gets_rospys_latched_message(ros1: Ros1World) -> None:
    talker = ros1.rospy("pub", "/latched", "std_msgs/String", "--latch", "--count", "1", "--text", "kept")
    talker.wait_line("^published 1$")
    got: list[str] = []
    ros1.node("rm_late").subscribe("/latched", "std_msgs/String", lambda m: got.append(m.data))
    wait_until(lambda: got, 30, "the latched message")
    assert got == ["kept 0"]


def test_late_rospy_subscriber_gets_robotmodels_latched_message(ros1: Ros1World) -> None:
    node = ros1.node("rm_latcher")
    pub = node.advertise("/tf_static", "tf2_msgs/TFMessage", latch=True)
    pub.publish(_tf("old", 1, 0, 1.0))
    pub.publish(_tf("static", 1700000001, 5, 2.0))  # only the last one is latched
    listener = ros1.rospy("sub", "/tf_static", "tf2_msgs/TFMessage")
    listener.wait_line(r"^got world->static@1700000001\.000000005:2\.000$")
    assert listener.count("^got ") == 1


def test_wrong_md5_is_refused_with_ros_text_on_both_sides(ros1: Ros1World, caplog: pytest.LogCaptureFixture) -> None:
    caplog.set_level(logging.INFO, logger="robotmodel.ros1")
    real = message_type("std_msgs/String").md5sum
    fake = "0123456789abcdef0123456789abcdef"
    # a rospy subscriber with another md5sum asks robotmodel's publisher
    node = ros1.node("rm_md5")
    pub = node.advertise("/typed", "std_msgs/String", latch=True)
    pub.publish(_string("must not arrive"))
    bad_sub = ros1.rospy("sub", "/typed", "std_msgs/String", "--md5", fake, "--name", "bad_sub")
    text = (f"Client [/bad_sub] wants topic [/typed] to have datatype/md5sum [std_msgs/String/{fake}], "
            f"but our version has [std_msgs/String/{real}] Dropping connection.")
    bad_sub.wait_line("remote error reported: " + _rx(text))
    wait_until(lambda: any(text in r.getMessage() for r in caplog.records), 10, "robotmodel's refusal log line")
    assert bad_sub.count("^got ") == 0 and pub.subscriber_count == 0

    # robotmodel subscribes to a rospy publisher with another md5sum
    bad_pub = ros1.rospy("pub", "/typed2", "std_msgs/String", "--md5", fake, "--name", "bad_pub")
    bad_pub.wait_line("^ready")
    got: list[object] = []
    node.subscribe("/typed2", "std_msgs/String", got.append)
    text = (f"Client [/rm_md5] wants topic [/typed2] to have datatype/md5sum [std_msgs/String/{real}], "
            f"but our version has [std_msgs/String/{fake}] Dropping connection.")
    bad_pub.wait_line(_rx(text))
    wait_until(lambda: any("remote error reported: " + text in r.getMessage() for r in caplog.records), 10,
               "robotmodel's log line of rospy's refusal")
    bad_pub.wait_line("^published 3$")
    assert got == []


def _rx(text: str) -> str:
    import re

    return re.escape(text)


def test_rostopic_hz_as_the_real_rostopic(ros1: Ros1World) -> None:
    """``robotmodel rostopic hz -w 5`` beside the real ``rostopic hz -w 5``, both started before the topic
    exists: the same warning, then ``subscribed to [/late]``, then reports whose window counts messages
    (5 once full) and whose rate is the publisher's (rostopic pub -r 20)."""
    import re
    import sys

    ours_env = dict(ros1.env, ROS_VERSION="1")
    real = ros1.start("rostopic", "hz", "-w", "5", "/late")
    ours = GroupProc([sys.executable, "-m", "robotmodel.cli.main", "rostopic", "hz", "-w", "5", "/late"], ours_env)
    ros1.procs.append(ours)
    for proc in (real, ours):
        proc.wait_line(r"^WARNING: topic \[/late\] does not appear to be published yet$", 60)
    ros1.start("rostopic", "pub", "-r", "20", "/late", "std_msgs/String", "data: x")
    rate = re.compile(r"^average rate: ([\d.]+)$")
    window = re.compile(r"window: (\d+)$")
    for proc in (real, ours):
        wait_until(lambda p=proc: sum(bool(rate.match(ln)) for ln in p.lines) >= 3, 60, "three reports")
    for proc in (real, ours):
        lines = [ln for ln in proc.lines if ln.strip()]
        assert lines[1] == "subscribed to [/late]", lines[:3]
        assert [int(m[1]) for ln in lines if (m := window.search(ln))][-1] == 5, lines
        assert abs(float([m[1] for ln in lines if (m := rate.match(ln))][-1]) - 20.0) < 2.0, lines
