"""Which wire a session uses when nobody names one: the environment decides, as ROS's own setup does.

A sourced ROS 1 (``setup.bash`` of Noetic or Debian's ROS 1) exports ``ROS_VERSION=1`` and
``ROS_MASTER_URI``; a sourced ROS 2 exports ``ROS_VERSION=2`` and may name its middleware in
``RMW_IMPLEMENTATION``, whose default in a stock install is Fast DDS. :func:`default_wire`
reads those, so that every command and the Python API join the system the user's shell is
set up for, without a flag: the shell that makes the user's ROS nodes talk makes robotmodel talk.
"""

from __future__ import annotations

import os
from collections.abc import Mapping

from robotmodel.errors import BusError

__all__ = ["DDS_RMWS", "ZENOH_RMW", "default_wire"]

#: The ``RMW_IMPLEMENTATION`` of rmw_zenoh.
ZENOH_RMW = "rmw_zenoh_cpp"
#: ROS 2's DDS middlewares (the tier-1 three, then the others ROS 2 ships): all speak the DDS wire.
DDS_RMWS = ("rmw_fastrtps_cpp", "rmw_cyclonedds_cpp", "rmw_connextdds",
            "rmw_fastrtps_dynamic_cpp", "rmw_connextddsmicro", "rmw_gurumdds_cpp")


def default_wire(environ: Mapping[str, str] | None = None) -> str:
    """The name of the wire (a key of :data:`robotmodel.bus.BACKENDS`) ``environ`` asks for; raises BusError.

    - ``ROS_VERSION=1`` with ``ROS_MASTER_URI`` set: ``"ros1"`` (a sourced ROS 1; the
      master is the one ``ROS_MASTER_URI`` names).
    - ``RMW_IMPLEMENTATION=rmw_zenoh_cpp``: ``"zenoh"``, as that ROS 2 speaks rmw_zenoh.
    - ``RMW_IMPLEMENTATION`` one of :data:`DDS_RMWS`, or unset or empty: ``"dds"``, as a stock
      ROS 2 (Fast DDS by default) speaks DDS.
    - Any other ``RMW_IMPLEMENTATION``: a :class:`BusError` naming it (ROS fails to load an
      rmw it does not have, too).

    ``environ`` defaults to ``os.environ``.
    """
    env = os.environ if environ is None else environ
    if env.get("ROS_VERSION", "").strip() == "1" and env.get("ROS_MASTER_URI", "").strip():
        return "ros1"
    rmw = env.get("RMW_IMPLEMENTATION", "").strip()
    if rmw == ZENOH_RMW:
        return "zenoh"
    if not rmw or rmw in DDS_RMWS:
        return "dds"
    raise BusError(f"RMW_IMPLEMENTATION '{rmw}' is not a middleware robotmodel speaks "
                   f"(expected {ZENOH_RMW} for zenoh, or {', '.join(DDS_RMWS[:3])} or unset for DDS)")
