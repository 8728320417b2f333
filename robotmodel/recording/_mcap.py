"""Writing MCAP in rosbag2's shape: profile ``ros2``, ``ros2msg`` schemas, CDR messages.

Schemas are rosbags' ``generate_msgdef`` text (the concatenated .msg form rosbag2
writes) and channels carry rosbag2's ``offered_qos_profiles`` YAML and the type's RIHS01
hash, so rosbags' reader (which requires the ros2 profile), mcap's reader and rosbag2
read the file. The writer finishes its chunk and flushes it to the OS every
``flush_every_s`` seconds (on a write, or on :meth:`McapWriter.flush_if_due` called by
the owner's loop in quiet spells): after a crash, every message up to the last flushed chunk can
be recovered from the file (MCAP records are self-delimiting; only the summary at the
end is missing).
"""

from __future__ import annotations

import os
import threading
import time
from pathlib import Path
from typing import IO, Any

from robotmodel.errors import RecordingError

__all__ = ["McapWriter", "qos_yaml"]

_DEFAULT_FLUSH_S = 1.0


def qos_yaml(depth: int, reliable: bool = True, transient_local: bool = False) -> str:
    """rosbag2's ``offered_qos_profiles`` text for one keep-last publisher."""
    from rosbags.interfaces import Qos, QosDurability, QosHistory, QosLiveliness, QosReliability, QosTime
    from rosbags.rosbag2.metadata import dump_qos_v9

    never = QosTime(sec=9223372036, nsec=854775807)
    qos = Qos(QosHistory.KEEP_LAST, depth, QosReliability.RELIABLE if reliable else QosReliability.BEST_EFFORT,
              QosDurability.TRANSIENT_LOCAL if transient_local else QosDurability.VOLATILE, never, never,
              QosLiveliness.AUTOMATIC, never, False)
    return str(dump_qos_v9([qos]))


