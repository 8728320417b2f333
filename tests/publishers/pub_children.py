"""Listener processes for the live publisher tests (``python pub_children.py MODE ...``).

Each talks on the bus its environment names (ROBOTMODEL_ZENOH_PORT, ROS_DOMAIN_ID) and
prints one JSON line per result on stdout, flushed. Stops on SIGTERM.

- ``lookups ROOT LINK``: for every /tf message, the joint state with the same stamp (from
  /joint_states) and ``lookup_transform(ROOT, LINK, stamp)`` as a 4x4 matrix; a /tf stamp
  no joint state had is reported as ``{"unmatched": stamp}``.
- ``reach ROOT N_LINKS``: once N_LINKS frames (ROOT included) are reachable from ROOT in the
  buffer, the reachable frames and the child frames seen on /tf and on /tf_static.
- ``late``: what arrives on /robot_description (the text) and /tf_static (child frames),
  printed once both have come.
- ``names``: the joint names of each new joint_states layout.
"""

from __future__ import annotations

import json
import queue
import sys
import threading
import time
from typing import Any

_NS = 1_000_000_000


def say(obj: Any) -> None:
    print(json.dumps(obj), flush=True)


def _stop_event() -> threading.Event:
    # As the tools: a handler that sets the event itself never runs when the kernel hands
    # SIGTERM to one of zenoh's threads while the main thread sleeps in stop.wait().
    from robotmodel.signals import stop_on_signals

    return stop_on_signals()


def _ns(stamp: Any) -> int:
    return int(stamp.sec) * _NS + int(stamp.nanosec)


def _matrix(msg: Any) -> list[list[float]]:
    import numpy as np

    tr, q = msg.transform.translation, msg.transform.rotation
    x, y, z, w = q.x, q.y, q.z, q.w
    m = np.eye(4)
    m[:3, :3] = [[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                 [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                 [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]]
    m[:3, 3] = [tr.x, tr.y, tr.z]
    return m.tolist()


def lookups(root: str, link: str) -> None:
    from robotmodel.bus import QOS_TF, Node
    from robotmodel.msgs import JointState, TFMessage
    from robotmodel.tf import Buffer, Duration, Time
    from robotmodel.tf_ros import TransformListener

    stop = _stop_event()
    states: dict[int, dict[str, float]] = {}
    lock = threading.Lock()
    tf_stamps: queue.Queue[int] = queue.Queue()

    def on_state(msg: JointState) -> None:
        with lock:
            states[_ns(msg.header.stamp)] = dict(zip(msg.name, msg.position, strict=True))

    def on_tf(msg: TFMessage) -> None:
        for stamp in {_ns(t.header.stamp) for t in msg.transforms}:
            tf_stamps.put(stamp)

    buffer = Buffer()
    with Node("lookup_listener") as node, TransformListener(buffer, node):
        node.create_subscription(JointState, "/joint_states", on_state, 100)
        node.create_subscription(TFMessage, "/tf", on_tf, QOS_TF)
        say({"ready": True})
        while not stop.is_set():
            try:
                stamp = tf_stamps.get(timeout=0.1)
            except queue.Empty:
                continue
            deadline = time.monotonic() + 2.0
            while time.monotonic() < deadline:
                with lock:
                    state = states.get(stamp)
                if state is not None:
                    break
                time.sleep(0.005)
            if state is None:
                say({"unmatched": stamp})
                continue
            msg = buffer.lookup_transform(root, link, Time(nanoseconds=stamp), timeout=Duration(seconds=2))
            say({"stamp": stamp, "lookup_stamp": _ns(msg.header.stamp), "positions": state,
                 "matrix": _matrix(msg)})


def reach(root: str, n_links: int) -> None:
    from robotmodel.bus import QOS_TF, QOS_TF_STATIC_LISTENER, Node
    from robotmodel.msgs import TFMessage
    from robotmodel.tf import Buffer, Time
    from robotmodel.tf_ros import TransformListener

    stop = _stop_event()
    seen: dict[str, set[str]] = {"tf": set(), "tf_static": set()}
    lock = threading.Lock()

    def recorder(topic: str) -> Any:
        def record(msg: TFMessage) -> None:
            with lock:
                seen[topic].update(t.child_frame_id for t in msg.transforms)
        return record

    buffer = Buffer()
    with Node("reach_listener") as node, TransformListener(buffer, node):
        node.create_subscription(TFMessage, "/tf", recorder("tf"), QOS_TF)
        node.create_subscription(TFMessage, "/tf_static", recorder("tf_static"), QOS_TF_STATIC_LISTENER)
        say({"ready": True})
        reachable: list[str] = []
        while len(reachable) < n_links:
            if stop.wait(0.05):
                return
            reachable = sorted(f for f in buffer.all_frame_names() if buffer.can_transform(root, f, Time()))
        # The listener's callback and ours run one after the other for each sample: let ours
        # catch up with what the buffer got (every frame but the root came on one topic or the
        # other) before reporting what each topic carried.
        deadline = time.monotonic() + 10.0
        while not stop.wait(0.01) and time.monotonic() < deadline:
            with lock:
                if set(reachable) - {root} <= seen["tf"] | seen["tf_static"]:
                    break
        with lock:
            say({"reachable": reachable, "tf": sorted(seen["tf"]), "tf_static": sorted(seen["tf_static"])})
        stop.wait()


def late() -> None:
    from robotmodel.bus import QOS_LATCHED, QOS_TF_STATIC_LISTENER, Node
    from robotmodel.msgs import String, TFMessage

    stop = _stop_event()
    got: dict[str, Any] = {}
    done = threading.Event()

    def on_description(msg: String) -> None:
        got["description"] = msg.data
        if "static" in got:
            done.set()

    def on_static(msg: TFMessage) -> None:
        got["static"] = sorted((t.header.frame_id, t.child_frame_id) for t in msg.transforms)
        if "description" in got:
            done.set()

    with Node("late_joiner") as node:
        node.create_subscription(String, "/robot_description", on_description, QOS_LATCHED)
        node.create_subscription(TFMessage, "/tf_static", on_static, QOS_TF_STATIC_LISTENER)
        say({"ready": True})
        if done.wait(60):
            say(got)
        stop.wait()


def names() -> None:
    from robotmodel.bus import Node
    from robotmodel.msgs import JointState

    stop = _stop_event()
    last: list[list[str]] = [[]]

    def on_state(msg: JointState) -> None:
        if list(msg.name) != last[0]:
            last[0] = list(msg.name)
            say({"names": last[0], "position": list(msg.position)})

    with Node("names_listener") as node:
        node.create_subscription(JointState, "/joint_states", on_state, 10)
        say({"ready": True})
        stop.wait()


if __name__ == "__main__":
    mode, args = sys.argv[1], sys.argv[2:]
    if mode == "lookups":
        lookups(args[0], args[1])
    elif mode == "reach":
        reach(args[0], int(args[1]))
    elif mode == "late":
        late()
    elif mode == "names":
        names()
    else:
        raise SystemExit(f"unknown mode {mode}")
