"""``robotmodel record`` and the MCAP writer: files rosbags and mcap read, a live session that gives FK
back, proper close on SIGINT/SIGTERM, and crash (kill -9) tolerance up to the last flushed chunk."""

from __future__ import annotations

import signal
import struct
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from handfk import HandFK
from recording.bagfiles import TS2
from recording.test_load import mat

from robotmodel.recording import McapWriter, bag_info, load_recording, qos_yaml

URDF = """<?xml version="1.0"?>
<robot name="rec2">
  <link name="base"/><link name="upper"/><link name="slider"/><link name="finger"/><link name="tool"/>
  <joint name="shoulder" type="revolute"><parent link="base"/><child link="upper"/>
    <origin xyz="0 0 0.5" rpy="0.1 0 0"/><axis xyz="0 1 0"/><limit lower="0.3" upper="1.1" effort="1" velocity="1"/>
  </joint>
  <joint name="extend" type="prismatic"><parent link="upper"/><child link="slider"/>
    <origin xyz="0.3 0 0"/><axis xyz="1 0 0"/><limit lower="0.1" upper="0.5" effort="1" velocity="1"/></joint>
  <joint name="finger_joint" type="revolute"><parent link="slider"/><child link="finger"/>
    <origin xyz="0.1 0 0"/><axis xyz="0 0 1"/><limit lower="-3" upper="3" effort="1" velocity="1"/>
    <mimic joint="shoulder" multiplier="-2" offset="0.1"/></joint>
  <joint name="tool_mount" type="fixed"><parent link="finger"/><child link="tool"/>
    <origin xyz="0.05 0 0" rpy="0 0 1.5707963267948966"/></joint>
</robot>
"""
TF = "tf2_msgs/msg/TFMessage"


def readable(path: Path) -> list[tuple[str, int, bytes]]:
    """Messages mcap's stream reader gets from a file, stopping at the first incomplete record (a crash)."""
    from mcap.exceptions import McapError
    from mcap.records import Channel, Message
    from mcap.stream_reader import StreamReader

    channels: dict[int, str] = {}
    out = []
    try:
        with path.open("rb") as f:
            for record in StreamReader(f).records:
                if isinstance(record, Channel):
                    channels[record.id] = record.topic
                elif isinstance(record, Message):
                    out.append((channels[record.channel_id], record.log_time, record.data))
    except (McapError, EOFError, ValueError, struct.error):
        pass  # the cut record; every record before it counts
    return out


def tf_span_s(msgs: list[tuple[str, int, bytes]]) -> float:
    stamps = [t for topic, t, _ in msgs if topic == "/tf"]
    return (max(stamps) - min(stamps)) / 1e9 if len(stamps) > 1 else 0.0


def test_writer_output_read_by_rosbags_and_mcap(tmp_path):
    from mcap.reader import make_reader
    from rosbags.interfaces import QosDurability
    from rosbags.rosbag2 import Reader

    path = tmp_path / "w.mcap"
    Msg = TS2.types
    def tf(child: str, ns: int) -> bytes:
        t = Msg["geometry_msgs/msg/TransformStamped"](
            header=Msg["std_msgs/msg/Header"](stamp=Msg["builtin_interfaces/msg/Time"](sec=ns // 10**9,
                                                                                       nanosec=ns % 10**9),
                                              frame_id="base"),
            child_frame_id=child, transform=Msg["geometry_msgs/msg/Transform"](
                translation=Msg["geometry_msgs/msg/Vector3"](x=1.0, y=0.0, z=0.0),
                rotation=Msg["geometry_msgs/msg/Quaternion"](x=0.0, y=0.0, z=0.0, w=1.0)))
        return bytes(TS2.serialize_cdr(Msg[TF](transforms=[t]), TF))

    with McapWriter(path) as w:
        w.add_topic("/tf", TF, qos_yaml(100))
        w.add_topic("/tf_static", TF, qos_yaml(1, transient_local=True))
        w.write("/tf_static", 5, tf("cam", 5))
        for k in range(10):
            w.write("/tf", 10 + k, tf("arm", 10**9 + k))
    with Reader(path) as r:
        got = [(c.topic, t, TS2.deserialize_cdr(raw, c.msgtype).transforms[0].child_frame_id)
               for c, t, raw in r.messages()]
        qos = {c.topic: c.ext.offered_qos_profiles[0].durability for c in r.connections}
    assert got[0] == ("/tf_static", 5, "cam") and len(got) == 11
    assert qos == {"/tf": QosDurability.VOLATILE, "/tf_static": QosDurability.TRANSIENT_LOCAL}
    with path.open("rb") as f:
        reader = make_reader(f)
        assert reader.get_header().profile == "ros2"
        assert reader.get_summary().statistics.message_count == 11
        assert {s.name for s in reader.get_summary().schemas.values()} == {TF}
    assert sorted(load_recording(path, progress=False).buffer.frames()) == ["arm", "cam"]