class McapWriter:
    """An MCAP file being written: ``add_topic`` each topic, then ``write`` raw CDR messages.

    Thread-safe (bus callbacks arrive on transport threads). ``close`` writes the summary;
    a writer that is never closed still leaves every flushed chunk readable. The file is
    created new (an existing file is a :class:`RecordingError`, never overwritten). Used as
    a context manager, a block that fails (an ``Exception``) before any message was
    written leaves no file behind (:meth:`discard`): a recording that could not start is
    no recording.
    """

    def __init__(self, path: str | os.PathLike[str], *, flush_every_s: float = _DEFAULT_FLUSH_S,
                 chunk_size: int = 1 << 20, library: str = "robotmodel") -> None:
        from mcap.writer import CompressionType, Writer

        self.path = Path(path)
        try:
            self._file: IO[bytes] = self.path.open("xb")
        except FileExistsError:
            raise RecordingError(f"{self.path}: already exists (not overwritten)") from None
        except OSError as exc:
            raise RecordingError(f"{self.path}: cannot write: {exc.strerror or exc}") from None
        self._writer: Any = Writer(self._file, chunk_size=chunk_size, compression=CompressionType.ZSTD)
        self._writer.start(profile="ros2", library=library)
        self._lock = threading.Lock()
        self._schemas: dict[str, int] = {}
        self._channels: dict[str, tuple[int, str]] = {}
        self._sequence: dict[str, int] = {}
        self._flush_every_ns = int(flush_every_s * 1e9)
        self._next_flush = time.monotonic_ns() + self._flush_every_ns
        self.messages = 0
        self._counts: dict[str, int] = {}
        self._qos: dict[str, str] = {}
        self.first_ns: int | None = None
        self.last_ns: int | None = None
        self._unflushed = False
        self.closed = False

    def __enter__(self) -> McapWriter:
        return self

    def __exit__(self, exc_type: type[BaseException] | None, exc: BaseException | None, tb: object) -> None:
        # Ctrl-C (KeyboardInterrupt) ends a recording as a stop does: the file is kept.
        if exc_type is not None and issubclass(exc_type, Exception) and self.messages == 0:
            self.discard()
        else:
            self.close()

    def add_topic(self, topic: str, msgtype: str, qos_profiles: str | None = None) -> None:
        """Declare ``topic`` of ROS 2 type ``msgtype`` (e.g. ``tf2_msgs/msg/TFMessage``); idempotent.

        Raises :class:`RecordingError` for a type rosbags' Jazzy typestore does not know,
        or a topic already declared with another type.
        """
        from robotmodel.msgs import typestore

        store = typestore()
        with self._lock:
            known = self._channels.get(topic)
            if known is not None:
                if known[1] != msgtype:
                    raise RecordingError(f"{self.path}: topic {topic} is {known[1]}, not {msgtype}")
                return
            if msgtype not in store.types:
                raise RecordingError(f"{self.path}: topic {topic}: unknown message type {msgtype}")
            schema = self._schemas.get(msgtype)
            if schema is None:
                text = store.generate_msgdef(msgtype, ros_version=2)[0]
                schema = self._schemas[msgtype] = self._writer.register_schema(
                    name=msgtype, encoding="ros2msg", data=text.encode())
            metadata = {"offered_qos_profiles": qos_profiles if qos_profiles is not None else qos_yaml(10),
                        "topic_type_hash": store.hash_rihs01(msgtype)}
            channel = self._writer.register_channel(topic=topic, message_encoding="cdr", schema_id=schema,
                                                    metadata=metadata)
            self._channels[topic] = (channel, msgtype)
            self._sequence[topic] = 0
            self._counts[topic] = 0
            self._qos[topic] = metadata["offered_qos_profiles"]

    def write(self, topic: str, log_ns: int, data: bytes, publish_ns: int | None = None) -> None:
        """Append one CDR message of a declared topic."""
        with self._lock:
            if self.closed:
                return
            channel = self._channels[topic][0]
            seq = self._sequence[topic] = self._sequence[topic] + 1
            self._writer.add_message(channel, log_time=log_ns, data=data,
                                     publish_time=log_ns if publish_ns is None else publish_ns, sequence=seq)
            self.messages += 1
            self._counts[topic] += 1
            self.first_ns = log_ns if self.first_ns is None else min(self.first_ns, log_ns)
            self.last_ns = log_ns if self.last_ns is None else max(self.last_ns, log_ns)
            self._unflushed = True
            now = time.monotonic_ns()
            if now >= self._next_flush:
                self._flush_locked(now)

    def _flush_locked(self, now: int) -> None:
        self._next_flush = now + self._flush_every_ns
        self._unflushed = False
        self._writer.flush()

    def flush(self) -> None:
        """Finish the chunk in progress and hand everything to the OS."""
        with self._lock:
            if not self.closed:
                self._flush_locked(time.monotonic_ns())

    def flush_if_due(self) -> None:
        """Flush when messages came in and the interval has passed (for quiet spells between messages)."""
        with self._lock:
            now = time.monotonic_ns()
            if not self.closed and self._unflushed and now >= self._next_flush:
                self._flush_locked(now)

    def close(self) -> None:
        """Write the summary and close the file (idempotent)."""
        with self._lock:
            if self.closed:
                return
            self.closed = True
            try:
                self._writer.finish()
            finally:
                self._file.close()

    def discard(self) -> None:
        """Close and delete the file (a recording that failed before it held anything); idempotent."""
        with self._lock:
            self.closed = True
            self._file.close()
            self.path.unlink(missing_ok=True)

    @property
    def topics(self) -> dict[str, Any]:
        """Declared topics and their types."""
        return {t: ty for t, (_, ty) in self._channels.items()}

    def topic_counts(self) -> list[tuple[str, str, str, int]]:
        """Each declared topic: (name, type, offered QoS YAML, messages written), in declaration order."""
        with self._lock:
            return [(t, ty, self._qos[t], self._counts[t]) for t, (_, ty) in self._channels.items()]
