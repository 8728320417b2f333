"""Bad recordings: one line naming the file and what was readable, never a traceback; rejected transforms counted."""

from __future__ import annotations

import math
import subprocess
import sys
from pathlib import Path

import pytest
from recording.bagfiles import NS, TS1, TS2, Msg, serialized, write, write_mcap

from robotmodel.errors import RecordingError
from robotmodel.recording import load_buffer, load_recording

T0 = 1_700_000_000 * NS


def tf_msgs(n: int) -> list[Msg]:
    out = []
    for k in range(n):
        t = T0 + k * 10_000_000
        out.append(Msg("/tf", t, "tf", [("odom", f"link_{j}", t, (0.1 * k, j, 0.0, 0.0, 0.0, 0.0, 1.0))
                                        for j in range(20)]))
    return out


def check_cli(path: Path, capsys_words: tuple[str, ...] = ()) -> str:
    """``robotmodel tf2-echo --bag PATH ...`` fails with exit 1 and one stderr line naming the file."""
    proc = subprocess.run([sys.executable, "-m", "robotmodel.cli.main", "tf2-echo", "--bag", str(path), "odom",
                           "link_0", "--time", "1700000000", *capsys_words], check=False, capture_output=True,
                          text=True, timeout=120)
    assert proc.returncode == 1, proc.stderr
    assert "Traceback" not in proc.stderr
    lines = proc.stderr.strip().splitlines()
    assert len(lines) == 1, proc.stderr
    assert str(path) in lines[0]
    assert proc.stdout == ""
    return lines[0]


def test_empty_file(tmp_path):
    path = tmp_path / "empty.mcap"
    path.write_bytes(b"")
    with pytest.raises(RecordingError, match="empty"):
        load_buffer(path)
    check_cli(path)


def test_wrong_format(tmp_path):
    path = tmp_path / "notes.bag"
    path.write_text("these are not the transforms you are looking for\n")
    with pytest.raises(RecordingError, match="not a recording"):
        load_buffer(path)
    assert "not a recording" in check_cli(path)


def test_missing_file_and_folder_without_metadata(tmp_path):
    with pytest.raises(RecordingError, match="cannot read"):
        load_buffer(tmp_path / "nothere.mcap")
    with pytest.raises(RecordingError, match=r"metadata\.yaml"):
        load_buffer(tmp_path)