def start_session(bus: Any, tmp_path: Path, out: Path, *extra: str) -> tuple[Any, Any, Any]:
    urdf = tmp_path / "rec2.urdf"
    urdf.write_text(URDF)
    rec = bus.robotmodel("record", "-o", str(out), "--flush-interval", "0.2", *extra)
    rec.wait_line(r"Subscribed to topic '/tf'", stream="err", timeout=60)
    rsp = bus.robotmodel("robot-state-publisher", str(urdf))
    jsp = bus.robotmodel("joint-state-publisher", str(urdf), "--rate", "50")
    return rec, rsp, jsp


def wait_file(rec: Any, out: Path, predicate: Any, what: str, timeout: float = 60.0) -> list[tuple[str, int, bytes]]:
    found: list[list[tuple[str, int, bytes]]] = []

    def check() -> bool:
        msgs = readable(out) if out.exists() else []
        if predicate(msgs):
            found.append(msgs)
            return True
        return False

    # Woken by the recorder's log lines or every 0.2 s; the deadline fails the test.
    rec.wait_for(check, timeout, what)
    return found[0]


@pytest.mark.parametrize("sig", [signal.SIGINT, signal.SIGTERM], ids=["SIGINT", "SIGTERM"])
def test_live_session_recorded_reproduces_fk(bus, tmp_path, sig):
    out = tmp_path / "session.mcap"
    rec, rsp, jsp = start_session(bus, tmp_path, out)
    wait_file(rec, out, lambda m: tf_span_s(m) >= 2.0 and any(t == "/robot_description" for t, _, _ in m),
              "2 s of /tf and the robot description in the file")
    assert rec.stop(sig) == 0, rec.err[-5:]
    assert any("Recording stopped" in line for line in rec.err)
    for proc in (rsp, jsp):
        assert proc.stop() == 0

    # A properly closed file: summary present, read by rosbags and by mcap's indexed reader.
    from mcap.reader import make_reader
    from rosbags.rosbag2 import Reader

    with out.open("rb") as f:
        summary = make_reader(f).get_summary()
    assert summary is not None and summary.statistics.message_count > 0
    with Reader(out) as r:
        topics = {c.topic: c.msgtype for c in r.connections}
        states = [TS2.deserialize_cdr(raw, c.msgtype) for c, _, raw in r.messages()
                  if c.topic == "/joint_states"]
    assert topics["/tf"] == TF and topics["/joint_states"] == "sensor_msgs/msg/JointState"
    loaded = load_recording(out, progress=False)
    assert loaded.robot_description is not None and not loaded.from_joint_states
    assert loaded.end_ns - loaded.start_ns >= 1_500_000_000
    fk = HandFK(loaded.robot_description)
    checked = 0
    for msg in states:
        t = msg.header.stamp.sec * 10**9 + msg.header.stamp.nanosec
        if not loaded.start_ns <= t <= loaded.end_ns:
            continue
        values = dict(zip(msg.name, msg.position.tolist(), strict=True))
        assert values["shoulder"] == pytest.approx(0.7) and values["extend"] == pytest.approx(0.3)
        want = fk.poses(values)
        for link in ("upper", "finger", "tool"):
            pose, used = loaded.buffer.lookup_ns("base", link, t)
            assert used == t
            np.testing.assert_allclose(mat(pose), want[link], atol=1e-9)
        checked += 1
    assert checked >= 50  # 2 s at 50 Hz, give or take the edges


