"""tf2-echo --bag, view-frames --bag and tf-export on real recordings, as subprocesses."""

from __future__ import annotations

import csv
import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from recording.bagfiles import write
from recording.test_load import DT, TICKS, expected_world_cam, scenario, stamp

from robotmodel.tf_ros._echo_args import euler_ypr


def run(*args: str, cwd: Path | None = None) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "robotmodel.cli.main", *args], check=False, capture_output=True,
                          text=True, timeout=120, cwd=cwd)


@pytest.fixture(scope="module")
def bag(tmp_path_factory) -> Path:
    return write(tmp_path_factory.mktemp("cli") / "run", "ros1", scenario())


def printed_blocks(text: str) -> list[tuple[str, list[float]]]:
    blocks = []
    for block in text.split("At time ")[1:]:
        when = block.splitlines()[0]
        numbers = [float(v) for v in re.search(r"Translation: \[(.*)\]", block).group(1).split(",")]
        blocks.append((when, numbers))
    return blocks


def test_tf2_echo_at_a_time(bag):
    t = stamp(5) + DT // 4
    proc = run("tf2-echo", "--bag", str(bag), "world", "cam", "--time", f"{t // 10**9}.{t % 10**9:09d}")
    assert proc.returncode == 0, proc.stderr
    ((when, translation),) = printed_blocks(proc.stdout)
    assert when == f"{t // 10**9}.{t % 10**9}"  # tf2_echo prints sec.nanosec unpadded
    want = expected_world_cam(t)
    assert translation == [round(v, 3) for v in want[:3, 3]]
    roll, pitch, yaw = euler_ypr(want[:3, :3].tolist())
    assert f"- Rotation: in RPY (radian) [{roll:.3f}, {pitch:.3f}, {yaw:.3f}]" in proc.stdout


def test_tf2_echo_relative_time_and_every(bag):
    proc = run("tf2-echo", "--bag", str(bag), "world", "cam", "--time=+0.1")
    assert proc.returncode == 0, proc.stderr
    assert printed_blocks(proc.stdout)[0][0] == f"{stamp(2) // 10**9}.{stamp(2) % 10**9}"
    proc = run("tf2-echo", "--bag", str(bag), "world", "cam", "--every", "0.25")
    assert proc.returncode == 0, proc.stderr
    span = stamp(TICKS - 1) - stamp(0)
    assert len(printed_blocks(proc.stdout)) == span // 250_000_000 + 1


def test_tf2_echo_failure_at_a_time_outside_the_recording(bag):
    proc = run("tf2-echo", "--bag", str(bag), "world", "cam", "--time", "1")
    assert proc.returncode == 1
    assert proc.stdout.startswith("Failure at ")
    assert "Lookup would require extrapolation into the past" in proc.stdout


def test_tf2_echo_bad_words(bag):
    proc = run("tf2-echo", "world", "cam", "--time", "3")
    assert proc.returncode == 2 and "need --bag" in proc.stderr
    proc = run("tf2-echo", "--bag", str(bag), "world", "cam", "--time", "soon")
    assert proc.returncode == 2 and proc.stderr.count("\n") == 1 and "--time" in proc.stderr
    proc = run("tf2-echo", "--bag", str(bag), "world", "cam", "--time", "3", "--every", "1")
    assert proc.returncode == 2


def test_view_frames_from_a_bag(bag, tmp_path):
    proc = run("view-frames", "--bag", str(bag), "-o", "tree", cwd=tmp_path)
    assert proc.returncode == 0, proc.stderr
    gv = (tmp_path / "tree.gv").read_text()
    for parent, child in (("world", "odom"), ("odom", "base"), ("base", "cam"), ("world", "map")):
        assert f'"{parent}" -> "{child}"' in gv
    assert "Listening" not in proc.stderr


def test_tf_export_csv_at_recorded_stamps_and_at_a_rate(bag, tmp_path):
    out = tmp_path / "poses.csv"
    proc = run("tf-export", "--bag", str(bag), "world", "cam", "-o", str(out))
    assert proc.returncode == 0, proc.stderr
    rows = list(csv.DictReader(out.open()))
    assert [int(r["stamp_ns"]) for r in rows] == [stamp(k) for k in range(TICKS)]
    for r in rows:
        t = int(r["stamp_ns"])
        assert r["time_s"] == f"{t // 10**9}.{t % 10**9:09d}"
        np.testing.assert_allclose([float(r[c]) for c in ("x", "y", "z")], expected_world_cam(t)[:3, 3], atol=1e-12)
    proc = run("tf-export", "--bag", str(bag), "world", "cam", "-o", str(out), "--rate", "7")
    assert proc.returncode == 0, proc.stderr
    stamps = [int(r["stamp_ns"]) for r in csv.DictReader(out.open())]
    assert stamps[0] == stamp(0) and np.all(np.diff(stamps) == round(1e9 / 7))
    assert stamps[-1] <= stamp(TICKS - 1) < stamps[-1] + round(1e9 / 7)


