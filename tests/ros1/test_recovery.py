"""Recovery through the bus layer on real ROS 1: a publisher killed -9 and restarted, a master restarted.

The robotmodel side is a :class:`robotmodel.bus.Node` on the ROS 1 wire (what every tool
uses) or a robotmodel command; the other side is Debian's rospy, C++ static_transform_publisher
and tf2_ros listener.
"""

from __future__ import annotations

import signal
import sys
import time

import pytest
from ros1helpers import RM_PEER, SYSTEM_PYTHON, Ros1World, wait_until

from robotmodel.bus import Node
from robotmodel.ros1 import typestore

STRING = typestore().types["std_msgs/msg/String"]


@pytest.mark.parametrize("publisher", ["robotmodel", "rospy"])
def test_publisher_killed_and_restarted_both_subscribers_recover(ros1: Ros1World, publisher: str) -> None:
    got: list[str] = []
    rospy_sub = ros1.rospy("sub", "/chatter", "std_msgs/String")
    rospy_sub.wait_line("^ready")

    def talker(text: str):  # type: ignore[no-untyped-def]
        if publisher == "rospy":
            return ros1.rospy("pub", "/chatter", "std_msgs/String", "--name", "talker", "--text", text)
        return ros1.start(sys.executable, str(RM_PEER), "/talker", "/chatter", text, "--bus")

    with Node("rm_sub", backend="ros1", connect=[ros1.uri]) as node:
        node.create_subscription(STRING, "/chatter", lambda m: got.append(m.data), 10)
        first = talker("first")
        wait_until(lambda: any(t.startswith("first") for t in got), 60, "messages of the first talker")
        rospy_sub.wait_line("^got first ")
        first.kill()  # SIGKILL to its process group: no unregistration
        second = talker("second")
        second.wait_line("^ready", 60)
        up = time.monotonic()
        wait_until(lambda: any(t.startswith("second") for t in got), 30, "robotmodel: the restarted talker")
        ours = time.monotonic() - up
        rospy_sub.wait_line("^got second ")
        theirs = time.monotonic() - up
    print(f"recovered after the restarted {publisher} publisher registered: robotmodel {ours:.3f} s, "
          f"rospy {theirs:.3f} s")
    assert ours < 2.0 and theirs < 2.0, (ours, theirs)


def test_master_restart_robotmodel_nodes_register_again(ros1: Ros1World) -> None:
    ros1.env["ROS_VERSION"] = "1"
    rm = [sys.executable, "-m", "robotmodel.cli.main"]
    stp = ros1.start(*rm, "static_transform_publisher", "1", "2", "3", "0", "0", "0", "map", "odom")
    echo = ros1.start(*rm, "tf2_echo", "map", "base")
    wait_until(lambda: ros1.registrations_of("/tf2_echo"), 60, "robotmodel tf2_echo registered")
    wait_until(lambda: any(n.startswith("/static_transform_publisher") and ros1.registrations_of(n)
                           for n in ros1.tool("rosnode", "list").split()), 60, "robotmodel's publisher registered")
    ros1.kill_master()
    ros1.restart_master()
    # Both re-register with the new master, which knows nothing of them otherwise: a rospy tf2
    # listener started now gets robotmodel's latched /tf_static, and robotmodel's tf2_echo the
    # real static_transform_publisher's.
    ros1.start("/usr/lib/tf2_ros/static_transform_publisher", "0", "0", "4", "0", "0", "0", "odom", "base")
    echo.wait_line(r"- Translation: \[1\.000, 2\.000, 7\.000\]", 60)
    listener = ros1.start(SYSTEM_PYTHON, str(RM_PEER.with_name("tf2_listener.py")), "map", "odom")
    assert listener.wait_line(r"^pose map odom (.*)$", 60).group(1).split()[:3] == ["1.0", "2.0", "3.0"]
    nodes = ros1.tool("rosnode", "list").split()
    assert "/tf2_echo" in nodes and any(n.startswith("/static_transform_publisher") for n in nodes), nodes
    for proc in (stp, echo):
        proc.kill(signal.SIGINT)  # neither crashed nor hangs: each stops on Ctrl-C
        assert proc.popen.returncode == 0, proc.lines[-10:]
        # one line for the outage: its loss, or (when the master was back before the next look) its restart
        said = [line for line in proc.lines if "lost the master" in line or " restarted: registered " in line]
        assert len(said) == 1, proc.lines
