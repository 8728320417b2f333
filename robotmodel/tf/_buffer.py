"""tf2_ros.Buffer's Python API over :class:`BufferCore`, with real waiting.

Unlike tf2_ros's Python buffer, which polls every 20 ms and never raises
TimeoutException, a lookup with a timeout here sleeps until an insert touches a frame
the lookup depends on, and raises :class:`TimeoutException` (with the last reason) when
the timeout expires. ``wait_for_transform_async`` returns a future resolved by the insert
that makes the transform available, with its callbacks run outside the buffer's lock (tf2's
transformable requests). Every failure of this API is a tf2 exception (TransformException),
invalid times and frame ids included, and ``can_transform`` always answers a bool.
"""

from __future__ import annotations

import threading
import time
from collections.abc import Callable
from concurrent.futures import Future
from typing import Any, TypeVar

import numpy as np
import numpy.typing as npt

from robotmodel.errors import InvalidArgumentException, TimeoutException, TransformException
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
from robotmodel.msgs.builtin_interfaces import Time as StampMsg
from robotmodel.spatial import Pose7, pose_compose
from robotmodel.tf._checks import checked_stamps, time_arg_ns
from robotmodel.tf._core import BufferCore
from robotmodel.tf._vector import lookup_many
from robotmodel.time import Duration, Time, to_nanoseconds

__all__ = ["Buffer"]

Stamped = TypeVar("Stamped", PointStamped, PoseStamped, Vector3Stamped)


_new = object.__new__


def _message(pose: Pose7, stamp_ns: int, target: str, source: str) -> TransformStamped:
    # This runs on every lookup: the six objects are made without their dataclass __init__
    # (a Python call each, a third of the cost) and every field is set here, so the message
    # equals the one the constructors give (tests/tf/test_buffer_api.py checks it field by field).
    x, y, z, qx, qy, qz, qw = pose
    stamp = _new(StampMsg)
    stamp.sec, stamp.nanosec = divmod(stamp_ns, 1_000_000_000)
    header = _new(Header)
    header.stamp, header.frame_id = stamp, target
    translation = _new(Vector3)
    translation.x, translation.y, translation.z = x, y, z
    rotation = _new(Quaternion)
    rotation.x, rotation.y, rotation.z, rotation.w = qx, qy, qz, qw
    transform = _new(Transform)
    transform.translation, transform.rotation = translation, rotation
    msg = _new(TransformStamped)
    msg.header, msg.child_frame_id, msg.transform = header, source, transform
    return msg


def _timeout_ns(timeout: Any) -> int:
    try:
        return to_nanoseconds(timeout)
    except (TypeError, ValueError, OverflowError, AttributeError):
        raise InvalidArgumentException(
            f'Invalid argument "{timeout}" passed to timeout - duration must have sec and nanosec, '
            "or nanoseconds.") from None


def _pose7(msg: TransformStamped) -> Pose7:
    t, r = msg.transform.translation, msg.transform.rotation
    return (t.x, t.y, t.z, r.x, r.y, r.z, r.w)


