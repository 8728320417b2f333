r"""Opening a recording with rosbags, whatever its format, and reading its messages raw.

Formats, told by their first bytes rather than their names: ROS 1 ``.bag``
(``#ROSBAG V2.0``), bare MCAP (``\x89MCAP0``), bare sqlite3 ``.db3`` (``SQLite format 3``)
and ROS 2 bag folders (``metadata.yaml`` with ``.db3`` or ``.mcap`` storage). Every
failure of rosbags (or of the file system) becomes one :class:`RecordingError` naming the
file and how many messages were read before it.
"""

from __future__ import annotations

import importlib
import struct
from collections.abc import Collection, Iterator
from dataclasses import dataclass
from enum import Enum
from functools import lru_cache
from pathlib import Path
from typing import TYPE_CHECKING, Any

from robotmodel.errors import MessageError, RecordingError

if TYPE_CHECKING:
    from rosbags.typesys.store import Typestore

__all__ = ["Format", "Recording", "Topic", "detect_format", "reader_errors", "ros1_typestore"]

_ROS1_MAGIC = b"#ROSBAG V2.0\n"
_MCAP_MAGIC = b"\x89MCAP0\r\n"
_SQLITE_MAGIC = b"SQLite format 3\x00"
_TFMESSAGE_ROS1 = "geometry_msgs/TransformStamped[] transforms"


class Format(Enum):
    """The container of a recording."""

    ROS1_BAG = "ROS 1 bag"
    MCAP = "MCAP"
    SQLITE3 = "ROS 2 sqlite3 bag"
    ROS2_FOLDER = "ROS 2 bag folder"


@dataclass(frozen=True, slots=True)
class Topic:
    """One topic of a recording: its name, ROS 2 type name and message count."""

    name: str
    msgtype: str
    count: int


def detect_format(path: Path) -> Format:
    """The format of ``path`` from its first bytes; :class:`RecordingError` when none fits."""
    if path.is_dir():
        if (path / "metadata.yaml").is_file():
            return Format.ROS2_FOLDER
        raise RecordingError(f"{path}: not a recording (a folder without metadata.yaml)")
    try:
        with path.open("rb") as f:
            head = f.read(16)
    except OSError as exc:
        raise RecordingError(f"{path}: cannot read: {exc.strerror or exc}") from None
    if not head:
        raise RecordingError(f"{path}: empty file, not a recording")
    if head.startswith(_ROS1_MAGIC[:len(head)]) and len(head) >= 13:
        return Format.ROS1_BAG
    if head.startswith(_MCAP_MAGIC):
        return Format.MCAP
    if head.startswith(_SQLITE_MAGIC):
        return Format.SQLITE3
    raise RecordingError(f"{path}: not a recording (neither a ROS 1 bag, an MCAP file nor a ROS 2 sqlite3 bag)")


@lru_cache(maxsize=1)
def ros1_typestore() -> Typestore:
    """Rosbags' ROS 1 Noetic typestore with tf2_msgs/TFMessage added (Noetic's store lacks it)."""
    from rosbags.typesys import Stores, get_types_from_msg, get_typestore

    store = get_typestore(Stores.ROS1_NOETIC)
    if "tf2_msgs/msg/TFMessage" not in store.types:
        store.register(get_types_from_msg(_TFMESSAGE_ROS1, "tf2_msgs/msg/TFMessage"))
    return store


@lru_cache(maxsize=1)
def reader_errors() -> tuple[type[BaseException], ...]:
    """What rosbags, mcap, sqlite3/apsw and the decompressors raise for damaged input."""
    from rosbags.rosbag1 import ReaderError as Ros1Error
    from rosbags.rosbag2 import ReaderError as Ros2Error
    from rosbags.serde import SerdeError

    # Damaged files surface from rosbags' parsers and the decompressors as many types.
    found: list[type[BaseException]] = [Ros1Error, Ros2Error, SerdeError, OSError, EOFError, ValueError, KeyError,
                                        IndexError, struct.error, AssertionError, TypeError, AttributeError,
                                        RuntimeError, MemoryError]
    # rosbags reads .db3 files through apsw (SQLite's own binding), not only sqlite3.
    for module, name in (("backports.zstd", "ZstdError"), ("zstandard", "ZstdError"), ("sqlite3", "Error"),
                         ("apsw", "Error")):
        try:
            found.append(getattr(importlib.import_module(module), name))
        except (ImportError, AttributeError):
            continue
    try:
        from mcap.exceptions import McapError

        found.append(McapError)
    except ImportError:
        pass
    return tuple(found)


