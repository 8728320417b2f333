"""A bus process for the tests: ``python tests/bus/peer.py ROLE [args]``.

It uses the environment it is given (ROBOTMODEL_ZENOH_PORT, ROS_DOMAIN_ID), prints one
line per event on stdout (flushed) and exits 0 when done. Roles:

- ``hold``: open a node and wait (the first process on the port).
- ``tf-pub ID COUNT``: wait for a /tf subscription, publish COUNT TFMessages (child ``c<ID>``,
  stamp = index) reliable with congestion control BLOCK, print ``done``, wait for stdin EOF.
- ``tf-count TOTAL``: subscribe to /tf, print ``ready``, then ``got <n> <per child>`` once
  TOTAL messages came (or the 60 s deadline passed).
- ``tf-tick [CHILD [FIRST]]``: publish a TFMessage with an increasing stamp (from FIRST)
  every 20 ms on /tf (forever).
- ``tf-print``: subscribe to /tf and print ``tf <child> <stamp>`` for each message.
- ``static-pub``: publish world->base and base->camera on /tf_static (latched), then wait.
- ``static-print``: subscribe to /tf_static (transient local) and print ``static <parent> <child>``.
"""

from __future__ import annotations

import sys
import threading
import time
from collections import Counter
from collections.abc import Callable

from robotmodel.bus import QOS_TF, QOS_TF_STATIC, QOS_TF_STATIC_LISTENER, History, Node, QoS
from robotmodel.msgs import TFMessage, make_transform

_SAY = threading.Lock()


def say(*words: object) -> None:
    # One write per line under a lock: callbacks print from the bus's threads too.
    line = " ".join(str(w) for w in words) + "\n"
    with _SAY:
        sys.stdout.write(line)
        sys.stdout.flush()


def wait_until(condition: Callable[[], bool], end: float) -> bool:
    while not condition():
        if time.monotonic() > end:
            return False
        time.sleep(0.005)
    return True


def wait_forever() -> None:
    # Until the test closes our stdin or kills us.
    sys.stdin.read()


def main(argv: list[str]) -> int:
    role = argv[0]
    with Node(f"peer_{role.replace('-', '_')}") as node:
        if role == "hold":
            say("ready")
            wait_forever()
        elif role == "tf-pub":
            ident, count = argv[1], int(argv[2])
            # Reliable + keep-all: rmw_zenoh's one profile that blocks instead of dropping
            # when the network is full, which a flood that must lose nothing needs.
            pub = node.create_publisher(TFMessage, "/tf", QoS(100, history=History.KEEP_ALL))
            end = time.monotonic() + 30
            # The listener's token (graph) and its subscriber (routing) both known here.
            if not pub.wait_for_subscriptions(1, timeout=30.0) or not wait_until(pub.matched, end):
                say("no subscription")
                return 1
            for i in range(count):
                pub.publish(TFMessage([make_transform("world", f"c{ident}", stamp_ns=i)]))
            say("done")
            wait_forever()
        elif role == "tf-count":
            total = int(argv[1])
            per_child: Counter[str] = Counter()
            lock = threading.Lock()
            enough = threading.Event()

            def on_tf(msg: TFMessage) -> None:
                with lock:
                    for t in msg.transforms:
                        per_child[t.child_frame_id] += 1
                    if sum(per_child.values()) >= total:
                        enough.set()

            node.create_subscription(TFMessage, "/tf", on_tf, QOS_TF)
            say("ready")
            enough.wait(60.0)
            with lock:
                say("got", sum(per_child.values()), dict(sorted(per_child.items())))
        elif role == "tf-tick":
            pub = node.create_publisher(TFMessage, "/tf", QOS_TF)
            say("ready")
            i = int(argv[2]) if len(argv) > 2 else 0
            while True:
                pub.publish(TFMessage([make_transform("world", argv[1] if len(argv) > 1 else "tick", stamp_ns=i)]))
                i += 1
                time.sleep(0.02)
        elif role == "tf-print":
            node.create_subscription(
                TFMessage, "/tf",
                lambda m: [say("tf", t.child_frame_id, t.header.stamp.sec * 10**9 + t.header.stamp.nanosec)
                           for t in m.transforms],
                QOS_TF)
            say("ready")
            wait_forever()
        elif role == "static-pub":
            pub = node.create_publisher(TFMessage, "/tf_static", QOS_TF_STATIC)
            pub.publish(TFMessage([make_transform("world", "base", (1.0, 0.0, 0.0)),
                                   make_transform("base", "camera", (0.0, 0.0, 0.5))]))
            say("ready")
            wait_forever()
        elif role == "static-print":
            node.create_subscription(
                TFMessage, "/tf_static",
                lambda m: [say("static", t.header.frame_id, t.child_frame_id) for t in m.transforms],
                QOS_TF_STATIC_LISTENER)
            say("ready")
            wait_forever()
        else:
            say(f"unknown role {role}")
            return 2
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