class Buffer(BufferCore):
    """A tf2_ros-style transform buffer: ``Buffer(cache_time=Duration(seconds=10))``.

    ``unbounded=True`` keeps every sample of every frame (offline use, e.g. a whole
    recording): nothing is pruned and nothing is too old; ``cache_time`` is then unused.
    """

    def __init__(self, cache_time: Duration | None = None, *, unbounded: bool = False) -> None:
        window = None if unbounded else (time_arg_ns(cache_time, "Buffer argument cache_time")
                                         if cache_time is not None else 10_000_000_000)
        super().__init__(window)

    def set_transform_static(self, transform: TransformStamped, authority: str) -> bool:
        """Insert a static transform, valid at all times."""
        return super().set_transform(transform, authority, True)

    def _wait(self, attempt: Callable[[], Any], timeout: Any, what: str, ends: list[tuple[str, int]]) -> Any:
        """``attempt()``, retried until it succeeds or ``timeout`` expires.

        Between attempts the thread sleeps until an insert touches one of the frames the
        lookup depends on (as tf2's transformable requests), not on every insert.
        """
        if timeout is None:
            return attempt()
        timeout_ns = _timeout_ns(timeout)
        if timeout_ns <= 0:
            return attempt()
        deadline = time.monotonic() + timeout_ns / 1e9
        with self._lock:
            while True:
                try:
                    return attempt()
                except InvalidArgumentException:
                    raise  # waiting cannot fix the arguments
                except TransformException as exc:
                    remaining = deadline - time.monotonic()
                    if remaining <= 0:
                        raise TimeoutException(
                            f"Timed out after {timeout_ns / 1e9:g} s waiting for transform {what}: {exc}",
                            target_frame=exc.target_frame, source_frame=exc.source_frame,
                            time_ns=exc.time_ns, earliest_ns=exc.earliest_ns, latest_ns=exc.latest_ns,
                        ) from exc
                    self._sleep_until_touched(self._dependencies(ends), remaining)

    def _sleep_until_touched(self, frames: set[str], seconds: float) -> None:
        cond = threading.Condition(self._lock)
        for name in frames:
            self._waiters.setdefault(name, []).append(cond)
        try:
            cond.wait(seconds)
        finally:
            for name in frames:
                waiting = self._waiters[name]
                waiting.remove(cond)
                if not waiting:
                    del self._waiters[name]

    def wait_for_transform_async(self, target_frame: str, source_frame: str,
                                 time: Any) -> Future[TransformStamped]:
        """A future of the transform at ``time``, resolved as soon as an insert makes it available.

        As tf2_ros (Jazzy): the result is the TransformStamped, there is no timeout (cancel the
        future to stop waiting). Done-callbacks run in the inserting thread, never under the
        buffer's lock.
        """
        t = time_arg_ns(time, "waitForTransform argument time")
        return self._request(lambda: _message(*self.lookup_ns(target_frame, source_frame, t), target_frame,
                                              source_frame), [(target_frame, t), (source_frame, t)])

    def wait_for_transform_full_async(self, target_frame: str, target_time: Any, source_frame: str,
                                      source_time: Any, fixed_frame: str) -> Future[TransformStamped]:
        """:meth:`wait_for_transform_async` for the advanced (fixed-frame) form."""
        tt = time_arg_ns(target_time, "waitForTransform argument target_time")
        st = time_arg_ns(source_time, "waitForTransform argument source_time")
        return self._request(
            lambda: _message(*self.lookup_full_ns(target_frame, tt, source_frame, st, fixed_frame), target_frame,
                             source_frame),
            [(target_frame, tt), (fixed_frame, tt), (fixed_frame, st), (source_frame, st)])

    def _request(self, attempt: Callable[[], TransformStamped],
                 ends: list[tuple[str, int]]) -> Future[TransformStamped]:
        """tf2's transformable request: retried by inserts into the frames the lookup depends on."""
        future: Future[TransformStamped] = Future()
        registered: set[str] = set()
        one_at_a_time = threading.Lock()

        def unregister() -> None:
            for name in registered:
                waiting = self._waiters[name]
                waiting.remove(retry)
                if not waiting:
                    del self._waiters[name]
            registered.clear()

        def retry() -> None:
            with one_at_a_time:
                if future.done():
                    return
                with self._lock:
                    if future.done():  # cancelled meanwhile
                        return
                    unregister()
                    try:
                        result = attempt()
                    except InvalidArgumentException as exc:
                        failure: TransformException | None = exc
                    except TransformException:
                        registered.update(self._dependencies(ends))
                        for name in registered:
                            self._waiters.setdefault(name, []).append(retry)
                        return
                    else:
                        failure = None
                # Outside the buffer's lock: the future's done-callbacks run here.
                if failure is not None:
                    future.set_exception(failure)
                else:
                    future.set_result(result)

        def forget(done: Future[TransformStamped]) -> None:
            if done.cancelled():
                with self._lock:
                    unregister()

        future.add_done_callback(forget)
        retry()
        return future

    def lookup_transform(self, target_frame: str, source_frame: str, time: Any,
                         timeout: Any = None) -> TransformStamped:
        """The pose of ``source_frame`` in ``target_frame`` at ``time`` (``Time()`` = latest)."""
        # robotmodel.time.Time is immutable and always within [0, 2**63) ns.
        t = time.nanoseconds if type(time) is Time else time_arg_ns(time, "lookupTransform argument time")
        if timeout is None:
            pose, stamp_ns = self.lookup_ns(target_frame, source_frame, t)
        else:
            pose, stamp_ns = self._wait(lambda: self.lookup_ns(target_frame, source_frame, t), timeout,
                                        f"from [{source_frame}] to [{target_frame}]",
                                        [(target_frame, t), (source_frame, t)])
        return _message(pose, stamp_ns, target_frame, source_frame)

    def lookup_transform_full(self, target_frame: str, target_time: Any, source_frame: str,
                              source_time: Any, fixed_frame: str, timeout: Any = None) -> TransformStamped:
        """Source at ``source_time`` in target at ``target_time``, through a frame fixed over time."""
        tt = time_arg_ns(target_time, "lookupTransform argument target_time")
        st = time_arg_ns(source_time, "lookupTransform argument source_time")
        pose, stamp_ns = self._wait(
            lambda: self.lookup_full_ns(target_frame, tt, source_frame, st, fixed_frame), timeout,
            f"from [{source_frame}] to [{target_frame}] via [{fixed_frame}]",
            [(target_frame, tt), (fixed_frame, tt), (fixed_frame, st), (source_frame, st)])
        return _message(pose, stamp_ns, target_frame, source_frame)

    def can_transform(self, target_frame: str, source_frame: str, time: Any, timeout: Any = None,
                      return_debug_tuple: bool = False) -> bool | tuple[bool, str]:
        """Whether the lookup would succeed (waiting up to ``timeout``); with the reason on request.

        Always a bool (or the tuple): any failure, invalid arguments included, is False.
        """
        try:
            t = time_arg_ns(time, "canTransform argument time")
            self._wait(lambda: self.lookup_ns(target_frame, source_frame, t), timeout,
                       f"from [{source_frame}] to [{target_frame}]", [(target_frame, t), (source_frame, t)])
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
        with self._lock:
            target_id = self._validate(target_frame, "get_latest_common_time")
            source_id = self._validate(source_frame, "get_latest_common_time")
            return Time(nanoseconds=self._latest_common_time(target_id, source_id, target_frame, source_frame))

    def transform(self, object_stamped: Stamped, target_frame: str, timeout: Any = None) -> Stamped:
        """A PointStamped/PoseStamped/Vector3Stamped expressed in ``target_frame`` (tf2_geometry_msgs)."""
        if not isinstance(object_stamped, PointStamped | PoseStamped | Vector3Stamped):
            raise InvalidArgumentException(f"Type {type(object_stamped).__name__} is not loaded or supported")
        header = object_stamped.header
        msg = self.lookup_transform(target_frame, header.frame_id, header.stamp, timeout)
        t_target_source: Pose7 = _pose7(msg)
        new_header = Header(stamp=stamp(time_arg_ns(header.stamp, "transform argument header.stamp")),
                            frame_id=target_frame)
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
        raise InvalidArgumentException(f"Type {type(object_stamped).__name__} is not loaded or supported")

    def lookup_transforms(self, target_frame: str, source_frame: str,
                          times: npt.ArrayLike) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]:
        """Vectorized lookups at N stamps (integer ns; 0 = latest common time).

        Returns translations ``(N, 3)`` and quaternions ``(N, 4)`` (x, y, z, w), with the same
        semantics and errors as N calls of :meth:`lookup_transform`.
        """
        if isinstance(times, np.ndarray) and times.size < 4 and times.dtype.kind == "i":
            times = times.reshape(-1).tolist()
        if isinstance(times, list) and 0 < len(times) < 4 and all(type(t) is int for t in times):
            # A few stamps: scalar lookups, without NumPy's per-call cost (same checks and errors);
            # one (N, 7) array, returned as its two column views.
            poses = np.array([self.lookup_ns(target_frame, source_frame, t)[0] for t in times])
            return poses[:, :3], poses[:, 3:]
        stamps = checked_stamps(times, "lookup_transforms argument times")
        with self._lock:
            return lookup_many(self, target_frame, source_frame, stamps)
