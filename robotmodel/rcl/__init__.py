"""What ROS's rcl layer does for every node, without ROS: its arguments, parameters and console lines.

- ``--ros-args`` blocks, read as rcl reads them (:func:`take_ros_args` → :class:`RosArgs`):
  ``-r [node:]from:=to`` remaps (``__ns``/``__node`` move and rename the node; topic rules go
  to :class:`robotmodel.bus.Node` ``remappings=``, which applies them with
  :mod:`robotmodel.bus._remap`'s rcl semantics), ``-p``/``--params-file`` overrides typed and
  merged as rcl and rclcpp do (:func:`node_params`, :func:`typed_param`), the logging and
  enclave flags accepted; anything else is refused with rcl's text
  (:class:`robotmodel.errors.RosArgsError`). :func:`remove_ros_args` is rclpy's.
- ROS 1's forms on the ROS 1 wire (``__name:=``, ``__ns:=``, ``from:=to``, ``_param:=value``):
  :func:`take_node_args` reads them after the ``--ros-args`` blocks (:mod:`robotmodel.rcl._ros1args`).
- The node's name and namespace as ROS settles them (:func:`node_namespace`,
  :func:`split_ros_words`), and its logger name (:func:`logger_name`).
- rcutils' console lines (``[WARN] [sec.nanosec] [node]: text``): :func:`ros_log`,
  :func:`ros_console`.

``robotmodel launch`` writes these blocks (:mod:`robotmodel.launch`) and every node
command reads them here, so one set of rules decides what a word means::

    from robotmodel.rcl import node_params, take_ros_args

    ros, rest = take_ros_args(["--ros-args", "-r", "__ns:=/r1", "-p", "rate:=20"], "joint_state_publisher")
    ros.namespace, node_params(ros, ros.namespace, "joint_state_publisher")  # ('/r1', {'rate': 20})

Importing this package loads no third-party module (YAML only once a params file or value is read).
"""

from __future__ import annotations

from robotmodel.errors import RosArgsError
from robotmodel.rcl._args import (
    RosArgs,
    apply_log_levels,
    logger_name,
    node_namespace,
    node_params,
    remove_ros_args,
    split_node_words,
    split_ros_words,
    take_node_args,
    take_ros_args,
    warn_ignored_params,
)
from robotmodel.rcl._console import effective_level, log_enabled, log_line, ros_console, ros_log, set_log_level
from robotmodel.rcl._params import (
    ParamEntry,
    ParamValue,
    is_param_name,
    param_file_entries,
    param_rule_entry,
    param_type_name,
    params_for_node,
    typed_param,
    warn_unused_params,
)
from robotmodel.rcl._ros1args import Ros1Words, ros1_wire, take_ros1_args

__all__ = [
    "ParamEntry",
    "ParamValue",
    "Ros1Words",
    "RosArgs",
    "RosArgsError",
    "apply_log_levels",
    "effective_level",
    "is_param_name",
    "log_enabled",
    "log_line",
    "logger_name",
    "node_namespace",
    "node_params",
    "param_file_entries",
    "param_rule_entry",
    "param_type_name",
    "params_for_node",
    "remove_ros_args",
    "ros1_wire",
    "ros_console",
    "ros_log",
    "set_log_level",
    "split_node_words",
    "split_ros_words",
    "take_node_args",
    "take_ros1_args",
    "take_ros_args",
    "typed_param",
    "warn_ignored_params",
    "warn_unused_params",
]
