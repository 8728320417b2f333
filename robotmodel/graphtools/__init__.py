"""ros2cli's ``ros2 node`` and ``ros2 param`` on the bus (ROS 1's rosnode/rosparam forms too).

- :func:`run_node_list`, :func:`run_node_info`: the graph's nodes and one node's endpoints.
- :func:`run_param_list`, :func:`run_param_get`, :func:`run_param_set`, :func:`run_param_dump`:
  a node's parameters through its ROS 2 parameter services, or the ROS 1 parameter server
  on the ROS 1 wire.
"""

from __future__ import annotations

from robotmodel.graphtools._node import run_node_info, run_node_list
from robotmodel.graphtools._param import run_param_dump, run_param_get, run_param_list, run_param_set

__all__ = ["run_node_info", "run_node_list", "run_param_dump", "run_param_get", "run_param_list", "run_param_set"]
