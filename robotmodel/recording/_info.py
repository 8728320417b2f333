"""``ros2 bag info`` for any recording: ROS 1 ``.bag``, ROS 2 bag folders (db3 or MCAP), bare MCAP and db3.

What rosbag2 prints (``format_bag_meta_data``): files, bag size (a folder's files summed, as
rcutils sums the folder), storage id, ROS distro, duration, start and end (the first and the
last message's log time, local time then seconds), messages, one line per topic (type,
count, serialization format) and the services recorded as ``_service_event`` topics. A ROS 1
bag adds rosbag info's compression line (each compression's share of the chunks and, for a
compressed one, compressed size over uncompressed size), read from the chunk headers.

rosbags reads the index; its end times are one nanosecond after the last message
(``end_time``, ``duration``), which rosbag2 and rosbag do not count.
"""

from __future__ import annotations

import time
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import yaml

from robotmodel.errors import RecordingError
from robotmodel.recording._open import Format, Recording, reader_errors

__all__ = ["BagInfo", "BagTopic", "bag_info", "format_bag_info", "format_size", "format_time", "run_bag_info"]

_STORAGE = {Format.ROS1_BAG: "rosbag_v2", Format.MCAP: "mcap", Format.SQLITE3: "sqlite3"}
_INDENT = " " * 19
_SERVICE_SUFFIX = "/_service_event"


@dataclass(frozen=True)
class BagTopic:
    """One topic: name, ROS 2 type name, message count, serialization format (``cdr``, ``ros1``)."""

    name: str
    msgtype: str
    count: int
    serialization: str

    @property
    def is_service_event(self) -> bool:
        """Whether rosbag2 counts it as a service's events, not as a topic."""
        return self.name.endswith(_SERVICE_SUFFIX) and self.msgtype.endswith("_Event")


@dataclass(frozen=True)
class BagInfo:
    """What ``ros2 bag info`` reports; times in integer nanoseconds (0 and 0 when empty)."""

    path: Path
    files: tuple[str, ...]
    size: int
    storage_id: str
    ros_distro: str
    start_ns: int
    end_ns: int
    message_count: int
    topics: tuple[BagTopic, ...]
    compression: str | None = None  # ROS 1 bags: rosbag info's compression text

    @property
    def duration_ns(self) -> int:
        """End minus start."""
        return self.end_ns - self.start_ns

    @property
    def services(self) -> tuple[BagTopic, ...]:
        """The ``_service_event`` topics."""
        return tuple(t for t in self.topics if t.is_service_event)


def bag_info(path: str | Path) -> BagInfo:
    """Read the recording's index (no message is decoded); :class:`RecordingError` for what cannot be read."""
    path = Path(path)
    with Recording(path) as rec:
        reader: Any = rec._reader
        try:
            count = int(reader.message_count)
            start = int(reader.start_time) if count else 0
            end = int(reader.end_time) - 1 if count else 0
            topics = tuple(_topics(reader, rec.ros1))
            compression = _compression(reader) if rec.ros1 else None
            distro = None if rec.ros1 else getattr(reader, "ros_distro", None)
        except reader_errors() as exc:
            raise rec.damaged(exc) from None
        files, size, storage = _files(path, rec.format)
    return BagInfo(path, files, size, storage, distro or "unknown", start, end, count, topics, compression)


def _topics(reader: Any, ros1: bool) -> list[BagTopic]:
    out = []
    for name, info in sorted(reader.topics.items()):
        serialization = "ros1"
        if not ros1 and info.connections:
            serialization = getattr(info.connections[0].ext, "serialization_format", "cdr")
        out.append(BagTopic(name, info.msgtype or "", int(info.msgcount), serialization))
    return out


def _files(path: Path, fmt: Format) -> tuple[tuple[str, ...], int, str]:
    if fmt is not Format.ROS2_FOLDER:
        return (str(path),), path.stat().st_size, _STORAGE[fmt]
    try:
        meta = yaml.safe_load((path / "metadata.yaml").read_text(encoding="utf-8"))["rosbag2_bagfile_information"]
    except (OSError, yaml.YAMLError, KeyError, TypeError) as exc:
        raise RecordingError(f"{path}: metadata.yaml unreadable: {exc}") from None
    size = sum(p.stat().st_size for p in path.iterdir() if p.is_file())
    return tuple(str(p) for p in meta.get("relative_file_paths", [])), size, str(meta.get("storage_identifier", ""))