def test_kill_9_leaves_every_flushed_chunk_readable(bus, tmp_path):
    out = tmp_path / "crash.mcap"
    rec, rsp, jsp = start_session(bus, tmp_path, out)
    before = wait_file(rec, out, lambda m: sum(t == "/tf" for t, _, _ in m) >= 20, "20 /tf messages flushed")
    rec.kill()  # SIGKILL: no summary, no footer
    for proc in (rsp, jsp):
        assert proc.stop() == 0
    after = readable(out)
    assert after[:len(before)] == before  # nothing flushed is lost
    # The file has no summary (rosbags refuses it; our loader says so in one line) ...
    from robotmodel.errors import RecordingError

    with pytest.raises(RecordingError, match=r"truncated or corrupt MCAP .*message\(s\) readable"):
        load_recording(out, progress=False)
    # ... and its messages rebuilt into a new file with mcap's writer load as a recording.
    from mcap.writer import Writer

    fixed = tmp_path / "recovered.mcap"
    with fixed.open("wb") as f:
        w = Writer(f)
        w.start(profile="ros2", library="test")
        channels = {}
        for topic, msgtype in (("/tf", TF), ("/tf_static", TF), ("/joint_states", "sensor_msgs/msg/JointState"),
                               ("/robot_description", "std_msgs/msg/String")):
            sid = w.register_schema(name=msgtype, encoding="ros2msg",
                                    data=TS2.generate_msgdef(msgtype, ros_version=2)[0].encode())
            channels[topic] = w.register_channel(topic=topic, message_encoding="cdr", schema_id=sid)
        for topic, t, data in after:
            w.add_message(channels[topic], log_time=t, publish_time=t, data=data)
        w.finish()
    loaded = load_recording(fixed, progress=False)
    assert loaded.transforms >= 20


def test_other_topics_are_subscribed_once_the_graph_names_their_type(bus, tmp_path, monkeypatch):
    import threading
    import time

    from robotmodel.bus import Node
    from robotmodel.msgs import String

    for key in ("ROBOTMODEL_ZENOH_PORT", "ROS_DOMAIN_ID"):
        monkeypatch.setenv(key, bus.env[key])
    out = tmp_path / "chatter.mcap"
    rec = bus.robotmodel("record", "-o", str(out), "--flush-interval", "0.2", "/chatter", "/tf")
    rec.wait_line(r"Subscribed to topic '/tf'", stream="err", timeout=60)
    pace = threading.Event()
    with Node("talker") as node:
        pub = node.create_publisher(String, "/chatter", 10)
        deadline = time.monotonic() + 60
        while not any(t == "/chatter" for t, _, _ in (readable(out) if out.exists() else [])):
            assert time.monotonic() < deadline, f"/chatter never recorded: {rec.err[-5:]}"
            pub.publish(String(data="hello"))
            pace.wait(0.1)  # publishing pace, not a wait for the condition
    # Stopped as the talker leaves the graph: /chatter was subscribed from the recorder's discovery
    # thread, whose zenoh callback thread once outlived the session and aborted the exit (SIGABRT).
    assert rec.stop(signal.SIGINT) == 0, rec.err[-20:]
    assert any("Subscribed to topic '/chatter'" in line for line in rec.err)
    from rosbags.rosbag2 import Reader

    with Reader(out) as r:
        types = {c.topic: c.msgtype for c in r.connections}
        texts = {TS2.deserialize_cdr(raw, c.msgtype).data for c, _, raw in r.messages() if c.topic == "/chatter"}
    assert types == {"/chatter": "std_msgs/msg/String", "/tf": TF}
    assert texts == {"hello"}


def test_existing_output_is_not_overwritten(tmp_path):
    import subprocess
    import sys

    out = tmp_path / "there.mcap"
    out.write_bytes(b"keep")
    proc = subprocess.run([sys.executable, "-m", "robotmodel.cli.main", "record", "-o", str(out)], check=False,
                          capture_output=True, text=True, timeout=60)
    assert proc.returncode == 1 and "already exists" in proc.stderr
    assert out.read_bytes() == b"keep"


