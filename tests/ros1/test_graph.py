"""The graph as real ROS 1 tools see it (rosnode, rostopic), rosnode kill, and no stale registrations."""

from __future__ import annotations

import logging
import os

import pytest
from ros1helpers import Ros1World, wait_until

from robotmodel.ros1 import xmlrpc_call


def test_rosnode_and_rostopic_show_robotmodels_node(ros1: Ros1World) -> None:
    node = ros1.node("rm_graph", namespace="/arm")
    node.advertise("joint_states", "sensor_msgs/JointState")
    node.subscribe("/tf", "tf2_msgs/TFMessage", lambda m: None)
    assert node.name == "/arm/rm_graph"

    assert "/arm/rm_graph" in ros1.tool("rosnode", "list").split()
    topics = ros1.tool("rostopic", "list").split()
    assert {"/arm/joint_states", "/tf", "/rosout"} <= set(topics)
    info = ros1.tool("rostopic", "info", "/arm/joint_states")
    assert "Type: sensor_msgs/JointState" in info and f"* /arm/rm_graph ({node.uri})" in info, info
    info = ros1.tool("rostopic", "info", "/tf")
    assert "Type: tf2_msgs/TFMessage" in info and "Subscribers: \n * /arm/rm_graph" in info, info
    nodeinfo = ros1.tool("rosnode", "info", "/arm/rm_graph")
    assert f"Pid: {os.getpid()}" in nodeinfo, nodeinfo  # rosnode asked our slave API (getPid)
    assert " * /arm/joint_states [sensor_msgs/JointState]" in nodeinfo and " * /tf [" in nodeinfo
    # getBusInfo: roscore's rosout node subscribes to our /rosout (it may still be connecting)
    wait_until(lambda: "* to: /rosout" in ros1.tool("rosnode", "info", "/arm/rm_graph"), 30, "rosout's connection")
    assert sorted(ros1.registrations_of("/arm/rm_graph")) == ["pub /arm/joint_states", "pub /rosout", "sub /tf"]

    node.close()
    assert ros1.registrations_of("/arm/rm_graph") == []
    assert "/arm/rm_graph" not in ros1.tool("rosnode", "list").split()


def test_rosnode_kill_stops_a_robotmodel_process(ros1: Ros1World) -> None:
    peer = ros1.robotmodel_peer("/rm_victim", "/chatter", "x")
    peer.wait_line("^ready")
    assert ros1.registrations_of("/rm_victim")
    out = ros1.tool("rosnode", "kill", "/rm_victim")
    assert "killed" in out, out
    peer.wait_line(r"^shut down: external shutdown request from \[/rosnode\]")
    assert peer.popen.wait(30) == 0
    assert ros1.registrations_of("/rm_victim") == []


def test_rosnode_kill_stops_an_in_process_node(ros1: Ros1World) -> None:
    node = ros1.node("rm_inproc")
    ros1.tool("rosnode", "kill", "/rm_inproc")
    assert node.wait_for_shutdown(30)
    wait_until(lambda: node.is_shutdown and ros1.registrations_of("/rm_inproc") == [], 30, "node closed")


def test_slave_api_answers_as_rospy_does(ros1: Ros1World) -> None:
    node = ros1.node("rm_slave")
    node.advertise("/chatter", "std_msgs/String")
    assert xmlrpc_call(node.uri, "getPid", "/x") == [1, "", os.getpid()]
    assert xmlrpc_call(node.uri, "getMasterUri", "/x") == [1, ros1.uri, ros1.uri]
    assert xmlrpc_call(node.uri, "getPublications", "/x")[2] == [["/rosout", "rosgraph_msgs/Log"],
                                                                  ["/chatter", "std_msgs/String"]]
    code, _, proto = xmlrpc_call(node.uri, "requestTopic", "/x", "/chatter", [["TCPROS"]])
    assert code == 1 and proto[:2] == ["TCPROS", "127.0.0.1"]
    assert xmlrpc_call(node.uri, "requestTopic", "/x", "/nope", [["TCPROS"]])[0] == -1
    assert xmlrpc_call(node.uri, "requestTopic", "/x", "/chatter", [["UDPROS"]])[0] == 0
    stats = xmlrpc_call(node.uri, "getBusStats", "/x")
    assert stats[0] == 1 and [row[0] for row in stats[2][0]] == ["/rosout", "/chatter"]


def test_node_closes_when_its_master_is_gone(ros1: Ros1World, caplog: pytest.LogCaptureFixture) -> None:
    caplog.set_level(logging.WARNING, logger="robotmodel.ros1")
    node = ros1.node("rm_orphan", keepalive=False)  # (its "lost the master" line is shown in test_recovery)
    node.advertise("/chatter", "std_msgs/String")
    ros1.kill_master()
    node.close()  # one log line per registration it could not remove; no exception, no hang
    assert node.is_shutdown
    lines = [r.getMessage() for r in caplog.records]
    assert len(lines) == 2, lines
    assert all(f"master {ros1.uri} is unreachable (unregisterPublisher)" in line for line in lines), lines
