"""Real recordings in every format, written with rosbags' and mcap's own writers (not robotmodel's).

A recording is a list of :class:`Msg` (topic, log time, what); :func:`write` writes it
as a ROS 1 bag, a ROS 2 sqlite3 or MCAP bag folder, a bare .db3 or a bare .mcap.
"""

from __future__ import annotations

import shutil
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from rosbags.typesys import Stores, get_types_from_msg, get_typestore

FORMATS = ("ros1", "db3_folder", "mcap_folder", "db3", "mcap")
NS = 1_000_000_000

TS2 = get_typestore(Stores.ROS2_JAZZY)
TS1 = get_typestore(Stores.ROS1_NOETIC)
if "tf2_msgs/msg/TFMessage" not in TS1.types:
    TS1.register(get_types_from_msg("geometry_msgs/TransformStamped[] transforms", "tf2_msgs/msg/TFMessage"))

TYPES = {"tf": "tf2_msgs/msg/TFMessage", "js": "sensor_msgs/msg/JointState", "str": "std_msgs/msg/String"}


@dataclass(frozen=True)
class Msg:
    """One message: ``kind`` tf (list of (parent, child, stamp_ns, pose7)), js ((stamp, names, positions)), str,
    or raw (the serialized bytes as given, for messages that do not decode; name the topic's type in ``types``)."""

    topic: str
    log_ns: int
    kind: str
    value: Any


def _stamp(ts: Any, ns: int, ros1: bool) -> Any:
    if ros1:
        return ts.types["builtin_interfaces/msg/Time"](sec=ns // NS, nanosec=ns % NS)
    return ts.types["builtin_interfaces/msg/Time"](sec=ns // NS, nanosec=ns % NS)


def _header(ts: Any, ns: int, frame: str, ros1: bool) -> Any:
    H = ts.types["std_msgs/msg/Header"]
    if ros1:
        return H(seq=0, stamp=_stamp(ts, ns, True), frame_id=frame)
    return H(stamp=_stamp(ts, ns, False), frame_id=frame)


def build(ts: Any, m: Msg, ros1: bool) -> Any:
    """The rosbags message object of ``m`` in typestore ``ts``."""
    T = ts.types
    if m.kind == "tf":
        transforms = []
        for parent, child, stamp_ns, p in m.value:
            transforms.append(T["geometry_msgs/msg/TransformStamped"](
                header=_header(ts, stamp_ns, parent, ros1), child_frame_id=child,
                transform=T["geometry_msgs/msg/Transform"](
                    translation=T["geometry_msgs/msg/Vector3"](x=p[0], y=p[1], z=p[2]),
                    rotation=T["geometry_msgs/msg/Quaternion"](x=p[3], y=p[4], z=p[5], w=p[6]))))
        return T["tf2_msgs/msg/TFMessage"](transforms=transforms)
    if m.kind == "js":
        import numpy as np

        stamp_ns, names, positions = m.value
        return T["sensor_msgs/msg/JointState"](
            header=_header(ts, stamp_ns, "", ros1), name=list(names),
            position=np.asarray(positions, dtype=np.float64), velocity=np.zeros(0), effort=np.zeros(0))
    return T["std_msgs/msg/String"](data=m.value)


def serialized(ts: Any, m: Msg, msgtype: str, ros1: bool) -> bytes:
    """The bytes written for ``m``: its value for raw messages, else the serialized message."""
    if m.kind == "raw":
        return bytes(m.value)
    if ros1:
        return bytes(ts.serialize_ros1(build(ts, m, True), msgtype))
    return bytes(ts.serialize_cdr(build(ts, m, False), msgtype))


def topics_of(msgs: Sequence[Msg]) -> dict[str, str]:
    return {m.topic: TYPES[m.kind] for m in msgs}


def write(path: Path, fmt: str, msgs: Sequence[Msg], types: dict[str, str] | None = None) -> Path:
    """Write ``msgs`` as ``fmt``; returns what to open (a file or a folder)."""
    types = types or topics_of(msgs)
    if fmt == "ros1":
        from rosbags.rosbag1 import Writer as Writer1

        out = path.with_suffix(".bag")
        with Writer1(out) as w:
            conns = {t: w.add_connection(t, ty, typestore=TS1) for t, ty in types.items()}
            for m in msgs:
                w.write(conns[m.topic], m.log_ns, serialized(TS1, m, types[m.topic], True))
        return out
    if fmt in ("db3_folder", "mcap_folder", "db3"):
        from rosbags.rosbag2 import StoragePlugin, Writer

        plugin = StoragePlugin.MCAP if fmt == "mcap_folder" else StoragePlugin.SQLITE3
        folder = path.with_name(path.name + "_" + fmt)
        with Writer(folder, version=9, storage_plugin=plugin) as w:
            conns = {t: w.add_connection(t, ty, typestore=TS2) for t, ty in types.items()}
            for m in msgs:
                w.write(conns[m.topic], m.log_ns, serialized(TS2, m, types[m.topic], False))
        if fmt != "db3":
            return folder
        (db,) = folder.glob("*.db3")
        out = path.with_suffix(".db3")
        shutil.copy(db, out)
        shutil.rmtree(folder)
        return out
    if fmt == "mcap":
        return write_mcap(path.with_suffix(".mcap"), msgs, types)
    raise ValueError(fmt)


def write_mcap(out: Path, msgs: Sequence[Msg], types: dict[str, str], chunk_size: int = 1 << 20) -> Path:
    """A bare MCAP (ros2 profile, CDR) through mcap's own Writer."""
    from mcap.writer import Writer

    with out.open("wb") as f:
        w = Writer(f, chunk_size=chunk_size)
        w.start(profile="ros2", library="tests")
        channels = {}
        for topic, ty in types.items():
            sid = w.register_schema(name=ty, encoding="ros2msg",
                                    data=TS2.generate_msgdef(ty, ros_version=2)[0].encode())
            channels[topic] = w.register_channel(topic=topic, message_encoding="cdr", schema_id=sid)
        for m in msgs:
            data = serialized(TS2, m, types[m.topic], False)
            w.add_message(channels[m.topic], log_time=m.log_ns, publish_time=m.log_ns, data=data)
        w.finish()
    return out
