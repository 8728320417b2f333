"""robotmodel's ROS 1 robot_state_publisher beside Debian's real C++ one (1.15.2), differentially.

Both run in the same namespace on one roscore, read the same ``tf_prefix`` (one searched up to
the namespace, one private), take the same rospy /joint_states, and a rospy reader prints
each publisher's frame ids exactly as they are on the wire: ours must put out the same pairs.
Neither publishes a /robot_description topic (ROS 1's RSP only reads the parameter).
"""

from __future__ import annotations

import itertools
import statistics
import sys
from pathlib import Path

from ros1helpers import SYSTEM_PYTHON, Ros1World, wait_until

from robotmodel.model import load

HERE = Path(__file__).resolve().parent
ARM = HERE.parent.parent / "urdf" / "arm.urdf.xacro"
REAL_RSP = "/usr/lib/robot_state_publisher/robot_state_publisher"
# namespace -> (where tf_prefix is set, relative to the namespace; its value)
PREFIXES = {"/r1": ("tf_prefix", "/pfx1"), "/r2": ("{node}/tf_prefix", "pfx2/")}


def _pairs(lines: list[str], callerid: str) -> set[tuple[str, str, str]]:
    return {(topic, parent, child) for topic, caller, parent, child, _ in (line.split() for line in lines[1:])
            if caller == callerid}


def test_tf_prefix_and_topics_as_the_real_rsp(ros1: Ros1World) -> None:
    setter = ros1.node("setter").params
    setter.set_param("/robot_description", load(ARM).source_text)
    for ns, (where, value) in PREFIXES.items():
        for node in ("robot_state_publisher", "rm_rsp"):
            setter.set_param(f"{ns}/{where.format(node=node)}", value)
    frames = ros1.start(SYSTEM_PYTHON, str(HERE / "rospy_tf_frames.py"))
    frames.wait_line("^ready", 60)
    ros1.env["ROS_VERSION"] = "1"
    for ns in PREFIXES:
        ros1.start(REAL_RSP, f"__ns:={ns}")
        ros1.start(sys.executable, "-m", "robotmodel.cli.main", "robot_state_publisher", f"__ns:={ns}",
                   "__name:=rm_rsp")
        ros1.start(SYSTEM_PYTHON, str(HERE / "rospy_joint_states.py"), f"{ns}/joint_states", "arm_base_joint=0.3",
                   "arm_elbow_joint=1.1")

    def same() -> bool:
        return all((real := _pairs(frames.lines, f"{ns}/robot_state_publisher"))
                   and {t for t, _, _ in real} == {"/tf", "/tf_static"} and _pairs(frames.lines, f"{ns}/rm_rsp") == real
                   for ns in PREFIXES)

    wait_until(same, 60, "the same frame ids from both RSPs")
    assert ("/tf_static", "pfx1/world", "pfx1/arm_base_link") in _pairs(frames.lines, "/r1/rm_rsp")
    assert ("/tf_static", "pfx2//world", "pfx2//arm_base_link") in _pairs(frames.lines, "/r2/rm_rsp")
    topics = ros1.tool("rostopic", "list").split()
    assert not [t for t in topics if t.endswith("robot_description")], topics
    # the same topics published and subscribed (roscpp's logger services aside)
    topics_of = [[r for r in ros1.registrations_of(f"/r1/{n}") if not r.startswith("srv ")]
                 for n in ("rm_rsp", "robot_state_publisher")]
    assert topics_of[0] == topics_of[1], topics_of


def test_use_tf_static_false_as_the_real_rsp(ros1: Ros1World) -> None:
    """``_use_tf_static:=false``: neither RSP sends /tf_static; both send the fixed joints on /tf at
    ``~publish_frequency``, stamped half a second after they arrive (the real one measured beside ours)."""
    setter = ros1.node("setter").params
    setter.set_param("/robot_description", load(ARM).source_text)
    frames = ros1.start(SYSTEM_PYTHON, str(HERE / "rospy_tf_frames.py"), "--all")
    frames.wait_line("^ready", 60)
    ros1.env["ROS_VERSION"] = "1"
    words = ("_use_tf_static:=false", "_publish_frequency:=10")
    ros1.start(REAL_RSP, "__ns:=/r1", *words)
    ros1.start(sys.executable, "-m", "robotmodel.cli.main", "robot_state_publisher", "__ns:=/r2", *words)
    fixed = ("world", "arm_base_link")  # arm.urdf.xacro's fixed joint

    def rows(caller: str) -> list[tuple[str, float, float]]:
        out = []
        for line in frames.lines[1:]:
            topic, who, parent, child, stamp, arrived = line.split()
            if who == caller and (parent, child) == fixed:
                out.append((topic, float(stamp), float(arrived)))
        return out

    callers = ("/r1/robot_state_publisher", "/r2/robot_state_publisher")
    wait_until(lambda: all(len(rows(c)) >= 6 for c in callers), 60, "six fixed transforms from each RSP on /tf")
    for caller in callers:
        got = rows(caller)[1:6]  # the first may come from a timer started before the reader connected
        assert {topic for topic, _, _ in rows(caller)} == {"/tf"}, (caller, rows(caller))
        # Stamped 0.5 s after sending, so never more than that after arriving; a late delivery on a
        # loaded machine only shrinks it, hence the median.
        ahead = [stamp - arrived for _, stamp, arrived in got]
        assert max(ahead) < 0.505 and statistics.median(ahead) > 0.3, (caller, ahead)
        gaps = [b[1] - a[1] for a, b in itertools.pairwise(got)]
        assert 0.07 < statistics.median(gaps) < 0.15, (caller, gaps)  # 10 Hz, by the stamps