def _truncated_mcap(path: Path, exc: BaseException) -> RecordingError:
    """The error for an MCAP without a readable summary, saying how much its records still hold."""
    from mcap.records import Message
    from mcap.stream_reader import StreamReader

    count, last = 0, None
    try:
        with path.open("rb") as f:
            for record in StreamReader(f, emit_chunks=False).records:
                if isinstance(record, Message):
                    count += 1
                    last = record.log_time
    except reader_errors():
        pass  # counting stops at the first damaged record
    upto = f" up to t={last / 1e9:.9f}" if last is not None else ""
    return RecordingError(f"{path}: truncated or corrupt MCAP ({_reason(exc)}); {count} message(s) readable{upto} "
                          "(the mcap CLI's 'mcap recover' rebuilds such a file)")


def _reason(exc: BaseException) -> str:
    text = " ".join(str(exc).split()) or type(exc).__name__
    return text[:200]


class Recording:
    """An open recording: its format, topics and a stream of its raw messages.

    >>> with Recording("run.mcap") as rec:            # doctest: +SKIP
    ...     for topic, t, data in rec.messages(["/tf"]):
    ...         ...
    """

    def __init__(self, path: str | Path) -> None:
        self.path = Path(path)
        self.format = detect_format(self.path)
        self.ros1 = self.format is Format.ROS1_BAG
        self.read = 0  # messages delivered so far (named in errors)
        self.last_ns: int | None = None
        errors = reader_errors()
        try:
            if self.ros1:
                from rosbags.rosbag1 import Reader as Ros1Reader

                self._reader: Any = Ros1Reader(self.path)
            else:
                from rosbags.rosbag2 import Reader as Ros2Reader

                self._reader = Ros2Reader(self.path)
            self._reader.open()
        except errors as exc:
            if self.format is Format.MCAP:
                raise _truncated_mcap(self.path, exc) from None
            raise RecordingError(f"{self.path}: cannot open as a {self.format.value}: {_reason(exc)}") from None
        self._connections: dict[str, list[Any]] = {}
        for conn in self._reader.connections:
            self._connections.setdefault(conn.topic, []).append(conn)

    def __enter__(self) -> Recording:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def close(self) -> None:
        """Close the file (idempotent)."""
        try:
            self._reader.close()
        except reader_errors():
            pass

    @property
    def message_count(self) -> int:
        """Messages in the whole recording, from its index."""
        return int(self._reader.message_count)

    @property
    def start_ns(self) -> int:
        """The first message's log time (the recording's start), from its index."""
        return int(self._reader.start_time)

    def connections(self, topic: str) -> list[Any]:
        """The rosbags connections recorded for ``topic`` (their ``ext`` holds the QoS or ROS 1 latching)."""
        return list(self._connections.get(topic, ()))

    def topics(self) -> list[Topic]:
        """Topics with their type and count, by name."""
        out = []
        for name in sorted(self._connections):
            conns = self._connections[name]
            out.append(Topic(name, conns[0].msgtype, sum(int(c.msgcount) for c in conns)))
        return out

    def msgtype(self, topic: str) -> str | None:
        """The ROS 2 type name recorded for ``topic`` (None when absent)."""
        conns = self._connections.get(topic)
        return conns[0].msgtype if conns else None

    def check_type(self, topic: str, expected: str) -> bool:
        """Whether ``topic`` is present; :class:`RecordingError` if it has another type than ``expected``."""
        conns = self._connections.get(topic, [])
        for conn in conns:
            if conn.msgtype != expected:
                raise RecordingError(f"{self.path}: topic {topic} has type {conn.msgtype}, expected {expected} "
                                     "(nothing read)")
        return bool(conns)

    def messages(self, topics: Collection[str]) -> Iterator[tuple[str, int, bytes]]:
        """(topic, log time ns, raw bytes) of the messages on ``topics``, in log-time order."""
        conns = [c for t in topics for c in self._connections.get(t, ())]
        if not conns:
            return
        errors = reader_errors()
        try:
            for conn, t, data in self._reader.messages(connections=conns):
                self.last_ns = t
                yield conn.topic, t, data
                self.read += 1
        except errors as exc:
            raise self.damaged(exc) from None

    def damaged(self, exc: BaseException) -> RecordingError:
        """The error for a file that failed mid-read: what broke and how much was read."""
        last_ns = self.last_ns
        where = f" (log time up to {last_ns / 1e9:.9f})" if last_ns is not None else ""
        return RecordingError(f"{self.path}: truncated or corrupt {self.format.value} after {self.read} "
                              f"message(s){where}: {_reason(exc)}")

    def deserialize(self, data: bytes, msgtype: str) -> Any:
        """A rosbags message object of ``msgtype`` from this recording's serialization.

        Raises :class:`MessageError` for bytes that do not decode as ``msgtype``: the
        message is bad, not the file.
        """
        try:
            if self.ros1:
                return ros1_typestore().deserialize_ros1(data, msgtype)
            from robotmodel.msgs import typestore

            return typestore().deserialize_cdr(data, msgtype)
        except reader_errors() as exc:
            raise MessageError(f"cannot decode {len(data)} bytes as {msgtype}: {_reason(exc)}") from None
