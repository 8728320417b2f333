"""tf2_ros's runtime classes on the bus: broadcasters and a listener.

Code written for tf2_ros carries over with its imports changed and its node setup made
optional::

    from robotmodel.tf import Buffer
    from robotmodel.tf_ros import StaticTransformBroadcaster, TransformBroadcaster, TransformListener

    with TransformListener(buffer := Buffer()):
        t = buffer.lookup_transform("world", "tool", Time(), timeout=Duration(seconds=2))

The ROS programs built on them, each taking its words as ROS's does (the ``robotmodel``
commands call these): :func:`run_static_transform_publisher` (ROS 2's flags and positional
forms, ROS 1's with a period; :func:`parse_static_args`), :func:`run_tf2_echo` (live, or
over a recording with ``--bag``), :func:`run_view_frames`.

This package sits on :mod:`robotmodel.bus`; :mod:`robotmodel.tf` (the buffer itself)
never imports it.
"""

from __future__ import annotations

from robotmodel.tf_ros._broadcaster import StaticTransformBroadcaster, TransformBroadcaster
from robotmodel.tf_ros._echo_program import run_tf2_echo
from robotmodel.tf_ros._listener import DEFAULT_AUTHORITY, TransformListener
from robotmodel.tf_ros._static_args import StaticTransformSpec, parse_static_args
from robotmodel.tf_ros._static_program import run_static_transform_publisher
from robotmodel.tf_ros._view_frames import run_view_frames

__all__ = [
    "DEFAULT_AUTHORITY",
    "StaticTransformBroadcaster",
    "StaticTransformSpec",
    "TransformBroadcaster",
    "TransformListener",
    "parse_static_args",
    "run_static_transform_publisher",
    "run_tf2_echo",
    "run_view_frames",
]
