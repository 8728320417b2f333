"""The viewer fed by the bus: rviz's RobotModel and TF displays, and joint_state_publisher_gui.

- no robot given: it comes from ``/robot_description`` (latched), and each new description
  there replaces it, as in rviz's RobotModel display;
- ``follow``: ``/joint_states`` drives the robot (latest state, redrawn at most 30 times a second);
- ``tf``: frames from ``/tf`` and ``/tf_static`` drawn as named axes (``tf_frames`` of them),
  placed from the fixed frame, with the robot where the fixed frame sees its root and, with
  ``track``, the camera following that frame;
- ``publish``: the sliders' values go out on ``/joint_states`` (joint_state_publisher_gui).

Relative topics (``robot_description``, ``joint_states``) resolve under the node's namespace,
as rviz's displays resolve them. With ``use_sim_time`` (ROS 2's node parameter; ROS 1's
``/use_sim_time``) the node's time is ``/clock``'s, as rviz's: a jump back of it (a looping
bag) clears the TF buffer, as rviz's tf2_ros buffer with the node's clock does, so each pass
of a replay is drawn again from its start (without it the buffer's newest transform stays the
recording's end), and the sliders' /joint_states are stamped in it. ``robotmodel view`` and
``joint-state-publisher-gui`` are :func:`serve_live`; a Python program starts a :class:`LiveViewer` itself.
"""

from __future__ import annotations

import sys
import threading
from collections.abc import Callable, Mapping, Sequence
from typing import TYPE_CHECKING, Any

from robotmodel.publishers._description_topic import DescriptionTopic

if TYPE_CHECKING:
    from robotmodel.model import RobotDescription
    from robotmodel.viewer._options import ViewOptions
    from robotmodel.viewer._viewer import Viewer

__all__ = ["LiveViewer", "serve_live"]

_TF_PERIOD = 1.0 / 30.0


def _parse(text: str) -> Any:
    from robotmodel.errors import RobotModelError
    from robotmodel.model import parse_urdf

    try:
        return parse_urdf(text)
    except RobotModelError as exc:
        print(f"robotmodel view: ignoring robot_description: {' '.join(str(exc).splitlines())}", file=sys.stderr)
        return None


def _wait_description(topic: DescriptionTopic, stop: threading.Event, closed: threading.Event) -> Any:
    print("Waiting for robot_description to be published on the robot_description topic...", file=sys.stderr)
    return topic.wait(_parse, stop, closed)


def _watch_descriptions(topic: DescriptionTopic, viewer: Any, stop: threading.Event) -> None:
    # As rviz's RobotModel display: a new description on the topic replaces the robot.
    while not stop.is_set():
        if topic.changed.wait(0.2):
            text = topic.take()
            desc = _parse(text) if text is not None else None
            if desc is not None:
                viewer.set_description(desc)


def _parameter_description(node: Any) -> RobotDescription | None:
    """On ROS 1, the robot on the parameter server (``robot_description`` up the namespace), as rviz reads it."""
    import logging

    from robotmodel.model import parse_urdf
    from robotmodel.publishers import description_parameter

    if node.context.backend.name != "ros1":
        return None
    text = description_parameter(node, logging.getLogger("robotmodel.viewer"))
    return None if text is None else parse_urdf(text)


def _follow(node: Any, viewer: Any) -> Any:
    from robotmodel.msgs import JointState

    def on_state(msg: JointState) -> None:
        model = viewer.model  # read per message: a new robot_description replaces it
        values = {n: float(p) for n, p in zip(msg.name, msg.position, strict=False)
                  if n in model.variables or n in model.mimics}
        if values:
            viewer.display(values)

    return node.create_subscription(JointState, "joint_states", on_state, 10)


def _tf_loop(buffer: Any, viewer: Any, fixed_frame: str | None, track: str | None, spec: str | Sequence[str],
             stop: threading.Event) -> None:
    from robotmodel.errors import TransformException
    from robotmodel.time import Time

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


