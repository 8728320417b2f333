"""ROS 1's publishers read their settings from the parameter server, as their ROS 1 nodes do.

The command line's ``_param:=value`` words are set as the node's private ``~param`` first
(:func:`private_params`, as rospy and roscpp do). joint_state_publisher (1.15.1) reads each
setting as ``~name`` and, when that is unset, ``name`` in the node's namespace
(:func:`ros1_jsp_settings`), the robot too (:func:`jsp_description`: not searched up the
namespaces, unlike robot_state_publisher's); robot_state_publisher (1.15.2) prefixes frames with
``~tf_prefix`` searched up from the node (:func:`tf_prefix_text`).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING, Any

from robotmodel.errors import RosArgsError

if TYPE_CHECKING:
    from robotmodel.bus import ParameterStore
    from robotmodel.rcl import RosArgs

__all__ = ["jsp_description", "private_params", "ros1_jsp_settings", "tf_prefix_text"]

_BOOLS = ("use_mimic_tags", "use_smallest_joint_limits", "publish_default_positions", "publish_default_velocities",
          "publish_default_efforts")


def private_params(node: Any, ros: RosArgs, namespace: str, name: str) -> ParameterStore:
    """The command line's ``_param:=`` values set as ``~param`` on the server; the node's parameter store."""
    from robotmodel.rcl import node_params

    store: ParameterStore = node.parameters
    for param, value in node_params(ros, namespace, name).items():
        store.set("~" + param, value)
    return store


def jsp_description(node: Any, log: Any) -> str | None:
    """ROS 1's joint_state_publisher's robot: ``~robot_description``, else the namespace's ``robot_description``.

    As its ``get_param`` reads it (a remap of ``robot_description`` renames the second); None,
    logged with its text, when neither is set.
    """
    store = node.parameters
    for key in ("~robot_description", node.resolve_topic_name("robot_description")):
        if store.has(key):
            value = store.get(key)
            if isinstance(value, str) and value:
                return value
    log.error("The robot_description parameter is required and not set.")
    return None


def tf_prefix_text(prefix: str) -> str:
    """The text ROS 1's RSP (1.15.2) puts before each frame for ``~tf_prefix``: tf's resolve, less one leading slash.

    Measured against Debian's: ``/pfx`` gives ``pfx/world``, ``pfx/`` gives ``pfx//world``, ``/`` gives ``/world``.
    """
    return prefix.removeprefix("/") + "/"


def _number(value: Any) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool)


def ros1_jsp_settings(store: ParameterStore, *, rate: float = 10.0,
                      zeros: Mapping[str, float] | None = None, source_list: Sequence[str] = ()) -> dict[str, Any]:
    """JointStatePublisher's keyword settings as ROS 1's joint_state_publisher reads them from the server.

    Each of ``rate``, ``delta``, ``source_list``, ``zeros/JOINT`` and the five booleans is
    ``~name`` else ``name`` (the namespace's), else the given default (the command's flags).
    A ``zeros`` value of 0 counts as unset, as ``if not zeroval`` has it. A value of the wrong
    type raises :class:`RosArgsError` naming the parameter. ``dependent_joints`` (joint ->
    {parent, factor, offset}) makes joints follow others, a joint's own mimic tag first.
    """

    def get(name: str) -> Any:
        for key in ("~" + name, name):
            if store.has(key):
                return store.get(key)
        return None

    def wrong(name: str, value: Any, kind: str) -> RosArgsError:
        return RosArgsError(f"parameter {name}: {value!r} is not {kind}")

    settings: dict[str, Any] = {"rate": rate, "zeros": dict(zeros or {}), "source_list": list(source_list)}
    hz = get("rate")
    if hz is not None:
        if not (_number(hz) and hz > 0):
            raise wrong("rate", hz, "a positive number of Hz")
        settings["rate"] = float(hz)
    delta = get("delta")
    if delta is not None:
        if not _number(delta):
            raise wrong("delta", delta, "a number")
        settings["delta"] = float(delta)
    for flag in _BOOLS:
        value = get(flag)
        if value is not None:
            if not isinstance(value, bool):
                raise wrong(flag, value, "a bool")
            settings[flag] = value
    sources = get("source_list")
    if sources is not None:
        if not (isinstance(sources, list) and all(isinstance(s, str) for s in sources)):
            raise wrong("source_list", sources, "a list of topic names")
        settings["source_list"] = list(sources)
    # zeros/JOINT per joint, the private tree over the namespace's
    for key in ("zeros", "~zeros"):
        tree = store.get(key) if store.has(key) else {}
        if not isinstance(tree, dict):
            raise wrong(key, tree, "a map of joint names to numbers")
        for joint, value in tree.items():
            if not _number(value):
                raise wrong(f"{key}/{joint}", value, "a number")
            settings["zeros"][joint] = float(value)
    settings["zeros"] = {joint: value for joint, value in settings["zeros"].items() if value}
    dependent = get("dependent_joints")
    if dependent is not None:
        settings["dependent_joints"] = _dependent_joints(dependent)
    return settings


def _dependent_joints(tree: Any) -> dict[str, tuple[str, float, float]]:
    """``dependent_joints``: joint -> {parent, factor (1), offset (0)}, as joint_state_publisher reads it."""
    if not isinstance(tree, dict):
        raise RosArgsError(f"parameter dependent_joints: {tree!r} is not a map of joint names to "
                           "{parent, factor, offset}")
    found: dict[str, tuple[str, float, float]] = {}
    for joint, rule in tree.items():
        if not (isinstance(rule, dict) and isinstance(rule.get("parent"), str)):
            raise RosArgsError(f"parameter dependent_joints/{joint}: {rule!r} is not {{parent, factor, offset}}")
        factor, offset = rule.get("factor", 1.0), rule.get("offset", 0.0)
        if not (_number(factor) and _number(offset)):
            raise RosArgsError(f"parameter dependent_joints/{joint}: factor and offset must be numbers: {rule!r}")
        found[str(joint)] = (rule["parent"], float(factor), float(offset))
    return found
