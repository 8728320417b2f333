"""view-frames on a live system: a static publisher and a 100 Hz broadcaster in their own processes.

The expected .gv layout is tf2_tools' view_frames (Jazzy) as read in its source: one edge
per child with its broadcaster, then the legend hanging off the root.
"""

from __future__ import annotations

import re
import shutil
import signal
import time

import yaml


def test_view_frames_on_three_processes(bus):
    static = bus.robotmodel("static-transform-publisher", "--z", "0.5", "--frame-id", "world",
                            "--child-frame-id", "base")
    static.wait_line(r"^from 'world' to 'base'$", stream="err")
    static_name = static.wait_line(r"\] \[(static_transform_publisher_[0-9A-Za-z]{16})\]: Spinning",
                                   stream="err").group(1)
    mover = bus.child("broadcaster", "mover_node", str(time.time_ns()))
    mover.wait_line(r"^SENT 10$")
    view = bus.robotmodel("view-frames", "--wait-time", "2", "-o", "tree")
    assert view.popen.wait(60) == 0, view.err
    view.kill()  # reaps the reader threads

    gv = (bus.cwd / "tree.gv").read_text()
    assert gv.startswith("digraph G {\n")
    edges = re.findall(r'^"([^"]+)" -> "([^"]+)"\[label=" Broadcaster: ([^\\]+)\\n', gv, re.M)
    assert sorted(edges) == [("base", "moving", "/mover_node"), ("world", "base", f"/{static_name}")]
    assert gv.endswith('}->"world";\n}')
    assert re.search(r'"Recorded at time: \d+\.\d+"\[ shape=plaintext \] ;', gv)

    frames = yaml.safe_load((bus.cwd / "tree.yaml").read_text())
    assert frames["base"]["rate"] == 10000.0 and frames["base"]["most_recent_transform"] == 0.0
    assert frames["moving"]["parent"] == "base" and frames["moving"]["rate"] > 10.0
    assert (bus.cwd / "tree.pdf").exists() == (shutil.which("dot") is not None)

    logs = [line.split("]: ", 1)[1] for line in view.err if "] [view_frames]: " in line]
    assert logs[:2] == ["Listening to tf data for 2.0 seconds...", "Generating graph..."]
    assert logs[2].startswith("Result:tf2_msgs.srv.FrameGraph_Response(frame_yaml=")
    assert logs[3] == "Exporting graph in tree.pdf file..."
    assert mover.stop() == 0
    assert static.stop(signal.SIGINT) == 0


def test_view_frames_default_name_and_no_data(bus):
    view = bus.robotmodel("view_frames", "-t", "0.2")
    assert view.popen.wait(60) == 0
    view.kill()
    names = [p.name for p in bus.cwd.iterdir()]
    gv = [n for n in names if n.endswith(".gv")]
    assert len(gv) == 1 and re.fullmatch(r"frames_\d{4}-\d\d-\d\d_\d\d\.\d\d\.\d\d\.gv", gv[0]), names
    assert (bus.cwd / gv[0]).read_text() == 'digraph G { "No tf data received" }'


def test_view_frames_with_a_control_character_in_a_frame_name(bus):
    """Any publisher picks the names: one holding a control character still gives .yaml, .gv and .pdf."""
    static = bus.robotmodel("static-transform-publisher", "--frame-id", "world", "--child-frame-id", "cam\x07era")
    static.wait_line(r"Spinning", stream="err")
    view = bus.robotmodel("view-frames", "--wait-time", "2", "-o", "tree")
    assert view.popen.wait(60) == 0, view.err
    view.kill()
    assert not any("Traceback" in line for line in view.err), view.err
    frames = yaml.safe_load((bus.cwd / "tree.yaml").read_text())
    assert frames["cam\x07era"]["parent"] == "world"
    assert '"world" -> "cam\\\\x07era"' in (bus.cwd / "tree.gv").read_text()
    assert (bus.cwd / "tree.pdf").read_bytes().startswith(b"%PDF")
    assert static.stop(signal.SIGINT) == 0
