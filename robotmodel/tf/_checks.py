"""tf2's input checks: insert validation (with its log texts), stamps and time arguments.

tf2 logs an invalid transform and drops it (setTransform returns false). A stamp outside
[0, 2**63) ns cannot be represented by tf2's time type at all (rclcpp and rclpy refuse
to build such a time), so it is rejected where it enters with InvalidArgumentException,
for inserts and for lookup arguments alike.
"""

from __future__ import annotations

import logging
import math
import operator
from typing import Any

import numpy as np
import numpy.typing as npt

from robotmodel.errors import InvalidArgumentException
from robotmodel.spatial import Pose7, quat_canonical, quats_canonical
from robotmodel.time import to_nanoseconds

__all__ = [
    "STAMP_LIMIT",
    "canonical_pose",
    "canonical_poses",
    "checked_stamps",
    "frame_ids_ok",
    "int_time_ns",
    "log",
    "stamp_ns",
    "time_arg_ns",
]

log = logging.getLogger("robotmodel.tf")

#: Stamps are integer nanoseconds in [0, STAMP_LIMIT): tf2's int64 time point, never negative.
STAMP_LIMIT = 2**63


def frame_ids_ok(parent: str, child: str, authority: str) -> bool:
    """tf2's frame id checks on the already slash-stripped ids, each failure logged with its text."""
    ok = True
    if child == parent:
        log.error('TF_SELF_TRANSFORM: Ignoring transform from authority "%s" with frame_id and  '
                  'child_frame_id "%s" because they are the same', authority, child)
        ok = False
    if not child:
        log.error('TF_NO_CHILD_FRAME_ID: Ignoring transform from authority "%s" because '
                  "child_frame_id not set ", authority)
        ok = False
    if not parent:
        log.error('TF_NO_FRAME_ID: Ignoring transform with child_frame_id "%s"  from authority "%s" '
                  "because frame_id not set", child, authority)
        ok = False
    return ok


def canonical_pose(pose: Any, child: str, authority: str) -> Pose7 | None:
    """The pose as tf2 stores it (quaternion through its matrix), or None after logging why not."""
    try:
        x, y, z, rx, ry, rz, rw = (float(v) for v in pose)
    except (TypeError, ValueError) as exc:
        raise InvalidArgumentException(
            f'Invalid pose for child_frame_id "{child}" from authority "{authority}": expected 7 numbers '
            f"(x, y, z, qx, qy, qz, qw) ({exc})") from None
    qx, qy, qz, qw = quat_canonical((rx, ry, rz, rw))
    ok = True
    if not all(math.isfinite(v) for v in (x, y, z, qx, qy, qz, qw)):
        log.error('TF_NAN_INPUT: Ignoring transform for child_frame_id "%s" from authority "%s" because '
                  "of a nan value in the transform (%f %f %f) (%f %f %f %f)", child, authority,
                  x, y, z, rx, ry, rz, rw)
        ok = False
    if math.isnan(qw):
        log.error('TF_DENORMALIZED_QUATERNION: Ignoring transform for child_frame_id "%s" from authority '
                  '"%s" because of an invalid quaternion in the transform (%f %f %f %f)', child,
                  authority, rx, ry, rz, rw)
        ok = False
    return (x, y, z, qx, qy, qz, qw) if ok else None


def canonical_poses(poses: npt.NDArray[np.float64], child: str,
                    authority: str) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.bool_]]:
    """Rows as tf2 stores them and which are valid; each invalid row is logged as by a single insert."""
    quats = quats_canonical(poses[:, 3:])
    out = np.empty_like(poses)
    out[:, :3] = poses[:, :3]
    out[:, 3:] = quats
    good: npt.NDArray[np.bool_] = np.asarray(np.isfinite(out).all(axis=1))
    for k in np.flatnonzero(~good).tolist():
        canonical_pose(poses[k], child, authority)  # logs tf2's texts for this row
    return out, good


def _stamp_error(value: Any, where: str, reason: str) -> InvalidArgumentException:
    return InvalidArgumentException(f'Invalid argument "{value}" passed to {where} - {reason}')


def stamp_ns(value: Any, child: str, authority: str) -> int:
    """An insert's stamp as an int in [0, 2**63), else InvalidArgumentException naming the frame."""
    try:
        ns = operator.index(value)
    except TypeError:
        raise InvalidArgumentException(
            f'Invalid stamp {value!r} for child_frame_id "{child}" from authority "{authority}": '
            "a stamp is an integer count of nanoseconds") from None
    if not 0 <= ns < STAMP_LIMIT:
        raise InvalidArgumentException(
            f'Invalid stamp {ns} ns for child_frame_id "{child}" from authority "{authority}": '
            + ("a tf2 time cannot be negative" if ns < 0 else "a tf2 time must be below 2^63 ns"))
    return ns


def int_time_ns(value: Any, where: str) -> int:
    """An integer-ns time argument in [0, 2**63), else InvalidArgumentException."""
    try:
        ns = operator.index(value)
    except TypeError:
        raise _stamp_error(value, where, "a time is an integer count of nanoseconds") from None
    if not 0 <= ns < STAMP_LIMIT:
        raise _stamp_error(value, where, "a tf2 time cannot be negative" if ns < 0
                           else "a tf2 time must be below 2^63 ns")
    return ns


def time_arg_ns(value: Any, where: str) -> int:
    """A time argument (Time, stamp message, rclpy time) in ns, checked as :func:`stamp_ns`."""
    try:
        ns = to_nanoseconds(value)
    except (TypeError, ValueError, OverflowError, AttributeError):
        raise _stamp_error(value, where, "time must have sec and nanosec, or nanoseconds.") from None
    if not 0 <= ns < STAMP_LIMIT:
        raise _stamp_error(value, where, "a tf2 time cannot be negative" if ns < 0
                           else "a tf2 time must be below 2^63 ns")
    return ns


def checked_stamps(values: Any, where: str) -> npt.NDArray[np.int64]:
    """A 1-D int64 array of stamps in [0, 2**63); anything else is InvalidArgumentException."""
    arr = np.asarray(values).reshape(-1)
    out = _stamp_array(arr)
    if out is None:
        # Built only on failure: the message renders the values, which costs milliseconds.
        raise _stamp_error(values, where, "stamps are integer nanoseconds in [0, 2^63)")
    if out.size and int(out.min()) < 0:
        raise _stamp_error(values, where, "a tf2 time cannot be negative")
    return out


def _stamp_array(arr: npt.NDArray[Any]) -> npt.NDArray[np.int64] | None:
    """``arr`` as int64 nanoseconds, or None when some value is no integer below 2**63."""
    kind = arr.dtype.kind
    if kind == "i":
        return arr.astype(np.int64, copy=False)
    if kind == "u":
        if arr.size and int(arr.max()) >= STAMP_LIMIT:
            return None
        return arr.astype(np.int64)
    if kind == "f":
        if not bool((np.isfinite(arr) & (arr == np.floor(arr)) & (arr < 2.0**63)).all()):
            return None
        return arr.astype(np.int64)
    if kind == "O":
        try:
            ints = [operator.index(v) for v in arr.tolist()]
        except TypeError:
            return None
        if any(not -STAMP_LIMIT <= v < STAMP_LIMIT for v in ints):
            return None
        return np.array(ints, dtype=np.int64)
    return None
