"""``--namespace`` and ``--ros-args`` for the argparse-based node commands (rcl's rules: :mod:`robotmodel.rcl`)."""

from __future__ import annotations

import argparse

from robotmodel.rcl import RosArgs, node_namespace

__all__ = ["add_node_arguments", "settle"]


def add_node_arguments(parser: argparse.ArgumentParser, node_name: str) -> None:
    """Give a :class:`robotmodel.cli._parser.CommandParser` ``--namespace`` and ``--ros-args`` blocks.

    ``node_name`` is the node's default name (``node:``-prefixed rules for others are ignored).
    After parsing, ``args.namespace`` is the node's absolute namespace and ``args.node_name``
    the ``__node`` override (or None); see :func:`settle`.
    """
    parser.takes_ros_args = True  # type: ignore[attr-defined]
    parser.ros_node_name = node_name  # type: ignore[attr-defined]
    parser.add_argument("--namespace", metavar="NS", default=None,
                        help="the node's namespace ('r1' means /r1): relative topics such as joint_states "
                        "and robot_description move under it, /tf and /tf_static do not. ROS 2's "
                        "'--ros-args -r __ns:=/r1' (and -r __node:=NAME) also work, and win")
    parser.epilog = ((parser.epilog or "") + " ROS 2 arguments (--ros-args ... [--]) may follow: -r FROM:=TO "
                     "remaps a topic of this node (-r joint_states:=/arm/joint_states, -r /tf:=/r1/tf), "
                     "-r __ns:=/NS and -r __node:=NAME move and rename it, -p NAME:=VALUE and "
                     "--params-file FILE set parameters (merged as rclcpp merges them; one this "
                     "command has no use for is named in a warning).").strip()


def settle(parsed: argparse.Namespace, ros: RosArgs) -> None:
    """Replace ``parsed.namespace`` by the node's absolute namespace; set ``parsed.node_name`` and ``parsed.ros``.

    ``parsed.ros`` keeps the topic remaps (for ``Node(remappings=parsed.ros.remaps)``) and
    the parameter overrides (:func:`node_params`).
    """
    parsed.namespace = node_namespace(getattr(parsed, "namespace", None), ros)
    parsed.node_name = ros.node_name
    parsed.ros = ros


