"""TFMessage bytes straight from robot_state_publisher's arrays, without message objects.

For one set of joints (and one frame prefix) everything in a /tf message is fixed but
the stamps and the seven numbers of each pose: the frame strings, their lengths and the
padding. So the bytes are laid out once as a template, and each message copies it and
writes stamps and poses at known offsets with two NumPy assignments. Tests check the
result equals rosbags' CDR of the same TFMessage.
"""

from __future__ import annotations

import struct
from collections.abc import Sequence

import numpy as np

from robotmodel.spatial import FloatArray

__all__ = ["TFTemplate"]

_HEADER_LE = b"\x00\x01\x00\x00"
_U32 = struct.Struct("<I")
_STAMP = struct.Struct("<iI")


def _cstring(text: str, pos: int) -> tuple[bytes, int]:
    raw = text.encode()
    return _U32.pack(len(raw) + 1) + raw + b"\x00", pos + 4 + len(raw) + 1


class TFTemplate:
    """The CDR layout of a TFMessage with transforms ``parents[i] -> children[i]``."""

    def __init__(self, parents: Sequence[str], children: Sequence[str]) -> None:
        n = len(parents)
        chunks = [_HEADER_LE, _U32.pack(n)]
        pos = 4  # offsets in the body, which starts after the 4-byte encapsulation header
        stamp_at, pose_at = [], []
        for parent, child in zip(parents, children, strict=True):
            pad = -pos % 4  # a transform starts 4-aligned
            chunks.append(b"\x00" * pad)
            pos += pad
            stamp_at.append(pos)
            chunks.append(b"\x00" * 8)
            pos += 8
            frame, pos = _cstring(parent, pos)
            chunks.append(frame)
            pad = -pos % 4
            chunks.append(b"\x00" * pad)
            pos += pad
            child_bytes, pos = _cstring(child, pos)
            chunks.append(child_bytes)
            pad = -pos % 8  # doubles are 8-aligned
            chunks.append(b"\x00" * pad)
            pos += pad
            pose_at.append(pos)
            chunks.append(b"\x00" * 56)
            pos += 56
        self.template = b"".join(chunks)
        self.count = n
        body = 4
        self._stamp_index = np.array(stamp_at, dtype=np.intp)[:, None] + body + np.arange(8)
        self._pose_index = (np.array(pose_at, dtype=np.intp)[:, None] + body + np.arange(56)).reshape(-1)

    def encode(self, stamp_ns: int, translations: FloatArray, rotations: FloatArray) -> bytes:
        """The message's bytes: every transform stamped ``stamp_ns``, poses from ``(N, 3)`` and ``(N, 4)``."""
        buf = np.frombuffer(bytearray(self.template), dtype=np.uint8)
        if self.count:
            poses = np.empty((self.count, 7))
            poses[:, :3] = translations
            poses[:, 3:] = rotations
            buf[self._pose_index] = poses.view(np.uint8).reshape(-1)
            stamp = np.frombuffer(_STAMP.pack(*divmod(stamp_ns, 1_000_000_000)), dtype=np.uint8)
            buf[self._stamp_index] = stamp  # (N, 8) positions, one stamp broadcast over the rows
        return buf.tobytes()
