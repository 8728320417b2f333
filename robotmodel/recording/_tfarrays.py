"""TFMessage bytes of many messages straight into NumPy arrays, checked against the reference decoders.

A /tf stream repeats the same message shape: the same frames in the same order, so the
same byte layout, with only stamps and poses changing. The first message of a shape is
decoded by the reference decoder (:func:`robotmodel.msgs.decode_tf_records` for CDR,
rosbags for ROS 1) and scanned for where its stamps and poses lie; the layout is kept
only when the values read at those offsets equal the reference's. Messages of that
length are then stacked into one ``(B, width)`` array of padded rows; those whose every
other byte (counts, string lengths, frame names, padding, encapsulation) equals the
proven message's (compared as masked 64-bit words) have the same layout by construction,
and their stamps and poses are read for all B at once (as whole int32/float64 words for
CDR). Anything else goes through the reference decoder one by one; a message it cannot
decode is left out and counted (``undecodable``), as the live listener drops one.
"""

from __future__ import annotations

import struct
from collections.abc import Callable
from dataclasses import dataclass
from itertools import chain
from typing import Any

import numpy as np
import numpy.typing as npt

from robotmodel.errors import MessageError
from robotmodel.msgs import TFRecord, decode_tf_records

__all__ = ["Block", "TFArrayDecoder", "ros1_reference"]

_NS = 1_000_000_000
_U32 = struct.Struct("<I")
_MAX_LAYOUTS_PER_LENGTH = 8
_LEAD = 4
_SEVEN = np.arange(7)


@dataclass(frozen=True, slots=True)
class Block:
    """B messages of one shape: T transforms each, as arrays.

    ``stamps`` (B, T) int64 ns, ``poses`` (B, T, 7) float64, ``order`` (B,) the
    messages' positions in the stream.
    """

    parents: tuple[str, ...]
    children: tuple[str, ...]
    stamps: npt.NDArray[np.int64]
    poses: npt.NDArray[np.float64]
    order: npt.NDArray[np.int64]


@dataclass(slots=True)
class _Layout:
    """Where one message shape keeps its values, in padded-row coordinates (see ``_rows``)."""

    parents: tuple[str, ...]
    children: tuple[str, ...]
    stamp_offs: list[int]  # where each transform's sec, nanosec start
    pose_offs: list[int]  # where its seven doubles start
    mask: npt.NDArray[np.uint64]  # all ones over structure bytes, zero over values
    template: npt.NDArray[np.uint64]  # the proven message's structure bytes (masked)
    aligned: bool  # stamps 4-aligned and poses 8-aligned in the row: read as words, not bytes


def _scan(data: bytes, ros1: bool) -> tuple[list[str], list[str], list[int], list[int], list[int]] | None:
    """Frame names and the offsets of each transform's stamp and pose; extra value bytes (ROS 1 seq)."""
    parents: list[str] = []
    children: list[str] = []
    stamps: list[int] = []
    poses: list[int] = []
    seqs: list[int] = []
    unpack = _U32.unpack_from
    try:
        if ros1:
            (count,) = unpack(data, 0)
            off = 4
        else:
            (count,) = unpack(data, 4)
            off = 8
        if count > len(data) // 64:
            return None
        for _ in range(count):
            if ros1:
                seqs.append(off)
                off += 4
            else:
                off += -off % 4
            stamps.append(off)
            off += 8
            names = []
            for _k in range(2):
                if not ros1:
                    off += -off % 4
                (n,) = unpack(data, off)
                off += 4
                raw = data[off:off + n]
                names.append((raw[:-1] if not ros1 else raw).decode())
                off += n
            if not ros1:
                off += -(off - 4) % 8
            parents.append(names[0])
            children.append(names[1])
            poses.append(off)
            off += 56
    except (struct.error, UnicodeDecodeError):
        return None
    if off != len(data):
        return None
    return parents, children, stamps, poses, seqs


