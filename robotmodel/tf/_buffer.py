"""tf2_ros.Buffer's Python API over :class:`BufferCore`, with real waiting.

Unlike tf2_ros's Python buffer, which polls every 20 ms and never raises
TimeoutException, a lookup with a timeout here sleeps on the buffer's condition
variable, wakes on every accepted insert, and raises :class:`TimeoutException` (with the
last reason) when the timeout expires.
"""

from __future__ import annotations

import time
from typing import Any, TypeVar

import numpy as np
import numpy.typing as npt

from robotmodel.errors import TimeoutException, TransformException
from robotmodel.msgs import (
    Header,
    PointStamped,
    PoseStamped,
    Quaternion,
    Transform,
    TransformStamped,
    Vector3,
    Vector3Stamped,
    stamp,
)
from robotmodel.spatial import Pose7, pose_compose
from robotmodel.tf._core import BufferCore
from robotmodel.tf._vector import lookup_many
from robotmodel.time import Duration, Time, to_nanoseconds

__all__ = ["Buffer"]

Stamped = TypeVar("Stamped", PointStamped, PoseStamped, Vector3Stamped)


def _message(pose: Pose7, stamp_ns: int, target: str, source: str) -> TransformStamped:
    return TransformStamped(
        header=Header(stamp=stamp(stamp_ns), frame_id=target),
        child_frame_id=source,
        transform=Transform(Vector3(pose[0], pose[1], pose[2]), Quaternion(pose[3], pose[4], pose[5], pose[6])),
    )


def _pose7(msg: TransformStamped) -> Pose7:
    t, r = msg.transform.translation, msg.transform.rotation
    return (t.x, t.y, t.z, r.x, r.y, r.z, r.w)


