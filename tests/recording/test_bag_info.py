"""``robotmodel bag info`` field by field: against what the files were written with, rosbags' reading, and rosbag.

The recordings are written here with rosbags' writers (ROS 1 .bag uncompressed, bz2 and lz4
in several chunks; ROS 2 folders with db3 and MCAP storage; the bare MCAP and db3 files of
those folders) from messages whose times and counts the test chooses. Each printed field is
checked against those values and against rosbags' own reading of the same file; the ROS 1
compression line against Debian's rosbag (``rosbag info``'s own code), where installed.
"""

from __future__ import annotations

import os
import re
import subprocess
import sys
import time
from pathlib import Path

import pytest

from robotmodel.recording import bag_info

T0 = 1_700_000_000_123_456_789
CHATTER = [T0 + i * 10_000_000 for i in range(300)]  # every 10 ms
COUNT = [T0 + i * 10_000_000 + 5 for i in range(0, 300, 3)]  # every 30 ms, 5 ns later
KINDS = ("bag-none", "bag-bz2", "bag-lz4", "db3-folder", "mcap-folder", "mcap-bare", "db3-bare")


@pytest.fixture(scope="module")
def bags(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Path]:
    from rosbags.rosbag1 import Writer as Writer1
    from rosbags.rosbag2 import StoragePlugin
    from rosbags.rosbag2 import Writer as Writer2
    from rosbags.typesys import Stores, get_typestore

    root = tmp_path_factory.mktemp("bags")
    out: dict[str, Path] = {}
    ros1 = get_typestore(Stores.ROS1_NOETIC)
    for kind, compression in (("bag-none", None), ("bag-bz2", "BZ2"), ("bag-lz4", "LZ4")):
        path = root / f"{kind}.bag"
        writer = Writer1(path)
        writer.chunk_threshold = 4096  # several chunks
        if compression:
            writer.set_compression(getattr(Writer1.CompressionFormat, compression))
        with writer:
            _write(writer, ros1, ros1.serialize_ros1)
        out[kind] = path
    ros2 = get_typestore(Stores.ROS2_JAZZY)
    for kind, plugin in (("db3-folder", StoragePlugin.SQLITE3), ("mcap-folder", StoragePlugin.MCAP)):
        path = root / kind
        with Writer2(path, version=8, storage_plugin=plugin) as writer:
            _write(writer, ros2, ros2.serialize_cdr)
        out[kind] = path
    out["mcap-bare"] = next((root / "mcap-folder").glob("*.mcap"))
    out["db3-bare"] = next((root / "db3-folder").glob("*.db3"))
    return out


def _write(writer, store, serialize) -> None:
    chatter = writer.add_connection("/chatter", "std_msgs/msg/String", typestore=store)
    count = writer.add_connection("/a/count", "std_msgs/msg/Int32", typestore=store)
    string, int32 = store.types["std_msgs/msg/String"], store.types["std_msgs/msg/Int32"]
    for i, t in enumerate(CHATTER):
        writer.write(chatter, t, serialize(string(data=f"hello world {i}"), "std_msgs/msg/String"))
        if i % 3 == 0:
            writer.write(count, t + 5, serialize(int32(data=i), "std_msgs/msg/Int32"))


def _cli(path: Path) -> dict[str, str]:
    env = {**os.environ, "TZ": "UTC"}
    proc = subprocess.run([sys.executable, "-m", "robotmodel.cli.main", "bag", "info", str(path)], env=env,
                          capture_output=True, text=True, timeout=60, check=True)
    fields: dict[str, str] = {}
    key = ""
    for line in proc.stdout.splitlines()[1:]:
        if line.startswith(" "):
            fields[key] += "\n" + line.strip()
        else:
            key, _, value = line.partition(":")
            fields[key] = value.strip()
    return fields


def _utc(ns: int) -> str:
    seconds, fraction = divmod(ns, 1_000_000_000)
    return f"{time.strftime('%b %e %Y %H:%M:%S', time.gmtime(seconds))}.{fraction:09d} ({seconds}.{fraction:09d})"


