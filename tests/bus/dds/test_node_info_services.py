"""``robotmodel node info`` on the DDS wire lists service servers and clients, as ``ros2 node info`` does.

On DDS a service is its readers and writers on ``rq/<name>Request`` and ``rr/<name>Reply``;
the graph shows a reader of the first as a server and of the second as a client (as
rmw_dds_common does), for our nodes and for a real rclpy node (Jazzy, Fast DDS), whose
servers are the ones rclpy's own graph lists for it.
"""

from __future__ import annotations

import json
from typing import Any

from rclpyside import DEADLINE_S

from robotmodel.bus import Node


def _sections(procs: Any, node: str, *options: str) -> dict[str, list[str]]:
    proc = procs.cli("node", "info", node, *options)
    assert proc.popen.wait(DEADLINE_S) == 0, proc.errors
    proc.wait_for(lambda _: False, 0.1)  # the readers drain what is left
    assert proc.lines[0] == node, proc.lines
    sections: dict[str, list[str]] = {}
    title = ""
    for line in proc.lines[1:]:
        if line.startswith("    "):
            sections[title].append(line.strip())
        else:
            title = line.strip().rstrip(":")
            sections[title] = []
    return sections


def test_node_info_lists_the_services_of_our_node_and_of_an_rclpy_node(rclpy: Any, procs: Any) -> None:
    peer = rclpy("params")
    reported = json.loads(peer.wait_line("services ", timeout=DEADLINE_S)[len("services "):])
    with Node("svc_owner") as node:  # this process is on the test's DDS domain (bus_env)
        node.create_service("rcl_interfaces/srv/GetParameters", "owner_srv", lambda *_: None)
        node.create_client("rcl_interfaces/srv/ListParameters", "/elsewhere/list_parameters")
        ours = _sections(procs, "/svc_owner")
    assert ours["Service Servers"] == ["/owner_srv: rcl_interfaces/srv/GetParameters"]
    assert ours["Service Clients"] == ["/elsewhere/list_parameters: rcl_interfaces/srv/ListParameters"]
    theirs = _sections(procs, "/rclpy_params", "--spin-time", "2")  # ros2cli's default, for a loaded machine
    assert theirs["Service Servers"] == sorted(f"{name}: {types[0]}" for name, types in reported)
    assert theirs["Service Clients"] == []