def test_quiet_spells_are_flushed_when_due(tmp_path):
    # A message followed by silence reaches the file at the next due flush_if_due, not at the next message.
    data = bytes(TS2.serialize_cdr(TS2.types["std_msgs/msg/String"](data="robot"), "std_msgs/msg/String"))
    for due, seen in ((False, 0), (True, 1)):
        path = tmp_path / f"quiet{due}.mcap"
        w = McapWriter(path, flush_every_s=3600.0)
        w.add_topic("/robot_description", "std_msgs/msg/String", qos_yaml(1, transient_local=True))
        w.write("/robot_description", 1, data)
        assert readable(path) == []
        if due:
            w._next_flush = 0  # as if the interval had passed since the last flush
        w.flush_if_due()
        assert len(readable(path)) == seen
        w.close()
        assert len(readable(path)) == 1


@pytest.mark.parametrize("words", [["bad topic"], ["--connect", "nonsense"], ["/tf", "--connect", "foo/127.0.0.1:7447"]])
def test_record_that_cannot_start_leaves_no_file(tmp_path, words):
    import subprocess
    import sys

    out = tmp_path / "never.mcap"
    proc = subprocess.run([sys.executable, "-m", "robotmodel.cli.main", "record", "-o", str(out), *words],
                          check=False, capture_output=True, text=True, timeout=60)
    assert proc.returncode == 1, proc.stderr
    assert len(proc.stderr.splitlines()) == 1 and "Traceback" not in proc.stderr
    assert not out.exists() and list(tmp_path.iterdir()) == []


def test_writer_block_that_fails_leaves_no_file_and_never_overwrites(tmp_path):
    from robotmodel.errors import RecordingError

    path = tmp_path / "failed.mcap"
    with pytest.raises(ValueError, match="start failed"), McapWriter(path):
        assert path.exists()
        raise ValueError("start failed")
    assert not path.exists()
    # Once a message is in, the file is the recording: kept (and finished) whatever ends the block.
    data = bytes(TS2.serialize_cdr(TS2.types["std_msgs/msg/String"](data="robot"), "std_msgs/msg/String"))
    with pytest.raises(ValueError, match="later"), McapWriter(path) as w:
        w.add_topic("/robot_description", "std_msgs/msg/String")
        w.write("/robot_description", 1, data)
        raise ValueError("later")
    assert len(readable(path)) == 1
    before = path.read_bytes()
    with pytest.raises(RecordingError, match="already exists"):
        McapWriter(path)
    assert path.read_bytes() == before


def test_record_all_topics_with_rosbags_output_name(bus, tmp_path, monkeypatch):
    """``record -a -O NAME`` (rosbag's and ros2 bag's flags): every topic, also ones appearing later;
    hidden ones left out, as ros2 bag does without --include-hidden-topics."""
    import threading
    import time

    from robotmodel.bus import Node
    from robotmodel.msgs import String

    for key in ("ROBOTMODEL_ZENOH_PORT", "ROS_DOMAIN_ID"):
        monkeypatch.setenv(key, bus.env[key])
    rec = bus.robotmodel("record", "-a", "-O", "everything", "--flush-interval", "0.2")
    rec.wait_line(r"Recording to 'everything\.mcap'", stream="err", timeout=60)
    out = tmp_path / "everything.mcap"
    pace = threading.Event()
    with Node("talker") as node:  # started after the recorder: found by the graph, as it appears
        pubs = [node.create_publisher(String, name, 10) for name in ("/chatter", "/robot/status", "/_hidden")]
        deadline = time.monotonic() + 60
        while {t for t, _, _ in (readable(out) if out.exists() else [])} < {"/chatter", "/robot/status"}:
            assert time.monotonic() < deadline, f"topics never recorded: {rec.err[-5:]}"
            for pub in pubs:
                pub.publish(String(data="hello"))
            pace.wait(0.1)  # publishing pace, not a wait for the condition
    assert rec.stop(signal.SIGINT) == 0, rec.err[-20:]
    from rosbags.rosbag2 import Reader

    with Reader(out) as r:
        topics = {c.topic for c in r.connections}
    assert {"/chatter", "/robot/status", "/tf", "/tf_static", "/joint_states", "/robot_description"} <= topics
    assert not any(part.startswith("_") for topic in topics for part in topic.split("/"))