@pytest.mark.parametrize("kind", KINDS)
def test_bag_info_fields_match_the_written_messages_and_rosbags(kind: str, bags: dict[str, Path]) -> None:
    from rosbags.rosbag1 import Reader as Reader1
    from rosbags.rosbag2 import Reader as Reader2

    path = bags[kind]
    fields = _cli(path)
    start, end = min(CHATTER), max(COUNT[-1], CHATTER[-1])
    # What was written.
    assert fields["Start"] == _utc(start) and fields["End"] == _utc(end)
    assert fields["Duration"] == f"{(end - start) // 10**9}.{(end - start) % 10**9:09d}s"
    assert fields["Messages"] == str(len(CHATTER) + len(COUNT))
    serialization = "ros1" if kind.startswith("bag") else "cdr"
    assert fields["Topic information"].splitlines() == [
        f"Topic: /a/count | Type: std_msgs/msg/Int32 | Count: {len(COUNT)} | Serialization Format: {serialization}",
        f"Topic: /chatter | Type: std_msgs/msg/String | Count: {len(CHATTER)} | Serialization Format: {serialization}"]
    assert fields["Service"] == "0"
    storage = {"bag": "rosbag_v2", "db3": "sqlite3", "mcap": "mcap"}[kind.split("-", maxsplit=1)[0]]
    assert fields["Storage id"] == storage
    files = [p for p in (path.iterdir() if path.is_dir() else [path]) if p.is_file()]
    size = sum(p.stat().st_size for p in files)
    assert fields["Bag size"] == (f"{size} B" if size < 1024 else f"{size / 1024:.1f} KiB" if size < 2**20
                                  else f"{size / 2**20:.1f} MiB")
    listed = fields["Files"].splitlines()
    assert listed == ([p.name for p in files if p.name != "metadata.yaml"] if path.is_dir() else [str(path)])
    # rosbags' reading of the same file (its end time is one nanosecond after the last message).
    reader = Reader1(path) if kind.startswith("bag") else Reader2(path)
    with reader:
        info = bag_info(path)
        assert (info.start_ns, info.end_ns + 1, info.message_count) == (
            reader.start_time, reader.end_time, reader.message_count)
        assert {t.name: (t.msgtype, t.count) for t in info.topics} == {
            name: (t.msgtype, t.msgcount) for name, t in reader.topics.items()}
        if not kind.startswith("bag"):
            assert fields["ROS Distro"] == (reader.ros_distro or "unknown")


def _rosbag_compression(path: Path) -> str | None:
    """The compression line of Debian's ROS 1 rosbag (its Bag.__str__), or None without it."""
    code = "import sys, rosbag; print(rosbag.Bag(sys.argv[1]))"
    try:
        proc = subprocess.run(["/usr/bin/python3", "-c", code, str(path)], capture_output=True, text=True,
                              timeout=60, check=False)
    except FileNotFoundError:
        return None
    m = re.search(r"^compression:\s+(.*)$", proc.stdout, re.M)
    return m.group(1).strip() if proc.returncode == 0 and m else None


@pytest.mark.parametrize("kind", ["bag-none", "bag-bz2", "bag-lz4"])
def test_ros1_compression_line_is_rosbag_infos(kind: str, bags: dict[str, Path]) -> None:
    expected = _rosbag_compression(bags[kind])
    if expected is None:
        pytest.skip("Debian's ROS 1 rosbag (python3-rosbag) is not installed")
    assert _cli(bags[kind])["Compression"] == expected
    chunks = re.search(r"\[(\d+)/(\d+) chunks", expected)
    assert chunks is not None and int(chunks.group(2)) > 1  # the bags have several chunks


def test_not_a_recording_is_one_line(tmp_path: Path) -> None:
    path = tmp_path / "notes.txt"
    path.write_text("hello\n")
    proc = subprocess.run([sys.executable, "-m", "robotmodel.cli.main", "bag", "info", str(path)],
                          capture_output=True, text=True, timeout=60, check=False)
    assert proc.returncode == 1
    assert proc.stderr.splitlines() == [f"robotmodel bag: error: {path}: not a recording (neither a ROS 1 bag, "
                                        "an MCAP file nor a ROS 2 sqlite3 bag)"]


def test_bag_record_is_record() -> None:
    from robotmodel.cli.main import build_parser

    parser = build_parser()
    bag = vars(parser.parse_args(["bag", "record", "-a", "-O", "run", "/tf", "--flush-interval", "0.5"]))
    plain = vars(parser.parse_args(["record", "-a", "-O", "run", "/tf", "--flush-interval", "0.5"]))
    assert bag.pop("verb") == "record" and bag.pop("command") == "bag" and plain.pop("command") == "record"
    assert bag == plain
