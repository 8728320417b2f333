"""A hand-written reader of ROS 1 sensor_msgs/JointState bytes for robot_state_publisher: stamp, names, positions.

The generic path (rosbags' ROS 1 to CDR conversion, then the CDR decoder and a message
object) costs more than everything else robot_state_publisher does per message. This one
reads only what RSP reads, and the names only when their bytes differ from the previous
message's: a publisher sends the same names every time. Tests check it against the generic
path on random messages. Anything it does not expect (truncated or inconsistent bytes,
bytes after the message, a name that is not UTF-8 or holds a NUL) raises
:class:`CannotDecode`, and the caller uses the generic path, which names the error.

Layout (little-endian, no alignment): Header (uint32 seq, int32 sec, uint32 nanosec,
string frame_id), string[] name, float64[] position, velocity, effort; a string is a
uint32 byte count and the bytes, an array a uint32 count and its items.
"""

from __future__ import annotations

import struct
from typing import Any, NamedTuple

import numpy as np

from robotmodel.publishers._jointstate_cdr import CannotDecode
from robotmodel.spatial import FloatArray

__all__ = ["Ros1JointStateReader", "StateArrays"]

_HEADER = struct.Struct("<IiII")  # seq, sec, nanosec, frame_id length
_U32 = struct.Struct("<I")
_NS = 1_000_000_000


class StateArrays(NamedTuple):
    """What robot_state_publisher reads of a JointState: stamp, names, positions."""

    stamp_ns: int
    names: tuple[str, ...]
    positions: FloatArray


class Ros1JointStateReader:
    """Reads ROS 1 JointState payloads, remembering the last name list (its bytes and its tuple)."""

    def __init__(self) -> None:
        self._names_bytes = b""
        self._names: tuple[str, ...] = ()

    def read(self, payload: Any) -> StateArrays:
        """Stamp, names and positions of the JointState in ``payload``; :class:`CannotDecode` otherwise."""
        data = payload if type(payload) is bytes else bytes(payload)
        end = len(data)
        try:
            _seq, sec, nanosec, n = _HEADER.unpack_from(data, 0)
            pos = 16 + n
            if pos > end:
                raise CannotDecode("bad frame_id")
            data[16:pos].decode()  # unread by RSP, but bytes the generic path refuses are refused here too
            known = self._names_bytes
            # A name block is self-delimiting: equal leading bytes mean equal names.
            if known and data.startswith(known, pos):
                names = self._names
                pos += len(known)
            else:
                start = pos
                names, pos = _names(data, pos, end)
                self._names_bytes = data[start:pos]
                self._names = names
            (count,) = _U32.unpack_from(data, pos)
            pos += 4
            if count > (end - pos) >> 3:
                raise CannotDecode("bad position count")
            positions = np.frombuffer(data, "<f8", count, pos)
            pos += 8 * count
            for _ in range(2):  # velocity and effort: skipped, but they must be there whole
                (count,) = _U32.unpack_from(data, pos)
                pos += 4 + 8 * count
        except (struct.error, UnicodeDecodeError) as exc:
            raise CannotDecode(str(exc)) from exc
        if pos != end:
            raise CannotDecode("the lengths do not add up to the payload's")
        return StateArrays(sec * _NS + nanosec, names, positions)


def _names(data: bytes, pos: int, end: int) -> tuple[tuple[str, ...], int]:
    (count,) = _U32.unpack_from(data, pos)
    pos += 4
    if count > (end - pos) >> 2:
        raise CannotDecode("bad name count")
    names = []
    for _ in range(count):
        (n,) = _U32.unpack_from(data, pos)
        start = pos + 4
        pos = start + n
        raw = data[start:pos]
        if pos > end or b"\x00" in raw:
            raise CannotDecode("bad name")
        names.append(raw.decode())
    return tuple(names), pos