class LiveViewer:
    """A :class:`robotmodel.viewer.Viewer` fed from the bus (see the module's list of modes).

    Usage::

        import threading
        from robotmodel.viewer import LiveViewer

        stop = threading.Event()
        with LiveViewer(follow=True, tf=True, fixed_frame="odom") as live:  # robot from /robot_description
            if live.start(stop):  # False when ``stop`` was set before a description came
                print(live.url)
                stop.wait()

    ``description`` None waits for ``/robot_description``. ``node`` is a :class:`robotmodel.bus.Node`
    to use (else one named ``node_name`` in ``namespace`` is opened with ``connect`` and
    ``remappings``, and closed with the viewer). ``make_viewer`` builds the Viewer for a
    description (default: ``Viewer(description, port=port)``); ``jsp_options`` are the
    publishing :class:`robotmodel.publishers.JointStatePublisher`'s keyword settings;
    ``use_sim_time`` puts the node on ``/clock``'s time (see the module's docstring).
    """

    def __init__(self, description: RobotDescription | None = None, *, follow: bool = False, tf: bool = False,
                 publish: bool = False, fixed_frame: str | None = None, track: str | None = None,
                 tf_frames: str | Sequence[str] = "all", node: Any = None, node_name: str = "robotmodel_view",
                 namespace: str = "/", connect: Sequence[str] = (), remappings: Sequence[str] = (),
                 port: int | None = None, make_viewer: Callable[[RobotDescription], Viewer] | None = None,
                 jsp_options: Mapping[str, Any] | Callable[[Any], Mapping[str, Any]] | None = None,
                 use_sim_time: bool = False) -> None:
        self.description = description
        self.use_sim_time = use_sim_time
        self.follow, self.tf, self.publish = follow, tf, publish
        self.fixed_frame, self.track, self.tf_frames = fixed_frame, track, tf_frames
        self.viewer: Viewer | None = None
        self._make_viewer = make_viewer or (lambda d: _default_viewer(d, port))
        self._jsp_options: dict[str, Any] = {}
        self._stop = threading.Event()
        self._closers: list[Any] = []
        self.node = node
        if node is None and (description is None or publish or follow or tf):
            from robotmodel.bus import Node

            self.node = Node(node_name, namespace, connect=list(connect), remappings=list(remappings))
            self._closers.append(self.node)
        try:
            self._jsp_options = dict(jsp_options(self.node) if callable(jsp_options) else jsp_options or {})
        except BaseException:
            self.close()
            raise
        if description is None and self.node is not None:
            description = _parameter_description(self.node)
            self.description = description
        self._topic = DescriptionTopic(self.node) if description is None else None
        if self._topic is not None:
            self._closers.insert(0, self._topic)

    def _clock(self) -> Any:
        """The node's ROS time: /clock under sim time, else the system's (None without a node)."""
        if self.node is None:
            return None
        from robotmodel.bus import node_clock

        return node_clock(self.node, self.use_sim_time)

    @property
    def url(self) -> str | None:
        """The page's address once started (None before)."""
        return self.viewer.url if self.viewer is not None else None

    def start(self, stop: threading.Event | None = None) -> bool:
        """Wait for a description if none was given, then serve it and wire the bus to it.

        Returns False (nothing served) when ``stop`` or :meth:`close` came first.
        """
        if self._topic is not None:
            desc = _wait_description(self._topic, stop or self._stop, self._stop)
            if desc is None:
                return False
            self.description = desc
        assert self.description is not None
        viewer = self._make_viewer(self.description)
        self.viewer = viewer
        self._closers.insert(0, viewer)
        if self._topic is not None:
            threading.Thread(target=_watch_descriptions, args=(self._topic, viewer, self._stop), daemon=True).start()
        viewer.publishing, viewer.following = self.publish, self.follow
        clock = self._clock()
        if self.publish:
            from robotmodel.publishers import JointStatePublisher

            jsp = JointStatePublisher(self.description, bus=self.node, zeros=viewer.positions, clock=clock,
                                      **self._jsp_options)
            self._closers.insert(0, jsp)
            # Read per move: a new robot_description changes both robots' joints.
            viewer.on_joints(lambda _all: jsp.set({k: v for k, v in viewer.positions.items()
                                                   if k in jsp.free_joints}))
        if self.follow:
            self._closers.insert(0, _follow(self.node, viewer))
        if self.tf:
            from robotmodel.rcl import logger_name
            from robotmodel.tf import Buffer
            from robotmodel.tf_ros import TransformListener
            from robotmodel.tf_ros._jump import clear_on_jump_back

            buffer = Buffer()
            self._closers.insert(0, TransformListener(buffer, self.node))
            node = self.node
            clear_on_jump_back(buffer, clock, logger_name(node.get_namespace(), node.get_name()),
                               ros1=node.context.backend.name == "ros1")
            threading.Thread(target=_tf_loop, args=(buffer, viewer, self.fixed_frame, self.track, self.tf_frames,
                                                    self._stop), daemon=True).start()
        return True

    def close(self) -> None:
        """Stop the threads, the server, the publisher and the subscriptions (and the node opened here)."""
        self._stop.set()
        for closer in self._closers:
            closer.close()
        self._closers.clear()

    def __enter__(self) -> LiveViewer:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()