class Buffer(BufferCore):
    """A tf2_ros-style transform buffer: ``Buffer(cache_time=Duration(seconds=10))``."""

    def __init__(self, cache_time: Duration | None = None) -> None:
        super().__init__(to_nanoseconds(cache_time) if cache_time is not None else 10_000_000_000)

    def set_transform_static(self, transform: TransformStamped, authority: str) -> bool:
        """Insert a static transform, valid at all times."""
        return super().set_transform(transform, authority, True)

    def _wait(self, attempt: Any, timeout: Any, what: str) -> Any:
        timeout_ns = to_nanoseconds(timeout) if timeout is not None else 0
        if timeout_ns <= 0:
            return attempt()
        deadline = time.monotonic() + timeout_ns / 1e9
        with self._cond:
            while True:
                try:
                    return attempt()
                except TransformException as exc:
                    remaining = deadline - time.monotonic()
                    if remaining <= 0:
                        raise TimeoutException(
                            f"Timed out after {timeout_ns / 1e9:g} s waiting for transform {what}: {exc}",
                            target_frame=exc.target_frame, source_frame=exc.source_frame,
                            time_ns=exc.time_ns, earliest_ns=exc.earliest_ns, latest_ns=exc.latest_ns,
                        ) from exc
                    self._waiting += 1
                    try:
                        self._cond.wait(remaining)
                    finally:
                        self._waiting -= 1

    def lookup_transform(self, target_frame: str, source_frame: str, time: Any,
                         timeout: Any = None) -> TransformStamped:
        """The pose of ``source_frame`` in ``target_frame`` at ``time`` (``Time()`` = latest)."""
        t = to_nanoseconds(time)
        pose, stamp = self._wait(lambda: self.lookup_ns(target_frame, source_frame, t), timeout,
                                 f"from [{source_frame}] to [{target_frame}]")
        return _message(pose, stamp, target_frame, source_frame)

    def lookup_transform_full(self, target_frame: str, target_time: Any, source_frame: str,
                              source_time: Any, fixed_frame: str, timeout: Any = None) -> TransformStamped:
        """Source at ``source_time`` in target at ``target_time``, through a frame fixed over time."""
        tt, st = to_nanoseconds(target_time), to_nanoseconds(source_time)
        pose, stamp = self._wait(
            lambda: self.lookup_full_ns(target_frame, tt, source_frame, st, fixed_frame), timeout,
            f"from [{source_frame}] to [{target_frame}] via [{fixed_frame}]")
        return _message(pose, stamp, target_frame, source_frame)

    def can_transform(self, target_frame: str, source_frame: str, time: Any, timeout: Any = None,
                      return_debug_tuple: bool = False) -> bool | tuple[bool, str]:
        """Whether the lookup would succeed (waiting up to ``timeout``); with the reason on request."""
        try:
            self.lookup_transform(target_frame, source_frame, time, timeout)
        except TransformException as exc:
            return (False, str(exc)) if return_debug_tuple else False
        return (True, "") if return_debug_tuple else True

    def can_transform_full(self, target_frame: str, target_time: Any, source_frame: str, source_time: Any,
                           fixed_frame: str, timeout: Any = None,
                           return_debug_tuple: bool = False) -> bool | tuple[bool, str]:
        """``can_transform`` for the advanced (fixed-frame) form."""
        try:
            self.lookup_transform_full(target_frame, target_time, source_frame, source_time, fixed_frame,
                                       timeout)
        except TransformException as exc:
            return (False, str(exc)) if return_debug_tuple else False
        return (True, "") if return_debug_tuple else True

    def get_latest_common_time(self, target_frame: str, source_frame: str) -> Time:
        """The newest time at which the whole chain from source to target has data."""
        with self._cond:
            target_id = self._validate(target_frame, "get_latest_common_time")
            source_id = self._validate(source_frame, "get_latest_common_time")
            return Time(nanoseconds=self._latest_common_time(target_id, source_id, target_frame, source_frame))

    def transform(self, object_stamped: Stamped, target_frame: str, timeout: Any = None) -> Stamped:
        """A PointStamped/PoseStamped/Vector3Stamped expressed in ``target_frame`` (tf2_geometry_msgs)."""
        header = object_stamped.header
        msg = self.lookup_transform(target_frame, header.frame_id, header.stamp, timeout)
        t_target_source: Pose7 = _pose7(msg)
        new_header = Header(stamp=stamp(to_nanoseconds(header.stamp)), frame_id=target_frame)
        if isinstance(object_stamped, PointStamped):
            pt = object_stamped.point
            x, y, z = pose_compose(t_target_source, (pt.x, pt.y, pt.z, 0.0, 0.0, 0.0, 1.0))[:3]
            out_point = PointStamped(header=new_header)
            out_point.point.x, out_point.point.y, out_point.point.z = x, y, z
            return out_point
        if isinstance(object_stamped, Vector3Stamped):
            v = object_stamped.vector
            x, y, z = pose_compose((0.0, 0.0, 0.0, *t_target_source[3:]), (v.x, v.y, v.z, 0.0, 0.0, 0.0, 1.0))[:3]
            return Vector3Stamped(header=new_header, vector=Vector3(x, y, z))
        if isinstance(object_stamped, PoseStamped):
            pp, o = object_stamped.pose.position, object_stamped.pose.orientation
            out = pose_compose(t_target_source, (pp.x, pp.y, pp.z, o.x, o.y, o.z, o.w))
            result = PoseStamped(header=new_header)
            pos, ori = result.pose.position, result.pose.orientation
            pos.x, pos.y, pos.z = out[0], out[1], out[2]
            ori.x, ori.y, ori.z, ori.w = out[3], out[4], out[5], out[6]
            return result
        raise TypeError(f"Type {type(object_stamped).__name__} is not loaded or supported")

    def lookup_transforms(self, target_frame: str, source_frame: str,
                          times: npt.ArrayLike) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]:
        """Vectorized lookups at N stamps (integer ns; 0 = latest common time).

        Returns translations ``(N, 3)`` and quaternions ``(N, 4)`` (x, y, z, w), with the same
        semantics and errors as N calls of :meth:`lookup_transform`.
        """
        stamps = np.asarray(times, dtype=np.int64).reshape(-1)
        with self._cond:
            return lookup_many(self, target_frame, source_frame, stamps)