def test_record_output_forms_and_tf_echo_alias(tmp_path):
    import subprocess
    import sys

    def run(*words: str) -> subprocess.CompletedProcess[str]:
        return subprocess.run([sys.executable, "-m", "robotmodel.cli.main", *words], check=False,
                              capture_output=True, text=True, timeout=60, cwd=tmp_path)

    proc = run("record", "-o", "a.mcap", "-O", "b")
    assert proc.returncode == 2 and "not allowed with argument" in proc.stderr
    (tmp_path / "taken.mcap").write_bytes(b"keep")
    proc = run("record", "-O", "taken")  # NAME gets .mcap, as rosbag's -O NAME gets .bag
    assert proc.returncode == 1 and "taken.mcap already exists" in proc.stderr
    (tmp_path / "folder").mkdir()
    proc = run("bag", "record", "-o", "folder")  # ros2 bag record's text; the folder is left as it was
    assert proc.returncode == 1 and "Output folder 'folder' already exists." in proc.stderr
    assert list((tmp_path / "folder").iterdir()) == []
    proc = run("bag", "record", "-o", "never", "--connect", "nonsense")  # could not start: no folder left
    assert proc.returncode == 1 and not (tmp_path / "never").exists(), proc.stderr
    # ROS 1's tf_echo name runs tf2_echo.
    proc = run("tf_echo", "--help")
    assert proc.returncode == 0 and proc.stdout.startswith("Usage: tf2_echo source_frame target_frame")


def test_bag_record_writes_a_rosbag2_folder_as_ros2_bag_record(bus, tmp_path):
    """``bag record`` without -o: a ``rosbag2_YYYY_MM_DD-HH_MM_SS`` folder in the current directory with
    ``<name>_0.mcap`` and metadata.yaml, which rosbags' rosbag2 reader (it needs the metadata) opens;
    the metadata's counts and times are those of the messages in the MCAP file, read with mcap."""
    import datetime
    import re

    from rosbags.rosbag2 import Reader

    urdf = tmp_path / "rec2.urdf"
    urdf.write_text(URDF)
    before = datetime.datetime.now().replace(microsecond=0)
    rec = bus.robotmodel("bag", "record", "--flush-interval", "0.2", "/tf", "/robot_description")  # cwd: tmp_path
    rec.wait_line(r"Subscribed to topic '/tf'", stream="err", timeout=60)
    rsp = bus.robotmodel("robot-state-publisher", str(urdf))
    jsp = bus.robotmodel("joint-state-publisher", str(urdf), "--rate", "50")
    folders = [p for p in tmp_path.iterdir() if p.is_dir()]
    assert len(folders) == 1 and re.fullmatch(r"rosbag2_\d{4}_\d\d_\d\d-\d\d_\d\d_\d\d", folders[0].name), folders
    folder = folders[0]
    named = datetime.datetime.strptime(folder.name, "rosbag2_%Y_%m_%d-%H_%M_%S")
    assert before <= named <= datetime.datetime.now()  # local time, as ros2 bag names it
    storage = folder / f"{folder.name}_0.mcap"
    wait_file(rec, storage, lambda m: tf_span_s(m) >= 0.5 and any(t == "/robot_description" for t, _, _ in m),
              "/tf and the robot description in the bag")
    assert rec.stop(signal.SIGINT) == 0, rec.err[-5:]
    for proc in (rsp, jsp):
        assert proc.stop() == 0
    msgs = readable(storage)
    with Reader(folder) as reader:
        assert reader.message_count == len(msgs)
        assert {c.topic: c.msgcount for c in reader.connections} == {
            t: sum(1 for m in msgs if m[0] == t) for t in ("/tf", "/robot_description")}
        assert reader.start_time == min(m[1] for m in msgs) and reader.end_time == max(m[1] for m in msgs) + 1
        assert {c.msgtype for c in reader.connections} == {TF, "std_msgs/msg/String"}
        assert reader.ros_distro == "jazzy" and not reader.compression_mode
    assert sorted(p.name for p in folder.iterdir()) == sorted(["metadata.yaml", storage.name])
    info = bag_info(folder)  # and robotmodel's own readers take the folder
    assert info.files == (storage.name,) and info.storage_id == "mcap" and info.message_count == len(msgs)
