"""ros2cli's ``ros2 node`` and ``ros2 param`` on the bus (ROS 1's rosnode/rosparam forms too).

- :func:`run_node_list`, :func:`run_node_info`: the graph's nodes and one node's endpoints.
- :func:`run_param_list`, :func:`run_param_get`, :func:`run_param_set`, :func:`run_param_dump`,
  :func:`run_param_delete`, :func:`run_param_describe`, :func:`run_param_load`: a node's
  parameters through its ROS 2 parameter services, or the ROS 1 parameter server on the ROS 1
  wire (:func:`parameter_file_values` reads a parameter file as ``ros2 param load`` does).
"""

from __future__ import annotations

from robotmodel.graphtools._node import run_node_info, run_node_list
from robotmodel.graphtools._param import run_param_dump, run_param_get, run_param_list, run_param_set
from robotmodel.graphtools._param_edit import (
    parameter_file_values,
    run_param_delete,
    run_param_describe,
    run_param_load,
)

__all__ = ["parameter_file_values", "run_node_info", "run_node_list", "run_param_delete", "run_param_describe",
           "run_param_dump", "run_param_get", "run_param_list", "run_param_load", "run_param_set"]
