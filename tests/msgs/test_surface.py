"""The public surface of robotmodel.time and robotmodel.msgs, and each class against ROS's definition."""

from __future__ import annotations

import dataclasses

import pytest
from msgstrategies import CLASSES, MODULES, STORE

import robotmodel.msgs
import robotmodel.time
from robotmodel.msgs import (
    builtin_interfaces,
    geometry_msgs,
    message_class,
    nav_msgs,
    rosgraph_msgs,
    sensor_msgs,
    std_msgs,
)


def test_time_surface() -> None:
    assert robotmodel.time.__all__ == [
        "Clock", "Duration", "PlaybackClock", "Rate", "SimClock", "SystemClock", "Time", "parse_seconds",
        "to_nanoseconds",
    ]
    for name in robotmodel.time.__all__:
        assert getattr(robotmodel.time, name).__doc__, name


def test_msgs_surface() -> None:
    assert robotmodel.msgs.__all__ == [
        "Header", "JointState", "Message", "Odometry", "Point", "PointStamped", "Pose", "PoseStamped",
        "PoseWithCovariance", "Quaternion", "String", "TFMessage", "TFRecord", "Transform", "TransformStamped", "Twist",
        "TwistStamped", "TwistWithCovariance", "Vector3", "Vector3Stamped", "builtin_interfaces", "decode_tf_records",
        "deserialize", "encode_tf_records", "from_rosbags", "geometry_msgs", "make_transform", "message_class", "nav_msgs", "rosgraph_msgs",
        "sensor_msgs", "serialize", "stamp", "std_msgs", "tf2_msgs", "to_rosbags", "turtlesim", "type_hash", "typestore",
    ]
    for name in robotmodel.msgs.__all__:
        assert getattr(robotmodel.msgs, name).__doc__, name


def test_package_modules_mirror_ros_packages() -> None:
    assert {c.__msgtype__ for c in CLASSES} == {
        "builtin_interfaces/msg/Time", "builtin_interfaces/msg/Duration", "std_msgs/msg/Header",
        "std_msgs/msg/String", "geometry_msgs/msg/Vector3", "geometry_msgs/msg/Point", "geometry_msgs/msg/Quaternion",
        "geometry_msgs/msg/Transform", "geometry_msgs/msg/TransformStamped", "geometry_msgs/msg/Pose",
        "geometry_msgs/msg/PoseStamped", "geometry_msgs/msg/PointStamped", "geometry_msgs/msg/Vector3Stamped",
        "geometry_msgs/msg/PoseWithCovariance", "geometry_msgs/msg/Twist", "geometry_msgs/msg/TwistStamped",
        "geometry_msgs/msg/TwistWithCovariance", "sensor_msgs/msg/JointState", "nav_msgs/msg/Odometry",
        "tf2_msgs/msg/TFMessage", "rosgraph_msgs/msg/Clock",
    }
    for module in MODULES:
        for cls in (getattr(module, n) for n in module.__all__):
            assert cls.__msgtype__.split("/")[0] == module.__name__.rsplit(".", 1)[1]
            assert cls.__msgtype__.rsplit("/", 1)[1] == cls.__name__
            assert message_class(cls.__msgtype__) is cls


@pytest.mark.parametrize("cls", CLASSES, ids=lambda c: c.__msgtype__)
def test_fields_match_ros_definition(cls: type) -> None:
    ros_fields = [name for name, _ in STORE.fielddefs[cls.__msgtype__][1]]
    assert [f.name for f in dataclasses.fields(cls)] == ros_fields
    assert cls.__doc__


@pytest.mark.parametrize("cls", CLASSES, ids=lambda c: c.__msgtype__)
def test_slots_reject_unknown_attributes_as_rclpy(cls: type) -> None:
    msg = cls()
    with pytest.raises(AttributeError):
        msg.no_such_field = 1


def test_ros2_defaults() -> None:
    assert geometry_msgs.Quaternion() == geometry_msgs.Quaternion(0.0, 0.0, 0.0, 1.0)
    assert geometry_msgs.Pose().orientation.w == 1.0
    assert nav_msgs.Odometry().pose.covariance == [0.0] * 36
    assert nav_msgs.Odometry().twist.covariance == [0.0] * 36
    js = sensor_msgs.JointState()
    assert (js.name, js.position, js.velocity, js.effort) == ([], [], [], [])
    a, b = sensor_msgs.JointState(), sensor_msgs.JointState()
    a.name.append("j1")
    a.header.stamp.sec = 3
    assert b.name == [] and b.header.stamp.sec == 0  # defaults are never shared
    assert std_msgs.String().data == "" and rosgraph_msgs.Clock().clock == builtin_interfaces.Time()


def test_repr_as_rclpy() -> None:
    assert repr(geometry_msgs.Vector3()) == "geometry_msgs.msg.Vector3(x=0.0, y=0.0, z=0.0)"
    assert repr(std_msgs.Header(frame_id="map")) == (
        "std_msgs.msg.Header(stamp=builtin_interfaces.msg.Time(sec=0, nanosec=0), frame_id='map')")
    assert repr(sensor_msgs.JointState(name=["j"], position=[1.5])).endswith(
        "name=['j'], position=[1.5], velocity=[], effort=[])")
