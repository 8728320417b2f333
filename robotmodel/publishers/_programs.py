"""robot_state_publisher and joint_state_publisher as programs: ROS parameters in, a node on the bus until stopped.

The ``robotmodel robot-state-publisher`` and ``joint-state-publisher`` commands are
:func:`run_robot_state_publisher` and :func:`run_joint_state_publisher`; the node's
``--ros-args`` parameters map onto the publishers' settings as ROS's nodes read them (a
parameter wins over the same setting's flag; one with no use here is named in a warning),
and :func:`jsp_settings` is that mapping for joint_state_publisher (its GUI uses it too).
"""

from __future__ import annotations

import os
import sys
from collections.abc import Callable, Mapping, Sequence
from typing import TYPE_CHECKING, Any

from robotmodel.errors import RosArgsError

if TYPE_CHECKING:
    from robotmodel.rcl import RosArgs

__all__ = ["description_parameter", "jsp_settings", "run_joint_state_publisher", "run_robot_state_publisher"]

_JSP = "joint_state_publisher"
_RSP = "robot_state_publisher"
_BOOLS = ("publish_default_positions", "publish_default_velocities", "publish_default_efforts", "use_mimic_tags",
          "use_smallest_joint_limits")
_WHY = {
    "dependent_joints": "joint_state_publisher replaces it with the URDF's mimic tags once a robot is loaded",
    "robot_description": "joint_state_publisher reads the robot from FILE or the robot_description topic",
    "qos_overrides": "QoS overrides are not read here",
}
_RSP_PARAMS = frozenset({"robot_description", "publish_frequency", "ignore_timestamp", "frame_prefix",
                         "use_sim_time"})
_RSP_WHY = {"qos_overrides": "QoS overrides are not read here"}


def jsp_settings(values: Mapping[str, Any], warn: Callable[[str], None], *, rate: float = 10.0,
                 zeros: Mapping[str, float] | None = None, source_list: Sequence[str] = ()) -> dict[str, Any]:
    """JointStatePublisher's keyword settings: the given ones, then the parameter overrides ``values`` over them.

    Raises RosArgsError (rclcpp's text) for a wrong type; ``warn`` hears of the overrides not used.
    """
    from robotmodel.rcl import RosArgsError, typed_param, warn_unused_params

    # joint_state_publisher declares its parameters from the overrides (rclpy), so a number is a number.
    given = typed_param(values, "rate", "integer", "double")
    if given is not None:
        if not (isinstance(given, (int, float)) and given > 0):
            raise RosArgsError(f"rate must be a positive number of Hz, got '{given}'")
        rate = float(given)
    settings: dict[str, Any] = {"rate": rate, "zeros": dict(zeros or {}), "source_list": list(source_list)}
    for flag in _BOOLS:
        value = typed_param(values, flag, "bool")
        if value is not None:
            settings[flag] = value
    delta = typed_param(values, "delta", "double", "integer")
    if isinstance(delta, (int, float)):
        settings["delta"] = float(delta)
    sources = typed_param(values, "source_list", "string_array")
    if isinstance(sources, tuple):
        settings["source_list"] = [str(topic) for topic in sources]
    for param in values:
        zero = typed_param(values, param, "double", "integer") if param.startswith("zeros.") else None
        if isinstance(zero, (int, float)):
            settings["zeros"][param.removeprefix("zeros.")] = float(zero)
    typed_param(values, "use_sim_time", "bool")  # the node's clock: the caller reads it (node_clock)
    warn_unused_params(values, lambda n: n in _BOOLS or n in ("rate", "delta", "source_list", "use_sim_time")
                       or n.startswith("zeros."), warn, _WHY)
    return settings


def _load(file: str | None, mappings: Mapping[str, str], package_paths: Sequence[str | os.PathLike[str]],
          untrusted: bool) -> Any:
    from robotmodel.model import load_source

    if file is None:
        return None
    return load_source(file, mappings, package_paths=package_paths, untrusted=untrusted)[0]


