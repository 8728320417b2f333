"""Streaming a recording's TF into an unbounded Buffer through bulk inserts.

Topics play roles by their recorded type: ``tf2_msgs/msg/TFMessage`` (static when the
name ends in ``tf_static``), ``sensor_msgs/msg/JointState`` and ``std_msgs/msg/String``
for ``/robot_description``. Dynamic /tf payloads are queued and decoded in bulk
(:mod:`._tfarrays`), then inserted per child frame with one ``insert_many`` per run of
increasing stamps and equal parent, in stamp order with the file order breaking ties, so
the buffer ends as after one tf2 insert per transform in file order. A /tf_static
message first flushes what is queued, so static/dynamic switches of a frame keep tf2's
order. Rows tf2 would reject (NaN/inf, a zero quaternion, bad frame ids) are skipped and
counted, with one warning for the whole file rather than one per transform. A message
that does not decode as its recorded type is skipped and counted the same way (the live
listener drops one with a warning too): the file is intact around it, so "truncated or
corrupt" stays for damage to the file itself.
"""

from __future__ import annotations

import itertools
import logging
import os
from collections.abc import Collection
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
import numpy.typing as npt

from robotmodel.errors import MessageError, RecordingError
from robotmodel.msgs import TFRecord, decode_tf_records
from robotmodel.recording._joints import JointStateTF
from robotmodel.recording._open import Recording, reader_errors
from robotmodel.recording._progress import Progress
from robotmodel.recording._tfarrays import Block, TFArrayDecoder, ros1_reference

if TYPE_CHECKING:
    from robotmodel.model import RobotDescription
    from robotmodel.tf import Buffer

__all__ = ["DEFAULT_TOPICS", "Loaded", "load_buffer", "load_recording"]

DEFAULT_TOPICS = ("/tf", "/tf_static", "/joint_states", "/robot_description")
TF_TYPE = "tf2_msgs/msg/TFMessage"
JOINT_STATE_TYPE = "sensor_msgs/msg/JointState"
STRING_TYPE = "std_msgs/msg/String"
# ROS 1 bags from before tf2 carry /tf as tf/tfMessage: the same fields, so the same bytes.
_OLD_TF_TYPE = "tf/msg/tfMessage"
_FLUSH_MESSAGES = 2048
_log = logging.getLogger("robotmodel.recording")


@dataclass(frozen=True, slots=True)
class Loaded:
    """A recording loaded into a buffer, and what was read."""

    buffer: Buffer
    path: Path
    messages: int  # messages read on the selected topics
    transforms: int  # transforms stored (static included)
    skipped: int  # transforms tf2 would reject (non-finite, zero quaternion, bad frame ids)
    start_ns: int  # first and last dynamic stamp (0 when none)
    end_ns: int
    robot_description: str | None  # the last recorded /robot_description
    from_joint_states: bool  # TF computed from /joint_states through the kinematics
    undecodable: int = 0  # messages skipped because they do not decode as their recorded type


