"""ROS 1 tf2_msgs/TFMessage bytes straight from robot_state_publisher's arrays, without message objects.

The ROS 1 counterpart of :mod:`._tf_cdr`: for one set of joints (and one frame prefix) only
the stamps and the seven numbers of each pose change from message to message, so the
layout is worked out once and each message gathers its bytes through a fixed index. ROS 1
lays a TFMessage out without alignment (uint32 count; per transform uint32 seq, uint32
secs, uint32 nsecs, string frame_id, string child_frame_id as uint32 length and bytes,
seven float64), as :class:`robotmodel.bus._ros1codec.Ros1TFCodec` writes it; tests check
the bytes equal that codec's for the same TFMessage.
"""

from __future__ import annotations

import struct
from collections.abc import Sequence

import numpy as np

from robotmodel.spatial import FloatArray

__all__ = ["Ros1TFTemplate"]

_U32 = struct.Struct("<I")
_SECS_LIMIT = 1 << 32


class Ros1TFTemplate:
    """The ROS 1 layout of a TFMessage with transforms ``parents[i] -> children[i]``.

    A message is one gather from a buffer kept here: the stamp's 8 bytes, the translations
    and rotations as float64, then the fixed bytes (count, and per transform a zero seq and
    the two frame strings), through an index built here. Each message writes the stamp
    and the poses into the buffer, so one template serves one thread at a time (the
    publisher holds its lock).
    """

    def __init__(self, parents: Sequence[str], children: Sequence[str]) -> None:
        n = len(parents)
        names = [_U32.pack(len(p)) + p + _U32.pack(len(c)) + c
                 for p, c in ((p.encode(), c.encode()) for p, c in zip(parents, children, strict=True))]
        fixed_at = 8 + 56 * n  # stamp, translations, rotations: float64-aligned, first
        self._buffer = np.zeros(fixed_at + 4 + sum(4 + len(each) for each in names), dtype=np.uint8)
        self._buffer[fixed_at:] = np.frombuffer(
            _U32.pack(n) + b"".join(b"\x00\x00\x00\x00" + each for each in names), dtype=np.uint8)
        self._stamp = self._buffer[:8].view("<u4")
        self._translations = self._buffer[8:8 + 24 * n].view("<f8").reshape(n, 3)
        self._rotations = self._buffer[8 + 24 * n:fixed_at].view("<f8").reshape(n, 4)
        self._kept: FloatArray | None = None  # read-only translations already in the buffer
        index = [np.arange(fixed_at, fixed_at + 4)]
        at = fixed_at + 4
        for i, each in enumerate(names):
            index += [np.arange(at, at + 4), np.arange(8), np.arange(at + 4, at + 4 + len(each)),
                      np.arange(8 + 24 * i, 8 + 24 * i + 24), np.arange(8 + 24 * n + 32 * i, 8 + 24 * n + 32 * i + 32)]
            at += 4 + len(each)
        self.count = n
        self._index = np.concatenate(index)

    def encode(self, stamp_ns: int, translations: FloatArray, rotations: FloatArray) -> bytes | None:
        """The message's bytes: every transform stamped ``stamp_ns``, poses from ``(N, 3)`` and ``(N, 4)``.

        None when the stamp does not fit ROS 1's unsigned seconds (the message path names the error).
        """
        sec, nanosec = divmod(stamp_ns, 1_000_000_000)
        if not 0 <= sec < _SECS_LIMIT:
            return None
        self._stamp[:] = sec, nanosec
        if translations is not self._kept:
            self._translations[:] = translations
            # A read-only array owning its data (the origins, when no joint slides) stays as it is: copied once.
            frozen = translations.base is None and not translations.flags.writeable
            self._kept = translations if frozen else None
        self._rotations[:] = rotations
        return self._buffer.take(self._index).tobytes()