class TFArrayDecoder:
    """Collects raw TFMessage payloads, then decodes them into :class:`Block` arrays in bulk.

    ``ros1`` selects ROS 1 serialization (``reference`` then decodes one message to
    TFRecords with rosbags); CDR messages are checked against robotmodel's own codec.
    """

    def __init__(self, ros1: bool = False, reference: Callable[[bytes], list[TFRecord]] | None = None) -> None:
        self.ros1 = ros1
        self._reference = reference or decode_tf_records
        self._layouts: dict[int, list[_Layout]] = {}
        self._pending: dict[int, list[tuple[int, bytes]]] = {}
        self.pending_messages = 0
        self.undecodable = 0  # messages the reference decoder refused (left out)
        self.first_error: tuple[int, str] | None = None  # (order, reason) of the first of them

    def add(self, order: int, data: bytes) -> None:
        """Queue one message (``order``: its position in the stream)."""
        self._pending.setdefault(len(data), []).append((order, data))
        self.pending_messages += 1

    def flush(self) -> tuple[list[Block], list[tuple[int, list[TFRecord]]]]:
        """Decode everything queued: array blocks, and (order, records) of messages taken one by one.

        A message that does not decode as a TFMessage is left out and counted in ``undecodable``.
        """
        blocks: list[Block] = []
        slow: list[tuple[int, list[TFRecord]]] = []
        pending, self._pending = self._pending, {}
        self.pending_messages = 0
        for length, items in pending.items():
            self._flush_length(length, items, blocks, slow)
        return blocks, slow

    def _flush_length(self, length: int, items: list[tuple[int, bytes]], blocks: list[Block],
                      slow: list[tuple[int, list[TFRecord]]]) -> None:
        if len(items) == 1 and length not in self._layouts:
            order, data = items[0]
            one = self._decode_one(order, data)
            if one is not None:
                slow.append((order, one))
            return
        orders = np.fromiter((o for o, _ in items), dtype=np.int64, count=len(items))
        arr = _rows([d for _, d in items], length)
        left = np.arange(len(items))
        layouts = self._layouts.setdefault(length, [])
        tried = 0
        while left.size:
            rows = arr if left.size == len(items) else arr[left]
            words = rows.view(np.uint64)
            taken = np.zeros(left.size, dtype=bool)
            for layout in layouts:
                diff = np.bitwise_xor(words, layout.template)
                diff &= layout.mask
                match = ~diff.any(axis=1) & ~taken
                if match.all():
                    blocks.append(self._extract(layout, rows, orders[left]))
                    taken = match
                elif match.any():
                    blocks.append(self._extract(layout, rows[match], orders[left[match]]))
                    taken |= match
            left = left[~taken]
            if not left.size:
                break
            first = int(left[0])
            data = items[first][1]
            records = self._decode_one(int(orders[first]), data)
            if records is None:
                left = left[1:]
                continue
            proven = self._prove(data, records) if tried < _MAX_LAYOUTS_PER_LENGTH else None
            tried += 1
            if proven is None or len(layouts) >= _MAX_LAYOUTS_PER_LENGTH:
                slow.append((int(orders[first]), records))
                left = left[1:]
            else:
                layouts.append(proven)

    def _decode_one(self, order: int, data: bytes) -> list[TFRecord] | None:
        try:
            return self._reference(data)
        except MessageError as exc:
            self.undecodable += 1
            if self.first_error is None or order < self.first_error[0]:
                self.first_error = (order, str(exc))
            return None

    def _prove(self, data: bytes, records: list[TFRecord]) -> _Layout | None:
        """The layout of ``data``, kept only if it reads exactly the reference's values."""
        scanned = _scan(data, self.ros1)
        if scanned is None:
            return None
        parents, children, stamp_offs, pose_offs, seq_offs = scanned
        if (parents != [r.parent for r in records] or children != [r.child for r in records]):
            return None
        row = _rows([data], len(data))
        stamp_offs = [o + _LEAD for o in stamp_offs]
        pose_offs = [o + _LEAD for o in pose_offs]
        value = np.zeros(row.shape[1], dtype=bool)
        for off in stamp_offs:
            value[off:off + 8] = True
        for off in pose_offs:
            value[off:off + 56] = True
        for off in seq_offs:
            value[off + _LEAD:off + _LEAD + 4] = True
        mask = np.where(value, np.uint8(0), np.uint8(0xFF)).view(np.uint64)
        aligned = all(o % 4 == 0 for o in stamp_offs) and all(o % 8 == 0 for o in pose_offs)
        layout = _Layout(tuple(parents), tuple(children), stamp_offs, pose_offs, mask,
                         row[0].view(np.uint64) & mask, aligned)
        block = self._extract(layout, row, np.zeros(1, dtype=np.int64))
        expect_stamps = [r.stamp_ns for r in records]
        expect_poses = np.array([r.pose for r in records], dtype=np.float64).reshape(-1, 7)
        same_poses = block.poses[0].tobytes() == expect_poses.tobytes()  # bit for bit, NaN included
        if block.stamps[0].tolist() != expect_stamps or not same_poses:
            return None
        return layout

    def _extract(self, layout: _Layout, rows: npt.NDArray[np.uint8], orders: npt.NDArray[np.int64]) -> Block:
        n, t = rows.shape[0], len(layout.children)
        if layout.aligned:
            # CDR aligns doubles to 8 and the row puts them on 8-byte words: a gather of words.
            ints = rows.view("<i4")
            idx = np.asarray(layout.stamp_offs, dtype=np.intp) // 4
            sec = np.take(ints, idx, axis=1).astype(np.int64)
            nanosec = np.take(ints, idx + 1, axis=1).astype(np.int64) & 0xFFFFFFFF
            pose_idx = (np.asarray(layout.pose_offs, dtype=np.intp)[:, None] // 8 + _SEVEN).ravel()
            poses = np.take(rows.view("<f8"), pose_idx, axis=1).reshape(n, t, 7)
            return Block(layout.parents, layout.children, sec * _NS + nanosec, poses, orders)
        # Unaligned (ROS 1): one contiguous slice copy per transform.
        stamp_bytes = np.empty((n, t, 8), dtype=np.uint8)
        pose_bytes = np.empty((n, t, 56), dtype=np.uint8)
        for j, (s_off, p_off) in enumerate(zip(layout.stamp_offs, layout.pose_offs, strict=True)):
            stamp_bytes[:, j] = rows[:, s_off:s_off + 8]
            pose_bytes[:, j] = rows[:, p_off:p_off + 56]
        pairs = stamp_bytes.view("<u4" if self.ros1 else "<i4").reshape(n, t, 2).astype(np.int64)
        if not self.ros1:
            pairs[..., 1] &= 0xFFFFFFFF  # nanosec is unsigned
        stamps = pairs[..., 0] * _NS + pairs[..., 1]
        return Block(layout.parents, layout.children, stamps, pose_bytes.view("<f8").reshape(n, t, 7), orders)


def _rows(datas: list[bytes], length: int) -> npt.NDArray[np.uint8]:
    """Messages of one length as rows of a byte array: ``_LEAD`` zero bytes, the message, zeros to 8.

    The lead puts CDR's body (which starts after the 4-byte encapsulation header) on an
    8-byte boundary, so its 8-aligned doubles fall on whole float64 words of the row.
    """
    width = -(-(length + _LEAD) // 8) * 8
    lead, tail = bytes(_LEAD), bytes(width - length - _LEAD)
    joined = b"".join(chain.from_iterable((lead, d, tail) for d in datas))
    return np.frombuffer(joined, dtype=np.uint8).reshape(len(datas), width)


def ros1_reference(deserialize: Callable[[bytes, str], Any]) -> Callable[[bytes], list[TFRecord]]:
    """A reference decoder of ROS 1 TFMessage bytes through rosbags' ``deserialize_ros1``."""
    from rosbags.serde import SerdeError

    def decode(data: bytes) -> list[TFRecord]:
        try:
            msg = deserialize(data, "tf2_msgs/msg/TFMessage")
        except (SerdeError, struct.error, ValueError, IndexError, UnicodeDecodeError) as exc:
            raise MessageError(f"cannot decode tf2_msgs/msg/TFMessage (ROS 1): {exc}") from None
        out = []
        for t in msg.transforms:
            s, tr, r = t.header.stamp, t.transform.translation, t.transform.rotation
            out.append(TFRecord(t.header.frame_id, t.child_frame_id, int(s.sec) * _NS + int(s.nanosec),
                                (tr.x, tr.y, tr.z, r.x, r.y, r.z, r.w)))
        return out

    return decode