class _Loader:
    def __init__(self, rec: Recording, buffer: Buffer, authority: str) -> None:
        self.rec = rec
        self.buffer = buffer
        self.authority = authority
        reference = ros1_reference(rec.deserialize) if rec.ros1 else decode_tf_records
        self.reference = reference
        self.decoder = TFArrayDecoder(rec.ros1, reference)
        self.accepted = 0
        self.skipped = 0
        self.undecodable = 0  # static, joint state and description messages that did not decode
        self.first_error: tuple[int, str, str] | None = None  # (order, topic, reason) of the first
        self.newest: dict[str, int] = {}
        self.held: dict[str, list[_Piece]] = {}
        self.start_ns = 2**63
        self.end_ns = 0

    # -------------------------------------------------------------- dynamic
    def flush(self) -> None:
        """Decode what is queued into per-child arrays, held until :meth:`commit`.

        Holding them lets each frame go into the buffer in one bulk insert, sized once,
        instead of regrowing its arrays (by an eighth at a time) at every flush.
        """
        if not self.decoder.pending_messages:
            return
        blocks, slow = self.decoder.flush()
        for child, parts in _by_child(blocks, slow).items():
            # Own copies of the columns, so that each decoded block is freed now.
            self.held.setdefault(child, []).extend(
                (p, np.array(st), np.array(po), np.array(o)) for p, st, po, o in parts)

    def commit(self) -> None:
        """Insert every held sample, frame by frame (each frame's arrays freed once inserted)."""
        self.flush()
        while self.held:
            child, parts = self.held.popitem()
            self._insert_child(child, parts)

    def _insert_child(self, child: str, parts: list[tuple[str, Any, Any, Any]]) -> None:
        names = sorted({p for p, _, _, _ in parts})
        code = {p: i for i, p in enumerate(names)}
        if len(parts) == 1:
            parent, stamps, poses, order = parts[0]
            pcodes = np.full(len(stamps), code[parent], dtype=np.int32)
        else:
            stamps = np.concatenate([s for _, s, _, _ in parts])
            poses = np.concatenate([p for _, _, p, _ in parts])
            order = np.concatenate([o for _, _, _, o in parts])
            pcodes = np.concatenate([np.full(len(s), code[p], dtype=np.int32) for p, s, _, _ in parts])
        if len(stamps) > 1 and not (stamps[1:] > stamps[:-1]).all():
            idx = np.lexsort((order, stamps))
            stamps, poses, pcodes = stamps[idx], poses[idx], pcodes[idx]
        # One reduction finds the usual case (all finite, no negative stamp); zero quaternions
        # are rare and left to insert_many, whose count of accepted rows tells them apart.
        if not np.isfinite(poses.sum()) or stamps[0] < 0:
            good = np.isfinite(poses).all(axis=1) & (stamps >= 0)
            self.skipped += int((~good).sum())
            stamps, poses, pcodes = stamps[good], poses[good], pcodes[good]
        if not len(stamps):
            return
        self.start_ns = min(self.start_ns, int(stamps[0]))
        self.end_ns = max(self.end_ns, int(stamps[-1]))
        for lo, hi in _runs(stamps, pcodes, self.newest.get(child.lstrip("/"), -1)):
            got = self.buffer.insert_many(names[int(pcodes[lo])], child, stamps[lo:hi], poses[lo:hi], self.authority)
            self.accepted += got
            self.skipped += hi - lo - got
        self.newest[child.lstrip("/")] = max(self.newest.get(child.lstrip("/"), -1), int(stamps[-1]))

    def undecoded(self, order: int, topic: str, exc: MessageError) -> None:
        """Count one message left out because it does not decode."""
        self.undecodable += 1
        if self.first_error is None:
            self.first_error = (order, topic, str(exc))

    def undecodable_report(self, dynamic_topic: str) -> str:
        """One line: how many messages did not decode, and why the first did not."""
        total = self.undecodable + self.decoder.undecodable
        firsts = [e for e in (self.first_error,) if e is not None]
        if self.decoder.first_error is not None:
            firsts.append((self.decoder.first_error[0], dynamic_topic, self.decoder.first_error[1]))
        _, topic, reason = min(firsts)
        return (f"{self.rec.path}: skipped {total} message(s) that do not decode as their recorded type "
                f"(first on {topic}: {' '.join(reason.split())[:200]})")

    # --------------------------------------------------------------- static
    def static(self, order: int, topic: str, data: bytes) -> None:
        self.commit()  # a frame switching between static and dynamic keeps tf2's order
        try:
            records = self.reference(data)
        except MessageError as exc:
            self.undecoded(order, topic, exc)
            return
        for parent, child, stamp_ns, pose in records:
            if not all(v - v == 0.0 for v in pose) or not any(pose[3:]) or stamp_ns < 0:
                self.skipped += 1
                continue
            ok = self.buffer.insert(parent, child, stamp_ns, pose, self.authority, is_static=True)
            self.accepted += ok
            self.skipped += not ok
            self.newest.pop(child.lstrip("/"), None)  # a switch to static drops the frame's history


_Piece = tuple[str, Any, Any, Any]  # parent, stamps (n,), poses (n, 7), order keys (n,)


def _by_child(blocks: list[Block], slow: list[tuple[int, list[TFRecord]]]) -> dict[str, list[_Piece]]:
    out: dict[str, list[_Piece]] = {}
    for b in blocks:
        width = len(b.children)
        orders = b.order[:, None] * 65536 + np.arange(width)
        for j in range(width):
            out.setdefault(b.children[j], []).append((b.parents[j], b.stamps[:, j], b.poses[:, j], orders[:, j]))
    grouped: dict[tuple[str, str], tuple[list[int], list[tuple[float, ...]], list[int]]] = {}
    for order, records in slow:
        for j, (parent, child, stamp_ns, pose) in enumerate(records):
            s, p, o = grouped.setdefault((child, parent), ([], [], []))
            s.append(stamp_ns)
            p.append(pose)
            o.append(order * 65536 + j)
    for (child, parent), (s, p, o) in grouped.items():
        out.setdefault(child, []).append((parent, np.asarray(s, dtype=np.int64), np.asarray(p, dtype=np.float64),
                                          np.asarray(o, dtype=np.int64)))
    return out


def _runs(stamps: npt.NDArray[np.int64], pcodes: npt.NDArray[np.int32], newest: int) -> list[tuple[int, int]]:
    """Row ranges of sorted ``stamps`` each insertable in one bulk step: increasing stamps, one parent.

    Rows not newer than the frame's data so far go first, together (row by row inside
    insert_many); a repeated stamp goes alone, so neither pushes a run off the bulk path.
    """
    n = len(stamps)
    first = int(np.searchsorted(stamps, newest, side="right")) if newest >= 0 else 0
    edges = {first, n}
    if first:
        edges.add(0)
    dups = np.flatnonzero(stamps[1:] <= stamps[:-1]) + 1
    edges.update((np.flatnonzero(pcodes[1:] != pcodes[:-1]) + 1).tolist())
    edges.update(dups.tolist())
    edges.update(d + 1 for d in dups.tolist() if d + 1 < n)
    ordered = sorted(edges)
    return [(lo, hi) for lo, hi in itertools.pairwise(ordered) if hi > lo]


