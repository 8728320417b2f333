"""``ros2 bag record``'s output: a bag folder holding ``NAME_0.mcap`` and rosbag2's ``metadata.yaml``.

rosbag2 names the folder ``rosbag2_YYYY_MM_DD-HH_MM_SS`` (local time) when no ``-o`` is
given, refuses a folder that exists, and writes ``metadata.yaml`` when the recording ends.
The metadata is rosbag2's version 9 (Jazzy's): what rosbags' and rosbag2's readers need to
open the folder (files, per-topic type, serialization format, offered QoS, type hash and
message count, start and duration).
"""

from __future__ import annotations

import datetime
from pathlib import Path
from typing import Any

from robotmodel._atomic import write_atomic
from robotmodel.errors import RecordingError
from robotmodel.recording._mcap import McapWriter

__all__ = ["default_folder_name", "open_bag_folder", "write_metadata"]

_VERSION = 9


def default_folder_name(now: datetime.datetime | None = None) -> str:
    """``rosbag2_YYYY_MM_DD-HH_MM_SS`` in local time, as ``ros2 bag record`` names a bag without ``-o``."""
    return (now or datetime.datetime.now()).strftime("rosbag2_%Y_%m_%d-%H_%M_%S")


def open_bag_folder(folder: Path) -> Path:
    """Create ``folder`` (never an existing one) and return the path of its storage file."""
    try:
        folder.mkdir(parents=True)
    except FileExistsError:
        raise RecordingError(f"Output folder '{folder}' already exists.") from None
    except OSError as exc:
        raise RecordingError(f"{folder}: cannot create the bag folder: {exc.strerror or exc}") from None
    return folder / f"{folder.name}_0.mcap"


def write_metadata(folder: Path, writer: McapWriter) -> None:
    """Write ``metadata.yaml`` for the bag ``writer`` recorded into ``folder`` (after it closed)."""
    import yaml

    from robotmodel.msgs import typestore

    start = writer.first_ns or 0
    duration = (writer.last_ns or start) - start
    store = typestore()
    topics: list[dict[str, Any]] = []
    for name, msgtype, qos, count in writer.topic_counts():
        topics.append({"topic_metadata": {"name": name, "type": msgtype, "serialization_format": "cdr",
                                          "offered_qos_profiles": qos,
                                          "type_description_hash": store.hash_rihs01(msgtype)},
                       "message_count": count})
    info = {"version": _VERSION, "storage_identifier": "mcap", "relative_file_paths": [writer.path.name],
            "duration": {"nanoseconds": duration}, "starting_time": {"nanoseconds_since_epoch": start},
            "message_count": writer.messages, "topics_with_message_count": topics,
            "compression_format": "", "compression_mode": "",
            "files": [{"path": writer.path.name, "starting_time": {"nanoseconds_since_epoch": start},
                       "duration": {"nanoseconds": duration}, "message_count": writer.messages}],
            "custom_data": None, "ros_distro": "jazzy"}
    write_atomic(folder / "metadata.yaml", yaml.safe_dump({"rosbag2_bagfile_information": info}, sort_keys=False))