def description_parameter(node: Any, log: Any) -> str | None:
    """ROS 1's nodes take the robot from the parameter server: ``robot_description`` searched up the namespace.

    As roscpp's ``searchParam`` (urdf's ``initParam``) finds it, from ``node``'s namespace up to
    ``/`` (a remap of ``robot_description`` names the parameter instead); None on the other
    wires (ROS 2 has no parameter server) or when it is not set, logged with ROS 1's text.
    """
    if node.context.backend.name != "ros1":
        return None
    store = node.parameters
    # ROS 1 remaps parameter names too (robot_description:=my_description), then searches the result
    remapped = node.resolve_topic_name("robot_description")
    if remapped != node.resolve_topic_name("robot_description", only_expand=True):
        found = remapped if store.has(remapped) else None
    else:
        found = store.search("robot_description")
    value = store.get(found) if found is not None else None
    if not isinstance(value, str) or not value:
        log.error("Could not find parameter robot_description on parameter server")
        return None
    return value


def run_joint_state_publisher(file: str | None = None, mappings: Mapping[str, str] | None = None, *,
                              package_paths: Sequence[str | os.PathLike[str]] = (), untrusted: bool = False,
                              rate: float = 10.0, zeros: Mapping[str, float] | None = None,
                              source_list: Sequence[str] = (), connect: Sequence[str] = (), namespace: str = "/",
                              ros: RosArgs | None = None) -> int:
    """joint_state_publisher until SIGINT/SIGTERM: the robot from ``file`` ('-': stdin) or the topic.

    The flags' settings (``rate``, ``zeros``, ``source_list``) give way to the node's ROS
    parameters in ``ros``; a parameter of the wrong type prints rclcpp's text and gives 2.
    Returns the exit code.
    """
    from robotmodel.bus import Node, node_clock
    from robotmodel.publishers._jsp import JointStatePublisher
    from robotmodel.publishers._ros1params import jsp_description, private_params, ros1_jsp_settings
    from robotmodel.rcl import RosArgs, logger_name, node_params, ros1_wire, ros_console
    from robotmodel.signals import stop_on_signals

    ros = ros or RosArgs()
    name = ros.node_name or _JSP
    log = ros_console(logger_name(namespace, name))
    on_ros1 = ros1_wire()
    values = {} if on_ros1 else node_params(ros, namespace, name)
    try:
        settings = {} if on_ros1 else jsp_settings(values, log.warning, rate=rate, zeros=dict(zeros or {}),
                                                   source_list=source_list)
    except RosArgsError as exc:
        print(f"robotmodel joint-state-publisher: error: {exc}", file=sys.stderr)
        return 2
    desc = _load(file, mappings or {}, package_paths, untrusted)
    stop = stop_on_signals()
    # joint_states, robot_description and relative --source-list topics resolve under the namespace.
    with Node(name, namespace, connect=list(connect), remappings=ros.remaps) as node:
        if on_ros1:  # ROS 1's JSP reads its settings from the parameter server
            try:
                settings = ros1_jsp_settings(private_params(node, ros, namespace, name), rate=rate,
                                             zeros=dict(zeros or {}), source_list=source_list)
            except RosArgsError as exc:
                print(f"robotmodel joint-state-publisher: error: {exc}", file=sys.stderr)
                return 2
        if desc is None and on_ros1:
            desc = jsp_description(node, log)
            if desc is None:
                return 1
        # Stamped and paced in ROS time, as rospy.Time.now() and rclpy's timers are: /clock with
        # /use_sim_time on ROS 1, with the node's use_sim_time parameter on the ROS 2 wires.
        clock = node_clock(node, values.get("use_sim_time") is True)
        with JointStatePublisher(desc, bus=node, logger=log, clock=clock, **settings):
            stop.wait()
    return 0