def _compression(reader: Any) -> str:
    """Rosbag info's compression text, from each chunk record's header (compression and uncompressed size)."""
    from rosbags.rosbag1.reader import Header, RecordType, read_uint32

    counts: dict[str, int] = {}
    packed: dict[str, int] = {}
    unpacked: dict[str, int] = {}
    for info in reader.chunk_infos:
        reader.bio.seek(info.pos)
        header = Header.read(reader.bio, RecordType.CHUNK)
        kind = header.get_string("compression")
        counts[kind] = counts.get(kind, 0) + 1
        unpacked[kind] = unpacked.get(kind, 0) + header.get_uint32("size")
        packed[kind] = packed.get(kind, 0) + read_uint32(reader.bio)
    if not counts:
        return "none"
    total = sum(counts.values())
    parts = []
    for count, kind in sorted(((c, k) for k, c in counts.items()), reverse=True):
        if kind == "none":
            parts.append(f"{kind} [{count}/{total} chunks]")
        else:
            parts.append(f"{kind} [{count}/{total} chunks; {100.0 * packed[kind] / unpacked[kind]:.2f}%]")
    return ", ".join(parts)


def format_size(size: int) -> str:
    """rosbag2's size: B, then KiB/MiB/GiB/TiB with one decimal."""
    value, unit = float(size), 0
    units = ("B", "KiB", "MiB", "GiB", "TiB")
    while value >= 1024 and unit < 4:
        value /= 1024
        unit += 1
    return f"{value:.{0 if unit == 0 else 1}f} {units[unit]}"


def format_time(ns: int) -> str:
    """rosbag2's time point: ``Mon d YYYY HH:MM:SS.nnnnnnnnn (sec.nnnnnnnnn)`` in local time."""
    seconds, fraction = divmod(ns, 1_000_000_000)
    local = time.localtime(seconds)
    return f"{time.strftime('%b %e %Y %H:%M:%S', local)}.{fraction:09d} ({seconds}.{fraction:09d})"


def _seconds(ns: int) -> str:
    seconds, fraction = divmod(ns, 1_000_000_000)
    return f"{seconds}.{fraction:09d}"


def format_bag_info(info: BagInfo) -> str:
    """The text ``ros2 bag info`` prints (a ROS 1 bag: rosbag info's compression line after the storage id)."""
    lines = ["", "Files:             " + (info.files[0] if info.files else "")]
    lines += [_INDENT + f for f in info.files[1:]]
    lines.append(f"Bag size:          {format_size(info.size)}")
    lines.append(f"Storage id:        {info.storage_id}")
    if info.compression is not None:
        lines.append(f"Compression:       {info.compression}")
    lines.append(f"ROS Distro:        {info.ros_distro}")
    lines.append(f"Duration:          {_seconds(info.duration_ns)}s")
    lines.append(f"Start:             {format_time(info.start_ns)}")
    lines.append(f"End:               {format_time(info.end_ns)}")
    services = info.services
    lines.append(f"Messages:          {info.message_count - sum(s.count for s in services)}")
    topics = [t for t in info.topics if not t.is_service_event]
    rows = [f"Topic: {t.name} | Type: {t.msgtype} | Count: {t.count} | Serialization Format: {t.serialization}"
            for t in topics]
    lines.append("Topic information: " + (rows[0] if rows else ""))
    lines += [_INDENT + row for row in rows[1:]]
    lines.append(f"Service:           {len(services)}")
    rows = [f"Service: {s.name.removesuffix(_SERVICE_SUFFIX)} | Type: {s.msgtype.removesuffix('_Event')} | "
            f"Event Count: {s.count} | Serialization Format: {s.serialization}" for s in services]
    lines.append("Service information: " + (rows[0] if rows else ""))
    lines += [" " * 21 + row for row in rows[1:]]
    return "\n".join(lines) + "\n"


def run_bag_info(path: str | Path) -> int:
    """``ros2 bag info PATH``: print the recording's summary; returns 0."""
    print(format_bag_info(bag_info(path)), end="", flush=True)
    return 0