def load_recording(
    path: str | os.PathLike[str],
    topics: Collection[str] | None = None,
    *,
    robot: RobotDescription | str | os.PathLike[str] | None = None,
    joint_states: bool | None = None,
    buffer: Buffer | None = None,
    progress: bool | None = None,
) -> Loaded:
    """Read a recording's TF into an unbounded :class:`~robotmodel.tf.Buffer`.

    ``topics`` defaults to /tf, /tf_static, /joint_states and /robot_description (those
    present are read). ``joint_states``: turn the recorded joint states into TF through
    the kinematics (None: only when no dynamic TF topic is read); the robot is ``robot``
    (a description, URDF/xacro path or text) or else the recorded /robot_description.
    ``progress``: a bar on stderr for reads over a second (None: when stderr is a
    terminal). Raises :class:`RecordingError` (one line: the file and what was read) for
    a file that is not a readable recording or a topic of an unexpected type. A message
    that does not decode as its type is skipped and counted (``Loaded.undecodable``, one
    warning for the file), as transforms tf2 would reject are.
    """
    from robotmodel.tf import Buffer

    wanted = list(DEFAULT_TOPICS if topics is None else topics)
    buf = buffer if buffer is not None else Buffer(unbounded=True)
    with Recording(Path(path)) as rec:
        roles: dict[str, str] = {}
        for topic in wanted:
            msgtype = rec.msgtype(topic)
            if msgtype is None:
                continue
            if msgtype in (TF_TYPE, _OLD_TF_TYPE):
                roles[topic] = "static" if topic.rstrip("/").endswith("tf_static") else "tf"
            elif msgtype == JOINT_STATE_TYPE:
                roles[topic] = "joints"
            elif msgtype == STRING_TYPE and topic.rstrip("/").endswith("robot_description"):
                roles[topic] = "description"
            else:
                expected = {"/joint_states": JOINT_STATE_TYPE, "/robot_description": STRING_TYPE}.get(topic, TF_TYPE)
                raise RecordingError(f"{rec.path}: topic {topic} has type {msgtype}, expected {expected} "
                                     "(nothing read)")
        use_joints = (joint_states if joint_states is not None
                      else "tf" not in roles.values()) and "joints" in roles.values()
        loader = _Loader(rec, buf, rec.path.name)
        joints = JointStateTF()
        description: str | None = None
        bar = Progress(str(rec.path), sum(t.count for t in rec.topics() if t.name in roles), progress)
        n = 0
        dynamic_topic = next((t for t, r in roles.items() if r == "tf"), "/tf")
        try:
            for n, (topic, _t_ns, data) in enumerate(rec.messages([t for t in wanted if t in roles]), 1):
                role = roles[topic]
                if role == "tf":
                    loader.decoder.add(n, data)
                    if loader.decoder.pending_messages >= _FLUSH_MESSAGES:
                        loader.flush()
                        bar.update(n)
                elif role == "static":
                    loader.static(n, topic, data)
                elif role == "joints" and not use_joints:
                    continue
                else:
                    try:
                        if role == "joints":
                            joints.add(rec.deserialize(data, JOINT_STATE_TYPE))
                        else:
                            description = str(rec.deserialize(data, STRING_TYPE).data)
                    except MessageError as exc:
                        loader.undecoded(n, topic, exc)
            loader.commit()
        except RecordingError:
            raise
        except reader_errors() as exc:
            raise rec.damaged(exc) from None
        finally:
            bar.close()
        undecodable = loader.undecodable + loader.decoder.undecodable
        if undecodable:
            _log.warning("%s", loader.undecodable_report(dynamic_topic))
        accepted, skipped = loader.accepted, loader.skipped
        start, end = (loader.start_ns, loader.end_ns) if loader.end_ns else (0, 0)
        if use_joints and len(joints):
            source = robot if robot is not None else description
            if source is None:
                raise RecordingError(f"{rec.path}: joint states without /tf need the robot: give its URDF, or "
                                     "record /robot_description")
            got, bad = joints.insert_into(buf, source, rec.path.name, str(rec.path))
            accepted, skipped = accepted + got, skipped + bad
            start, end = joints.span()
        if skipped:
            _log.warning("%s: skipped %d transform(s) tf2 would reject (non-finite values, zero quaternions or bad "
                         "frame ids)", rec.path, skipped)
        return Loaded(buf, rec.path, n, accepted, skipped, start, end, description, use_joints and len(joints) > 0,
                      undecodable)


def load_buffer(path: str | os.PathLike[str], topics: Collection[str] | None = None, **options: Any) -> Buffer:
    """The unbounded Buffer of :func:`load_recording` (same arguments)."""
    return load_recording(path, topics, **options).buffer