def run_robot_state_publisher(file: str | None = None, mappings: Mapping[str, str] | None = None, *,
                              package_paths: Sequence[str | os.PathLike[str]] = (), untrusted: bool = False,
                              publish_frequency: float | None = None, frame_prefix: str = "",
                              ignore_timestamp: bool = False, connect: Sequence[str] = (), namespace: str = "/",
                              ros: RosArgs | None = None) -> int:
    """robot_state_publisher until SIGINT/SIGTERM: the robot from ``file`` ('-': stdin) or ``-p robot_description``.

    The node's ROS parameters in ``ros`` win over the keyword settings; a parameter of the
    wrong type prints rclcpp's text and gives 2; no robot at all logs RSP's FATAL line and
    gives 1. ``publish_frequency`` None: RSP's default (20 Hz; 50 on ROS 1). On the ROS 1
    wire it is ROS 1's RSP: private parameters ``~publish_frequency``, ``~tf_prefix``
    (searched up the namespace), ``~ignore_timestamp`` on the parameter server (the command
    line's ``_param:=`` values are set there first), the robot from FILE or the server's
    ``robot_description``. Returns the exit code.
    """
    from robotmodel.bus import Node, node_clock
    from robotmodel.publishers._description_topic import DescriptionTopic
    from robotmodel.publishers._rsp import RobotStatePublisher
    from robotmodel.publishers._rsp_state import check_publish_frequency
    from robotmodel.rcl import (
        RosArgs,
        logger_name,
        node_params,
        ros1_wire,
        ros_console,
        typed_param,
        warn_unused_params,
    )
    from robotmodel.signals import stop_on_signals

    ros = ros or RosArgs()
    name = ros.node_name or _RSP
    log = ros_console(logger_name(namespace, name))
    if ros1_wire():
        return _run_ros1_rsp(file, mappings or {}, package_paths, untrusted, publish_frequency, frame_prefix,
                             ignore_timestamp, connect, namespace, name, ros, log)
    settings: dict[str, Any] = {"publish_frequency": 20.0 if publish_frequency is None else publish_frequency,
                                "ignore_timestamp": ignore_timestamp, "frame_prefix": frame_prefix}
    try:
        values = node_params(ros, namespace, name)
        for param, kind in (("publish_frequency", "double"), ("ignore_timestamp", "bool"),
                            ("frame_prefix", "string")):
            value = typed_param(values, param, kind)
            if value is not None:
                settings[param] = value
        text = typed_param(values, "robot_description", "string")
        use_sim_time = typed_param(values, "use_sim_time", "bool") is True
        warn_unused_params(values, lambda n: n in _RSP_PARAMS, log.warning, _RSP_WHY)
    except RosArgsError as exc:
        print(f"robotmodel robot-state-publisher: error: {exc}", file=sys.stderr)
        return 2
    check_publish_frequency(settings["publish_frequency"])
    # As RSP before 3.5.1: the parameter is the robot; FILE is the fallback when it is empty.
    desc: Any = str(text) if text else _load(file, mappings or {}, package_paths, untrusted)
    if desc is None and text is not None:  # an explicitly empty parameter: RSP's fatal line
        log.critical("robot_description parameter must not be empty")
        return 1
    stop = stop_on_signals()
    # RSP's topics are relative (joint_states, robot_description): they follow the namespace; /tf does not.
    with Node(name, namespace, connect=list(connect), remappings=ros.remaps) as node:
        # ROS time, as rclcpp's RSP: /tf_static and "moved backwards in time" follow /clock under sim
        # time; its first /tf_static is stamped 0 before any /clock came (rclcpp's now() in its constructor).
        clock = node_clock(node, use_sim_time)
        topic = None
        if desc is None:
            # Neither FILE nor parameter: the robot another node publishes (a stock ROS 2's RSP would
            # stop here; robotmodel's joins a running system the way rviz does).
            topic = DescriptionTopic(node)
            log.info("No robot_description parameter: waiting for the robot on the robot_description topic")
            desc = topic.wait(lambda t: _parse_or_warn(t, log), stop)
            if desc is None:
                topic.close()
                return 0
        with RobotStatePublisher(desc, bus=node, logger=log, clock=clock, **settings) as rsp:
            rsp.serve_parameters()  # ros2 param get/set, as ROS 2's robot_state_publisher
            if topic is not None:
                _follow_descriptions(topic, rsp, stop, log)
            stop.wait()
        if topic is not None:
            topic.close()
    return 0


