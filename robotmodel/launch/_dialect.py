"""Which launch XML a file is written in: ROS 1 (roslaunch) or ROS 2 (launch_ros), from its content.

The name alone does not tell: ``.launch.xml`` is ROS 2's suffix, yet many ROS 1 packages
name their includes so (turtlebot3_bringup's ``includes/description.launch.xml``,
ur_gazebo's ``inc/*.launch.xml``). The rules, in order:

1. A file included from a ROS 1 file is ROS 1: roslaunch reads every include as its own XML.
2. Else the content decides, when it uses only one dialect's words. ROS 1's: ``$(arg)``,
   ``$(find)``, ``$(optenv)``, ``<node type=...>`` or ``ns=``, ``<rosparam>``, ``<machine>``,
   ``<test>``, ``<param command|textfile|binfile=...>``, ``<arg doc=...>``, ``<include
   ns|pass_all_args=...>``, ``clear_params``. ROS 2's: ``$(var)``, ``$(find-pkg-share)`` and
   the other ROS 2-only substitutions, ``<node exec|namespace|ros_args=...>``, ``<let>``,
   ``<push-ros-namespace>``, ``<set_remap>``, ``<set_parameter>``, ``<executable>``,
   ``<param from=...>``, ``<arg description=...>``, ``<group scoped=...>``.
3. Else (both dialects' words, or neither) the name: ``.launch`` is ROS 1, ``.launch.xml``
   ROS 2; otherwise ROS 2 when the file shows ROS 2 words or its includer is ROS 2, else ROS 1.
"""

from __future__ import annotations

from pathlib import Path

from robotmodel.launch._model import Dialect
from robotmodel.launch._xml import Element

__all__ = ["detect_dialect"]

_ROS2_TAGS = frozenset({
    "let", "push-ros-namespace", "push_ros_namespace", "executable", "set_env", "set-env", "unset_env",
    "unset-env", "set_remap", "set-remap", "set_parameter", "set-parameter", "set_parameters_from_file",
})
_ROS1_TAGS = frozenset({"rosparam", "machine", "test"})
_ROS2_SUBST = ("$(var ", "$(find-pkg-share ", "$(find-pkg-prefix ", "$(find-exec ", "$(exec-in-pkg ", "$(command ",
               "$(not ", "$(and ", "$(or ", "$(equals ", "$(not-equals ", "$(file-content ", "$(filename)")
_ROS1_SUBST = ("$(arg ", "$(find ", "$(optenv ")
# Attributes only one dialect gives a tag.
_ROS2_ATTRS = {"node": {"exec", "namespace", "ros_args", "exec_name"}, "param": {"from"}, "arg": {"description"},
               "group": {"scoped", "forwarding"}}
_ROS1_ATTRS = {"node": {"type", "ns", "clear_params", "machine"}, "param": {"command", "textfile", "binfile"},
               "arg": {"doc"}, "include": {"ns", "pass_all_args", "clear_params"}, "group": {"clear_params"}}


def detect_dialect(path: Path, root: Element, includer: Dialect | None = None) -> Dialect:
    """The dialect of launch file ``path`` (parsed as ``root``), included from a file of ``includer``."""
    if includer is Dialect.ROS1:
        return Dialect.ROS1
    ros1, ros2 = _evidence(root)
    if ros1 != ros2:
        return Dialect.ROS1 if ros1 else Dialect.ROS2
    if path.name.endswith(".launch.xml"):
        return Dialect.ROS2
    if path.name.endswith(".launch"):
        return Dialect.ROS1
    return Dialect.ROS2 if ros2 or includer is Dialect.ROS2 else Dialect.ROS1


def _evidence(root: Element) -> tuple[bool, bool]:
    """Whether the file uses ROS 1-only words, and whether ROS 2-only ones."""
    ros1 = ros2 = False
    stack = [root]
    while stack and not (ros1 and ros2):
        elem = stack.pop()
        ros1 = ros1 or elem.tag in _ROS1_TAGS or bool(_ROS1_ATTRS.get(elem.tag, set()) & elem.attrib.keys())
        ros2 = ros2 or elem.tag in _ROS2_TAGS or bool(_ROS2_ATTRS.get(elem.tag, set()) & elem.attrib.keys())
        for value in (*elem.attrib.values(), elem.text):
            ros1 = ros1 or any(s in value for s in _ROS1_SUBST)
            ros2 = ros2 or any(s in value for s in _ROS2_SUBST)
        stack.extend(elem.children)
    return ros1, ros2
