"""The serving half of ``view`` and ``joint-state-publisher-gui``: the page, and the bus when asked.

- no FILE: the robot comes from ``/robot_description`` (latched), and each new description
  there replaces it, as in rviz's RobotModel display;
- ``--follow``: ``/joint_states`` drives the robot (latest state, redrawn at most 30 times a second);
- ``--tf``: frames from ``/tf`` and ``/tf_static`` drawn as named axes (those ``--frames`` names),
  placed from the fixed frame, with the robot where the fixed frame sees its root and, with
  ``--track FRAME``, the camera following that frame;
- ``--publish``: the sliders' values go out on ``/joint_states`` (joint_state_publisher_gui).
"""

from __future__ import annotations

import argparse
import sys
import threading
from typing import Any

__all__ = ["serve_live"]

_TF_PERIOD = 1.0 / 30.0


class _Descriptions:
    """The latest /robot_description text (latched), and an event for each new one."""

    def __init__(self, node: Any) -> None:
        from robotmodel.bus import QOS_LATCHED
        from robotmodel.msgs import String

        self.text: str | None = None
        self.changed = threading.Event()
        self._lock = threading.Lock()
        self.sub = node.create_subscription(String, "robot_description", self._on_message, QOS_LATCHED)

    def _on_message(self, msg: Any) -> None:
        with self._lock:
            if msg.data != self.text:
                self.text = msg.data
                self.changed.set()

    def take(self) -> str | None:
        """The text if it changed since the last call, else None."""
        with self._lock:
            if not self.changed.is_set():
                return None
            self.changed.clear()
            return self.text

    def close(self) -> None:
        self.sub.close()


def _parse(text: str) -> Any:
    from robotmodel.errors import RobotModelError
    from robotmodel.model import parse_urdf

    try:
        return parse_urdf(text)
    except RobotModelError as exc:
        print(f"robotmodel view: ignoring robot_description: {' '.join(str(exc).splitlines())}", file=sys.stderr)
        return None


def _wait_description(topic: _Descriptions, stop: threading.Event) -> Any:
    print("Waiting for robot_description to be published on the robot_description topic...", file=sys.stderr)
    while not stop.is_set():
        if topic.changed.wait(0.1):
            text = topic.take()
            desc = _parse(text) if text is not None else None
            if desc is not None:
                return desc
    return None


def _watch_descriptions(topic: _Descriptions, viewer: Any, stop: threading.Event) -> None:
    # As rviz's RobotModel display: a new description on the topic replaces the robot.
    while not stop.is_set():
        if topic.changed.wait(0.2):
            text = topic.take()
            desc = _parse(text) if text is not None else None
            if desc is not None:
                viewer.set_description(desc)


def _follow(node: Any, viewer: Any) -> Any:
    from robotmodel.msgs import JointState

    def on_state(msg: JointState) -> None:
        model = viewer.model  # read per message: a new robot_description replaces it
        values = {n: float(p) for n, p in zip(msg.name, msg.position, strict=False)
                  if n in model.variables or n in model.mimics}
        if values:
            viewer.display(values)

    return node.create_subscription(JointState, "joint_states", on_state, 10)


def _tf_loop(buffer: Any, viewer: Any, args: argparse.Namespace, stop: threading.Event) -> None:
    from robotmodel.cli.view_cmd import frames_spec

    from robotmodel.errors import TransformException
    from robotmodel.time import Time

    fixed_frame, track = getattr(args, "fixed_frame", None), getattr(args, "track", None)
    spec = frames_spec(args.frames) if args.frames is not None else "all"
    drawn = set() if spec == "none" else set(spec) if spec != "all" else None

    while not stop.wait(_TF_PERIOD):
        fixed = fixed_frame or viewer.description.root  # rviz's Fixed Frame
        poses = {}
        for frame in buffer.all_frame_names():
            try:
                t = buffer.lookup_transform(fixed, frame, Time()).transform
            except TransformException:
                continue
            poses[frame] = _matrix(t)
        viewer.show_tf(poses if drawn is None else {f: m for f, m in poses.items() if f in drawn})
        root = viewer.description.root
        if root in poses:  # the robot is drawn where the fixed frame sees its root, as in rviz
            viewer.place_robot(poses[root])
        if track in poses:
            viewer.track(poses[track][:3, 3])


def _matrix(t: Any) -> Any:
    import numpy as np

    from robotmodel.spatial import quat_to_matrix

    m = np.eye(4)
    q = t.rotation
    m[:3, :3] = quat_to_matrix(np.array([q.x, q.y, q.z, q.w]))
    m[:3, 3] = (t.translation.x, t.translation.y, t.translation.z)
    return m


def serve_live(args: argparse.Namespace, desc: Any, initial: dict[str, float], frames: Any,
               *, publish: bool = False, jsp_options: dict[str, Any] | None = None) -> int:
    """Serve the viewer until SIGINT/SIGTERM; ``desc=None`` takes the robot from the bus.

    ``jsp_options`` are the publishing JointStatePublisher's settings from the ROS parameters
    (the caller has read them); without them every parameter override is named as ignored.
    """
    from robotmodel.cli.view_cmd import make_viewer

    from robotmodel.signals import stop_on_signals

    publish = publish or getattr(args, "publish", False)
    follow = getattr(args, "follow", False)
    tf = getattr(args, "tf", False)
    stop = stop_on_signals()
    closers: list[Any] = []
    node = None
    try:
        if desc is None or publish or follow or tf:
            from robotmodel.bus import Node

            # Relative robot_description and joint_states: under --namespace, as rviz's displays resolve them.
            ros = getattr(args, "ros", None)
            if ros is not None and jsp_options is None:
                from robotmodel.rcl import warn_ignored_params

                warn_ignored_params(ros, args.namespace, getattr(args, "node_name", None) or "robotmodel_view")
            node = Node(getattr(args, "node_name", None) or "robotmodel_view", getattr(args, "namespace", "/"),
                        connect=args.connect, remappings=ros.remaps if ros is not None else ())
            closers.append(node)
        topic = None
        if desc is None:
            topic = _Descriptions(node)
            closers.insert(0, topic)
            desc = _wait_description(topic, stop)
            if desc is None:
                return 0
        viewer = make_viewer(args, desc, initial, frames, serve=True)
        closers.insert(0, viewer)
        if topic is not None:
            threading.Thread(target=_watch_descriptions, args=(topic, viewer, stop), daemon=True).start()
        viewer.publishing, viewer.following = publish, follow
        if publish:
            from robotmodel.publishers import JointStatePublisher

            jsp = JointStatePublisher(desc, bus=node, zeros=viewer.positions, **(jsp_options or {}))
            closers.insert(0, jsp)
            # Read per move: a new robot_description changes both robots' joints.
            viewer.on_joints(lambda _all: jsp.set({k: v for k, v in viewer.positions.items()
                                                   if k in jsp.free_joints}))
        if follow:
            closers.insert(0, _follow(node, viewer))
        if tf:
            from robotmodel.tf import Buffer
            from robotmodel.tf_ros import TransformListener

            buffer = Buffer()
            closers.insert(0, TransformListener(buffer, node))
            threading.Thread(target=_tf_loop, args=(buffer, viewer, args, stop), daemon=True).start()
        print(viewer.url, flush=True)
        if args.open:
            viewer.open()
        stop.wait()
    finally:
        stop.set()
        for closer in closers:
            closer.close()
    return 0