def _default_viewer(desc: RobotDescription, port: int | None) -> Viewer:
    from robotmodel.viewer._viewer import Viewer

    return Viewer(desc, port=port)


def _page_line(url: str, node_name: str | None, *, publish: bool, follow: bool, tf: bool) -> str:
    """The URL line; a page with a role says which page it is (launch starts two: the sliders and rviz's)."""
    if publish:
        role = "sliders publishing /joint_states"
    elif follow:
        role = "the robot following /joint_states" + (" and /tf" if tf else "")
    elif tf:
        role = "the robot with /tf"
    else:
        return url
    who = node_name or ("joint_state_publisher_gui" if publish else "view")
    return f"{url} ({who}: {role})"


def serve_live(options: ViewOptions, desc: RobotDescription | None, initial: Mapping[str, float], frames: Any,
               *, publish: bool = False,
               jsp_options: Mapping[str, Any] | Callable[[Any], Mapping[str, Any]] | None = None) -> int:
    """Serve the viewer with ``options`` until SIGINT/SIGTERM, printing its URL; ``desc=None``: from the bus.

    ``jsp_options`` are the publishing JointStatePublisher's settings from the ROS parameters
    (the caller has read them, or a function reading them from the node once it is up: ROS 1's
    parameter server); without them every parameter override is named as ignored.
    Returns the exit code (0).
    """
    from robotmodel.rcl import RosArgs, node_params, warn_ignored_params
    from robotmodel.signals import stop_on_signals
    from robotmodel.viewer._options import build_viewer, frames_spec

    publish = publish or options.publish
    stop = stop_on_signals()
    name = options.node_name or "robotmodel_view"
    ros = options.ros or RosArgs()
    if jsp_options is None and (desc is None or publish or options.follow or options.tf):
        warn_ignored_params(ros, options.namespace, name, used=("use_sim_time",))
    use_sim_time = node_params(ros, options.namespace, name).get("use_sim_time") is True
    tf_frames = frames_spec(options.frames) if options.frames is not None else "all"
    with LiveViewer(desc, follow=options.follow, tf=options.tf, publish=publish, fixed_frame=options.fixed_frame,
                    track=options.track, tf_frames=tf_frames, node_name=name, namespace=options.namespace,
                    connect=options.connect, remappings=ros.remaps, jsp_options=jsp_options,
                    use_sim_time=use_sim_time,
                    make_viewer=lambda d: build_viewer(options, d, initial, frames, serve=True)) as live:
        if not live.start(stop):
            return 0
        assert live.viewer is not None and live.url is not None
        print(_page_line(live.url, options.node_name, publish=publish, follow=options.follow, tf=options.tf),
              flush=True)
        if options.open:
            live.viewer.open()
        stop.wait()
    return 0
