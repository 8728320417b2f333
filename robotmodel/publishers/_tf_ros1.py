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
_STAMP = struct.Struct("<II")
_SECS_LIMIT = 1 << 32


class Ros1TFTemplate:
    """The ROS 1 layout of a TFMessage with transforms ``parents[i] -> children[i]``.

    A message is one gather from the concatenation of the fixed bytes (count, and per
    transform a zero seq and the two frame strings), the stamp's 8 bytes and the bytes of
    the translations and rotations, through an index built here.
    """

    def __init__(self, parents: Sequence[str], children: Sequence[str]) -> None:
        n = len(parents)
        names = [_U32.pack(len(p)) + p + _U32.pack(len(c)) + c
                 for p, c in ((p.encode(), c.encode()) for p, c in zip(parents, children, strict=True))]
        fixed = _U32.pack(n) + b"".join(b"\x00\x00\x00\x00" + each for each in names)
        stamp = len(fixed)
        translations, rotations = stamp + 8, stamp + 8 + 24 * n
        index = [np.arange(4)]
        at = 4
        for i, each in enumerate(names):
            index += [np.arange(at, at + 4), np.arange(stamp, stamp + 8), np.arange(at + 4, at + 4 + len(each)),
                      np.arange(translations + 24 * i, translations + 24 * i + 24),
                      np.arange(rotations + 32 * i, rotations + 32 * i + 32)]
            at += 4 + len(each)
        self.fixed = np.frombuffer(fixed, dtype=np.uint8)
        self.count = n
        self._index = np.concatenate(index)

    def encode(self, stamp_ns: int, translations: FloatArray, rotations: FloatArray) -> bytes | None:
        """The message's bytes: every transform stamped ``stamp_ns``, poses from ``(N, 3)`` and ``(N, 4)``.

        None when the stamp does not fit ROS 1's unsigned seconds (the message path names the error).
        """
        sec, nanosec = divmod(stamp_ns, 1_000_000_000)
        if not 0 <= sec < _SECS_LIMIT:
            return None
        source = np.concatenate((self.fixed, np.frombuffer(_STAMP.pack(sec, nanosec), dtype=np.uint8),
                                 np.ascontiguousarray(translations, dtype="<f8").view(np.uint8),
                                 np.ascontiguousarray(rotations, dtype="<f8").view(np.uint8)), axis=None)
        return source.take(self._index).tobytes()
