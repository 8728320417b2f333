"""view_frames from an in-process buffer: tf2_tools' .gv layout, and a real PDF from graphviz."""

from __future__ import annotations

import re
import shutil
from pathlib import Path

from tfhelpers import make

from robotmodel.tf import Buffer, view_frames_gv, write_view_frames


def _filled() -> Buffer:
    buf = Buffer()
    buf.set_transform_static(make("base_link", "camera_link", (0.1, 0, 0.2)), "static_pub")
    for i in range(6):
        buf.set_transform(make("map", "odom", sec=10 + i * 0.2), "localization")
        buf.set_transform(make("odom", "base_link", sec=10 + i * 0.2), "odometry")
    return buf


def test_gv_layout_matches_tf2_tools() -> None:
    text = view_frames_gv(_filled().all_frames_as_yaml(), 1_700_000_000_250_000_000)
    lines = text.splitlines()
    assert lines[0] == "digraph G {"
    edges = [line for line in lines if "->" in line and "label" in line]
    assert edges[0] == ('"base_link" -> "camera_link"[label=" Broadcaster: static_pub\\nAverage rate: 10000.0\\n'
                        'Buffer length: 0.0\\nMost recent transform: 0.0\\nOldest transform: 0.0\\n"];')
    odom = next(e for e in edges if e.startswith('"map" -> "odom"'))
    rate = float(re.search(r"Average rate: ([0-9.]+)", odom).group(1))
    assert rate == 6 / 1.0  # six samples over one second
    assert lines[-4:] == [' subgraph cluster_legend { style=bold; color=black; label ="view_frames Result";',
                          '"Recorded at time: 1700000000.25"[ shape=plaintext ] ;', '}->"map";', "}"]
    assert view_frames_gv("", 0) == 'digraph G { "No tf data received" }'


def test_write_gv_and_pdf(tmp_path: Path) -> None:
    gv, pdf = write_view_frames(_filled(), tmp_path / "frames", 1_700_000_000_000_000_000)
    assert gv.read_text(encoding="utf-8").startswith("digraph G {")
    assert shutil.which("dot"), "graphviz must be installed (.ci/run installs it)"
    assert pdf is not None and pdf.read_bytes().startswith(b"%PDF")


# Names any publisher may send: control characters, quotes, YAML words and numbers, backslashes.
HOSTILE_NAMES = ["cam\x07era", 'q"uote', "it's", "1", "true", "null", "x: y", "back\\slash", "new\nline",
                 "\u00e9t\u00e9", "- dash", "#hash", "sp ace ", "cam\\x07era", "\U0001f600", "\u2028", "\x7f", "end\\"]


def test_any_frame_name_reads_back_and_draws(tmp_path: Path) -> None:
    import json
    import subprocess

    import yaml

    buf = Buffer()
    for name in HOSTILE_NAMES:
        buf.set_transform_static(make("base", name), "pub\x01lisher")
    frames = yaml.safe_load(buf.all_frames_as_yaml())
    assert sorted(frames) == sorted(HOSTILE_NAMES)
    assert {(v["parent"], v["broadcaster"]) for v in frames.values()} == {("base", "pub\x01lisher")}
    # A name tf2's text already reads back is written exactly as tf2 writes it.
    plain = Buffer()
    plain.set_transform_static(make("base", "cam"), "pub")
    assert plain.all_frames_as_yaml().startswith("cam: \n  parent: 'base'\n  broadcaster: 'pub'\n")

    gv, pdf = write_view_frames(buf, tmp_path / "frames", 1_700_000_000_000_000_000)
    assert pdf is not None and pdf.read_bytes().startswith(b"%PDF")
    drawn = subprocess.run(["dot", "-Tjson", str(gv)], capture_output=True, text=True, check=True)
    nodes = [o["name"] for o in json.loads(drawn.stdout)["objects"] if o["name"] != "cluster_legend"]
    assert len(nodes) == len(set(nodes)) == len(HOSTILE_NAMES) + 2  # each frame, base, the legend