def _parse_or_warn(text: str, log: Any) -> Any:
    """The robot in ``text``, or None after one error line naming what is wrong with it."""
    from robotmodel.errors import RobotModelError
    from robotmodel.model import parse_urdf

    try:
        return parse_urdf(text)
    except RobotModelError as exc:
        log.error("ignoring robot_description: %s", " ".join(str(exc).splitlines()))
        return None


def _follow_descriptions(topic: Any, rsp: Any, stop: Any, log: Any) -> None:
    """Take each later description another node publishes (ours, republished, is the same text: skipped)."""
    import threading

    def run() -> None:
        while not stop.is_set():
            desc = topic.wait(lambda t: None if t == rsp.description_text else _parse_or_warn(t, log), stop)
            if desc is not None:
                rsp.set_description(desc)

    threading.Thread(target=run, name="robot_description", daemon=True).start()


def _run_ros1_rsp(file: str | None, mappings: Mapping[str, str], package_paths: Sequence[str | os.PathLike[str]],
                  untrusted: bool, publish_frequency: float | None, frame_prefix: str, ignore_timestamp: bool,
                  connect: Sequence[str], namespace: str, name: str, ros: RosArgs, log: Any) -> int:
    """ROS 1's robot_state_publisher: its private parameters and the robot from the server.

    ``~publish_frequency`` (50), ``~tf_prefix`` (searched), ``~ignore_timestamp``,
    ``~use_tf_static`` (true; false: the fixed joints on /tf, 0.5 s ahead).
    """
    from robotmodel.bus import Node, TopicClock, node_clock
    from robotmodel.publishers._ros1params import private_params, tf_prefix_text
    from robotmodel.publishers._rsp import RobotStatePublisher
    from robotmodel.publishers._rsp_state import check_publish_frequency
    from robotmodel.signals import stop_on_signals

    desc: Any = _load(file, mappings, package_paths, untrusted)
    stop = stop_on_signals()
    with Node(name, namespace, connect=list(connect), remappings=ros.remaps) as node:
        store = private_params(node, ros, namespace, name)

        def param(key: str, kinds: tuple[type, ...], default: Any) -> Any:
            value = store.get(key) if store.has(key) else default
            if not isinstance(value, kinds) or isinstance(value, bool) is not (bool in kinds):
                log.error("parameter %s: %r is not a %s; using %r", key, value, kinds[0].__name__, default)
                return default
            return value

        hz = float(param("~publish_frequency", (float, int), 50.0 if publish_frequency is None else publish_frequency))
        # tf_prefix is searched up from the private namespace (the master starts at the caller id),
        # as RSP's n_tilde.searchParam does.
        prefix_key = store.search("tf_prefix")
        prefix = str(param(prefix_key, (str,), "")) if prefix_key else ""
        settings: dict[str, Any] = {"publish_frequency": check_publish_frequency(hz),
                    "ignore_timestamp": bool(param("~ignore_timestamp", (bool,), ignore_timestamp)),
                    "use_tf_static": bool(param("~use_tf_static", (bool,), True)),
                    "frame_prefix": tf_prefix_text(prefix) if prefix else frame_prefix}
        if desc is None:
            desc = description_parameter(node, log)
        if desc is None:
            log.critical("Failed to extract kdl tree from xml robot description")
            return 1
        clock = node_clock(node)
        # On sim time RSP's one-shot timer publishes /tf_static once time runs: stamped in it, never 0.
        if isinstance(clock, TopicClock) and not clock.wait_for_valid(stop):
            return 0
        with RobotStatePublisher(desc, bus=node, logger=log, clock=clock, **settings):
            stop.wait()
    return 0
