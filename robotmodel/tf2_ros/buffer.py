"""tf2_ros.buffer: :class:`Buffer`, whose lookups fail as tf2_ros's do.

tf2_ros's ``lookup_transform(..., timeout)`` waits for the transform and then looks it up
once more, so what it raises after the timeout is the tf2 error that explains the failure
(LookupException, ConnectivityException, ExtrapolationException), never TimeoutException:
the three-exception ``except`` of every listener catches it. This Buffer does the same
over :class:`robotmodel.tf.Buffer` (which wakes on the insert it waits for instead of
polling). Times and timeouts may be rospy's (``rospy.Time(0)``, ``rospy.Duration(1.0)``,
from :mod:`robotmodel.rospy`), rclpy's (anything with ``nanoseconds``) or robotmodel's.
"""

from __future__ import annotations

import contextlib
from typing import Any

from robotmodel.errors import TimeoutException
from robotmodel.msgs import TransformStamped
from robotmodel.tf import Buffer as _CoreBuffer

__all__ = ["Buffer"]


class Buffer(_CoreBuffer):
    """``Buffer(cache_time=None, debug=True)`` (rospy) or ``Buffer(cache_time=None, node=None)`` (rclpy).

    ``cache_time`` is any duration (rospy's, rclpy's, robotmodel's); default 10 s.
    ``debug`` and ``node`` are accepted for tf2_ros's signatures and unused.
    """

    def __init__(self, cache_time: Any = None, debug: bool = True, node: Any = None, **options: Any) -> None:
        del debug, node
        from robotmodel.time import Duration, to_nanoseconds

        super().__init__(None if cache_time is None else Duration(nanoseconds=to_nanoseconds(cache_time)),
                         **options)

    def lookup_transform(self, target_frame: str, source_frame: str, time: Any,
                         timeout: Any = None) -> TransformStamped:
        """As tf2_ros: wait up to ``timeout`` for the transform, then look it up (its error if still missing)."""
        if timeout is not None:
            self.can_transform(target_frame, source_frame, time, timeout)
        return super().lookup_transform(target_frame, source_frame, time)

    def lookup_transform_full(self, target_frame: str, target_time: Any, source_frame: str,
                              source_time: Any, fixed_frame: str, timeout: Any = None) -> TransformStamped:
        """The advanced lookup, waiting as :meth:`lookup_transform` does."""
        if timeout is not None:
            # Not via can_transform_full: robotmodel's calls lookup_transform_full, this method.
            with contextlib.suppress(TimeoutException):
                return super().lookup_transform_full(target_frame, target_time, source_frame, source_time,
                                                     fixed_frame, timeout)
        return super().lookup_transform_full(target_frame, target_time, source_frame, source_time, fixed_frame)