def test_tf_export_errors_leave_no_file(bag, tmp_path):
    out = tmp_path / "poses.csv"
    proc = run("tf-export", "--bag", str(bag), "world", "nowhere", "-o", str(out))
    assert proc.returncode == 1 and "nowhere" in proc.stderr and "Traceback" not in proc.stderr
    assert not out.exists()
    try:
        import pyarrow  # noqa: F401
    except ImportError:
        proc = run("tf-export", "--bag", str(bag), "world", "cam", "-o", str(tmp_path / "p.parquet"))
        assert proc.returncode == 1 and "pyarrow" in proc.stderr
        assert not list(tmp_path.glob("*parquet*"))
    else:
        proc = run("tf-export", "--bag", str(bag), "world", "cam", "-o", str(tmp_path / "p.parquet"))
        assert proc.returncode == 0


def test_view_frames_from_a_bag_with_a_control_character_in_a_frame_name(tmp_path):
    import yaml
    from recording.bagfiles import Msg

    t0 = 1_700_000_000 * 10**9
    msgs = [Msg("/tf", t0 + k * 10**8, "tf", [("odom", "cam\x07era", t0 + k * 10**8, (k, 0, 0, 0, 0, 0, 1)),
                                              ("odom", 'b"ase', t0 + k * 10**8, (0, k, 0, 0, 0, 0, 1))])
            for k in range(5)]
    path = write(tmp_path / "odd", "mcap", msgs)
    proc = run("view-frames", "--bag", str(path), "-o", "tree", cwd=tmp_path)
    assert proc.returncode == 0, proc.stderr
    assert "Traceback" not in proc.stderr
    assert set(yaml.safe_load((tmp_path / "tree.yaml").read_text())) == {"cam\x07era", 'b"ase'}
    assert (tmp_path / "tree.pdf").read_bytes().startswith(b"%PDF")
    assert '"odom" -> "cam\\\\x07era"' in (tmp_path / "tree.gv").read_text()


def test_tf2_echo_time_beyond_tf2s_range_is_refused(bag):
    for word in ("1e300", "+1e300", "9223372036.854775808"):
        proc = run("tf2-echo", "--bag", str(bag), "world", "cam", "--time", word)
        assert proc.returncode == 2, proc.stderr
        assert "Traceback" not in proc.stderr and proc.stdout == ""
        (line,) = proc.stderr.splitlines()
        assert "--time" in line and "out of range" in line
    # The last representable instant is still a lookup (far beyond the data: tf2's failure block).
    proc = run("tf2-echo", "--bag", str(bag), "world", "cam", "--time", "9223372036.854775807")
    assert proc.returncode == 1 and proc.stdout.startswith("Failure at 9.22337e+09\n")


def test_tf2_echo_every_over_a_damaged_stamp_is_refused(tmp_path):
    from recording.bagfiles import Msg

    t0 = 1_700_000_000 * 10**9
    msgs = []
    for k in range(20):
        stamp_ns = t0 + k * 10**8
        if k == 5:  # one bit of the seconds flipped (1700000000 has bit 19 clear): 524288 s later
            sec, nanosec = divmod(stamp_ns, 10**9)
            stamp_ns = (sec ^ 1 << 19) * 10**9 + nanosec
        msgs.append(Msg("/tf", t0 + k * 10**8, "tf", [("odom", "base", stamp_ns, (k, 0, 0, 0, 0, 0, 1))]))
    path = write(tmp_path / "flipped", "mcap", msgs)
    proc = run("tf2-echo", "--bag", str(path), "odom", "base")
    assert proc.returncode == 1
    assert proc.stdout == ""
    (line,) = proc.stderr.splitlines()
    assert str(path) in line and "524,2" in line and "more than 100,000" in line and "damaged" in line
    # A step that keeps the count sane still answers.
    proc = run("tf2-echo", "--bag", str(path), "odom", "base", "--every", "100")
    assert proc.returncode == 0, proc.stderr
    assert len(printed_blocks(proc.stdout)) == 524288 // 100 + 1
