"""tf2_ros's runtime classes on the bus: broadcasters and a listener.

Code written for tf2_ros carries over with its imports changed and its node setup made
optional::

    from robotmodel.tf import Buffer
    from robotmodel.tf_ros import StaticTransformBroadcaster, TransformBroadcaster, TransformListener

    with TransformListener(buffer := Buffer()):
        t = buffer.lookup_transform("world", "tool", Time(), timeout=Duration(seconds=2))

This package sits on :mod:`robotmodel.bus`; :mod:`robotmodel.tf` (the buffer itself)
never imports it.
"""

from __future__ import annotations

from robotmodel.tf_ros._broadcaster import StaticTransformBroadcaster, TransformBroadcaster
from robotmodel.tf_ros._listener import DEFAULT_AUTHORITY, TransformListener

__all__ = ["DEFAULT_AUTHORITY", "StaticTransformBroadcaster", "TransformBroadcaster", "TransformListener"]