def test_truncated_mcap_says_how_much_is_readable(tmp_path):
    path = write_mcap(tmp_path / "cut.mcap", tf_msgs(200), {"/tf": "tf2_msgs/msg/TFMessage"}, chunk_size=4096)
    data = path.read_bytes()
    path.write_bytes(data[: len(data) * 6 // 10])
    with pytest.raises(RecordingError) as info:
        load_buffer(path)
    text = str(info.value)
    assert str(path) in text and "truncated" in text
    readable = int(text.split(" message(s) readable", maxsplit=1)[0].rsplit(" ", 1)[1])
    assert 0 < readable < 200
    assert "\n" not in text
    check_cli(path)


def test_corrupt_chunk_in_mcap(tmp_path):
    path = write_mcap(tmp_path / "bad.mcap", tf_msgs(200), {"/tf": "tf2_msgs/msg/TFMessage"}, chunk_size=4096)
    data = bytearray(path.read_bytes())
    mid = len(data) // 2
    data[mid:mid + 64] = bytes(64)  # zeroes in the middle of a chunk's compressed bytes
    path.write_bytes(bytes(data))
    with pytest.raises(RecordingError) as info:
        load_buffer(path)
    assert str(path) in str(info.value) and "\n" not in str(info.value)
    check_cli(path)


@pytest.mark.parametrize("fmt", ["ros1", "db3"])
def test_truncated_bag_and_db3(tmp_path, fmt):
    path = write(tmp_path / "cut", fmt, tf_msgs(100))
    data = path.read_bytes()
    path.write_bytes(data[: len(data) // 2])
    with pytest.raises(RecordingError) as info:
        load_buffer(path)
    assert str(path) in str(info.value) and "\n" not in str(info.value)
    check_cli(path)


def test_topic_of_unexpected_type(tmp_path):
    msgs = [Msg("/tf", T0, "str", "not a TFMessage")]
    path = write(tmp_path / "typed", "mcap", msgs)
    with pytest.raises(RecordingError, match=r"topic /tf has type std_msgs/msg/String, expected tf2_msgs/msg/TFMessage"):
        load_buffer(path)
    check_cli(path)


def test_non_finite_transforms_skipped_with_a_count(tmp_path, caplog):
    msgs = tf_msgs(30)
    bad = {(3, 0), (3, 5), (17, 19), (29, 2)}
    for k, j in bad:
        parent, child, t, pose = msgs[k].value[j]
        value = [math.nan, math.inf, -math.inf, math.nan][len(child) % 4]
        msgs[k].value[j] = (parent, child, t, (pose[0], value, *pose[2:]))
    msgs[5].value[1] = (*msgs[5].value[1][:3], (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0))  # zero quaternion
    path = write(tmp_path / "nan", "mcap", msgs)
    loaded = load_recording(path, progress=False)
    assert loaded.skipped == len(bad) + 1
    assert loaded.transforms == 30 * 20 - len(bad) - 1
    assert "skipped 5 transform(s)" in caplog.text
    # A skipped sample is absent: the lookup at its stamp interpolates its neighbours.
    pose, _ = loaded.buffer.lookup_ns("odom", "link_5", T0 + 3 * 10_000_000)
    assert pose[:3] == pytest.approx((0.3, 5.0, 0.0))


TF_TYPE = "tf2_msgs/msg/TFMessage"


@pytest.mark.parametrize("fmt", ["ros1", "db3", "mcap"])
def test_undecodable_messages_are_skipped_and_counted(tmp_path, fmt, caplog):
    """A message that does not decode is skipped and counted; the rest of an intact file is read."""
    ros1 = fmt == "ros1"
    msgs = tf_msgs(300)
    cut = serialized(TS1 if ros1 else TS2, msgs[226], TF_TYPE, ros1)[:40]
    miscounted = bytearray(serialized(TS1 if ros1 else TS2, msgs[100], TF_TYPE, ros1))
    count_at = 0 if ros1 else 4  # the transform count (after CDR's encapsulation header)
    miscounted[count_at:count_at + 4] = (10**6).to_bytes(4, "little")  # same length as its neighbours
    msgs[226] = Msg("/tf", msgs[226].log_ns, "raw", cut)
    msgs[100] = Msg("/tf", msgs[100].log_ns, "raw", bytes(miscounted))
    msgs.insert(0, Msg("/tf_static", T0, "raw", b"\xff" * 8))
    msgs.insert(1, Msg("/robot_description", T0, "raw", b"\xff" * 8))
    types = {"/tf": TF_TYPE, "/tf_static": TF_TYPE, "/robot_description": "std_msgs/msg/String"}
    path = write(tmp_path / "one_bad", fmt, msgs, types)

    loaded = load_recording(path, progress=False)
    assert loaded.undecodable == 4
    assert loaded.messages == 302
    assert loaded.transforms == 298 * 20
    warnings = [r.getMessage() for r in caplog.records if "do not decode" in r.getMessage()]
    assert len(warnings) == 1 and "skipped 4 message(s)" in warnings[0] and str(path) in warnings[0]
    # Message 100 is left out: the lookup at its stamp interpolates messages 99 and 101.
    pose, _ = loaded.buffer.lookup_ns("odom", "link_3", T0 + 100 * 10_000_000)
    assert pose[:3] == pytest.approx((10.0, 3.0, 0.0))

    proc = subprocess.run([sys.executable, "-m", "robotmodel.cli.main", "tf2-echo", "--bag", str(path), "odom",
                           "link_3", "--time", f"{(T0 + 100 * 10_000_000) / NS:.2f}"], check=False,
                          capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr
    assert "Translation: [10.000, 3.000, 0.000]" in proc.stdout
    (line,) = proc.stderr.splitlines()
    assert "skipped 4 message(s) that do not decode" in line and "truncated" not in line


def test_db3_with_a_damaged_page_is_one_line(tmp_path):
    """A .db3 whose SQLite pages are damaged past what opening reads: one line naming the file, exit 1."""
    msgs = tf_msgs(100)
    msgs.insert(50, Msg("/robot_description", T0 + 495 * 10**6, "str", "Z" * 30000))  # spills into overflow pages
    path = write(tmp_path / "flipped", "db3", msgs)
    data = bytearray(path.read_bytes())
    page = int.from_bytes(data[16:18], "big")  # SQLite's header: the page size
    # An overflow page of the description (all its bytes after the 4-byte link are the text) whose
    # link to the next page is then bent out of the file: SQLite finds it only when reading the row.
    overflow = [k for k in range(len(data) // page) if data[k * page + 4:(k + 1) * page] == b"Z" * (page - 4)
                and int.from_bytes(data[k * page:k * page + 4], "big")]
    assert overflow
    data[overflow[0] * page:overflow[0] * page + 4] = (0x7FFFFFF0).to_bytes(4, "big")
    path.write_bytes(bytes(data))
    with pytest.raises(RecordingError, match=r"truncated or corrupt ROS 2 sqlite3 bag after \d+ message\(s\)"):
        load_buffer(path)
    assert "malformed" in check_cli(path)
