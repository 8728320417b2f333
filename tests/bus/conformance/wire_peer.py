"""The other side of a conformance case: roles run in a child process (wires with processes) or in-process.

``python wire_peer.py WIRE ROLE [ARGS]`` opens a session on WIRE (with the environment's
domain and rendezvous), plays ROLE, prints ``ready`` and waits for stdin to close (or to be
killed). On the in-process wire the suite calls the same role on a session of its own and
"kills" it by closing that session.

Roles:

- ``latched TOPIC COUNT DEPTH``: node ``latcher`` publishes ``m0``..``m<COUNT-1>`` (std_msgs/String)
  on TOPIC, reliable transient local with DEPTH.
- ``talker NAME NAMESPACE``: node NAME in NAMESPACE with a best-effort keep-last 7 publisher of
  std_msgs/String on ``chatter`` (relative) and a tf2_ros listener-QoS subscription on ``/tf``.
- ``adder SERVICE``: node ``adder`` serves example_interfaces/srv/AddTwoInts as SERVICE (sum = a + b).
"""

from __future__ import annotations

import sys
from collections.abc import Callable
from typing import Any

from robotmodel.bus import QOS_TF, Context, Durability, Node, QoS, Reliability, typestore

STRING = "std_msgs/msg/String"
TF = "tf2_msgs/msg/TFMessage"
ADD = "example_interfaces/srv/AddTwoInts"


def latched(ctx: Context, topic: str, count: str, depth: str) -> list[Any]:
    node = Node("latcher", context=ctx)
    String = typestore().types[STRING]
    pub = node.create_publisher(STRING, topic, QoS(int(depth), durability=Durability.TRANSIENT_LOCAL))
    for i in range(int(count)):
        pub.publish(String(data=f"m{i}"))
    return [node, pub]


def talker(ctx: Context, name: str, namespace: str) -> list[Any]:
    node = Node(name, namespace, context=ctx)
    pub = node.create_publisher(STRING, "chatter", QoS(7, Reliability.BEST_EFFORT))
    sub = node.create_subscription(TF, "/tf", lambda m: None, QOS_TF)
    return [node, pub, sub]


def adder(ctx: Context, service: str) -> list[Any]:
    node = Node("adder", context=ctx)

    def add(request: Any, respond: Callable[[Any], None], _request_id: Any) -> None:
        respond(typestore().types[ADD + "_Response"](sum=request.a + request.b))

    server = node.create_service(ADD, service, add)
    return [node, server]


ROLES: dict[str, Callable[..., list[Any]]] = {"latched": latched, "talker": talker, "adder": adder}


def main(argv: list[str]) -> int:
    wire, role, *args = argv
    with Context(backend=wire) as ctx:
        keep = ROLES[role](ctx, *args)
        sys.stdout.write("ready\n")
        sys.stdout.flush()
        sys.stdin.read()
        del keep
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
