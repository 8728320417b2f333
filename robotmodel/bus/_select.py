"""Which wire a session uses when nobody names one: the environment decides, as ROS's own setup does.

A sourced ROS 1 (``setup.bash`` of Noetic or Debian's ROS 1) exports ``ROS_VERSION=1`` and
``ROS_MASTER_URI``; a sourced ROS 2 exports ``ROS_VERSION=2`` and may name its middleware in
``RMW_IMPLEMENTATION``. :func:`default_wire` reads those, so that every command and the
Python API join the system the user's shell is set up for, without a flag.
"""

from __future__ import annotations

import os
from collections.abc import Mapping

__all__ = ["default_wire"]


def default_wire(environ: Mapping[str, str] | None = None) -> str:
    """The name of the wire (a key of :data:`robotmodel.bus.BACKENDS`) ``environ`` asks for.

    - ``ROS_VERSION=1`` with ``ROS_MASTER_URI`` set: ``"ros1"`` (a sourced ROS 1; the
      master is the one ``ROS_MASTER_URI`` names).
    - ``RMW_IMPLEMENTATION=rmw_zenoh_cpp``: ``"zenoh"``, as that ROS 2 speaks rmw_zenoh.
    - Anything else: ``"zenoh"``. A stock ROS 2 speaks DDS; the DDS wire (``"dds"``, chosen
      by name today) becomes the default for this case (any other ``RMW_IMPLEMENTATION``, or
      none) once every command is proven on it, and ``rmw_zenoh_cpp`` keeps zenoh then.

    ``environ`` defaults to ``os.environ``.
    """
    env = os.environ if environ is None else environ
    if env.get("ROS_VERSION", "").strip() == "1" and env.get("ROS_MASTER_URI", "").strip():
        return "ros1"
    return "zenoh"
