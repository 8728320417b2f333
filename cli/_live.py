"""The serving half of ``view`` and ``joint-state-publisher-gui``: the page, and the bus when asked.

- no FILE: the robot comes from ``/robot_description`` (latched), as rviz's RobotModel display;
- ``--follow``: ``/joint_states`` drives the robot (latest state, redrawn at most 30 times a second);
- ``--tf``: frames from ``/tf`` and ``/tf_static`` drawn as named axes, placed from the fixed frame;
- ``--publish``: the sliders' values go out on ``/joint_states`` (joint_state_publisher_gui).
"""

from __future__ import annotations

import argparse
import sys
import threading
from typing import Any

__all__ = ["serve_live"]

_TF_PERIOD = 1.0 / 30.0


def _wait_description(node: Any, stop: threading.Event) -> Any:
    from robotmodel.bus import QOS_LATCHED
    from robotmodel.model import parse_urdf
    from robotmodel.msgs import String

    got: list[Any] = []
    ready = threading.Event()

    def on_description(msg: String) -> None:
        if not got:
            got.append(msg.data)
            ready.set()

    sub = node.create_subscription(String, "robot_description", on_description, QOS_LATCHED)
    print("Waiting for robot_description to be published on the robot_description topic...", file=sys.stderr)
    while not ready.wait(0.1):
        if stop.is_set():
            sub.close()
            return None
    sub.close()
    return parse_urdf(got[0])


def _follow(node: Any, viewer: Any) -> Any:
    from robotmodel.msgs import JointState

    known = set(viewer.model.variables) | set(viewer.model.mimics)

    def on_state(msg: JointState) -> None:
        values = {n: float(p) for n, p in zip(msg.name, msg.position, strict=False) if n in known}
        if values:
            viewer.display(values)

    return node.create_subscription(JointState, "joint_states", on_state, 10)


def _tf_loop(buffer: Any, viewer: Any, fixed: str, stop: threading.Event) -> None:
    from robotmodel.errors import TransformException
    from robotmodel.time import Time

    while not stop.wait(_TF_PERIOD):
        poses = {}
        for frame in buffer.all_frame_names():
            try:
                t = buffer.lookup_transform(fixed, frame, Time()).transform
            except TransformException:
                continue
            poses[frame] = _matrix(t)
        viewer.show_tf(poses)


def _matrix(t: Any) -> Any:
    import numpy as np

    from robotmodel.spatial import quat_to_matrix

    m = np.eye(4)
    q = t.rotation
    m[:3, :3] = quat_to_matrix(np.array([q.x, q.y, q.z, q.w]))
    m[:3, 3] = (t.translation.x, t.translation.y, t.translation.z)
    return m


def serve_live(args: argparse.Namespace, desc: Any, initial: dict[str, float], frames: Any,
               *, publish: bool = False) -> int:
    """Serve the viewer until SIGINT/SIGTERM; ``desc=None`` takes the robot from the bus."""
    from robotmodel.cli._bus_args import stop_on_signals
    from robotmodel.cli.view_cmd import make_viewer

    publish = publish or getattr(args, "publish", False)
    follow = getattr(args, "follow", False)
    tf = getattr(args, "tf", False)
    stop = stop_on_signals()
    closers: list[Any] = []
    node = None
    try:
        if desc is None or publish or follow or tf:
            from robotmodel.bus import Node

            node = Node("robotmodel_view", connect=args.connect)
            closers.append(node)
        if desc is None:
            desc = _wait_description(node, stop)
            if desc is None:
                return 0
        viewer = make_viewer(args, desc, initial, frames, serve=True)
        closers.insert(0, viewer)
        viewer.publishing, viewer.following = publish, follow
        if publish:
            from robotmodel.publishers import JointStatePublisher

            jsp = JointStatePublisher(desc, bus=node, zeros=viewer.positions)
            closers.insert(0, jsp)
            free = set(jsp.free_joints)
            viewer.on_joints(lambda _all: jsp.set({k: v for k, v in viewer.positions.items() if k in free}))
        if follow:
            closers.insert(0, _follow(node, viewer))
        if tf:
            from robotmodel.tf import Buffer
            from robotmodel.tf_ros import TransformListener

            buffer = Buffer()
            closers.insert(0, TransformListener(buffer, node))
            thread = threading.Thread(target=_tf_loop, args=(buffer, viewer, desc.root, stop), daemon=True)
            thread.start()
        print(viewer.url, flush=True)
        if args.open:
            viewer.open()
        stop.wait()
    finally:
        stop.set()
        for closer in closers:
            closer.close()
    return 0
