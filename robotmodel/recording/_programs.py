"""``record`` and ``tf-export`` as programs: topics from the bus into MCAP; a frame pair's poses out of a recording."""

from __future__ import annotations

import sys
from collections.abc import Sequence
from pathlib import Path

__all__ = ["run_record", "run_tf_export"]

_NODE = "rosbag2_recorder"
_RECORDED = ("/tf", "/tf_static", "/joint_states", "/robot_description")


def run_record(output: str | None, topics: Sequence[str] = (), *, all_topics: bool = False,
               flush_interval: float = 1.0, connect: Sequence[str] = ()) -> int:
    """``ros2 bag record`` into MCAP until SIGINT/SIGTERM (default topics: TF, joint states, the robot); exit code.

    rosbag2's ros2 profile, CDR payloads, receive times as log times. ``output`` ending in
    ``.mcap`` is one MCAP file; any other name is a bag folder as ``ros2 bag record -o``
    writes it (``NAME/NAME_0.mcap`` and ``metadata.yaml``), and none is the folder
    ``rosbag2_YYYY_MM_DD-HH_MM_SS``. A stop finishes the file (summary and index) and the
    folder's metadata; a crash leaves every chunk flushed so far (one per ``flush_interval``
    seconds) recoverable. An existing ``output`` is never overwritten. ``all_topics``
    records every topic the graph shows, now or later (``-a``); then no default topics.
    """
    from robotmodel.bus import Node
    from robotmodel.rcl import ros_log
    from robotmodel.recording._bagdir import default_folder_name, open_bag_folder, write_metadata
    from robotmodel.recording._mcap import McapWriter
    from robotmodel.recording._record import Recorder
    from robotmodel.signals import stop_on_signals

    if not flush_interval > 0:
        print("robotmodel record: error: --flush-interval must be > 0", file=sys.stderr)
        return 2
    bare = output is not None and output.endswith(".mcap")
    out = Path(output or default_folder_name())
    folder = None if bare else out
    if out.exists():
        what = f"{out} already exists (not overwritten)" if folder is None else f"Output folder '{out}' already exists."
        print(f"robotmodel record: error: {what}", file=sys.stderr)
        return 1
    stop = stop_on_signals()
    try:
        with McapWriter(out if folder is None else open_bag_folder(folder), flush_every_s=flush_interval) as writer, \
                Node(_NODE, connect=list(connect)) as node:
            recorder = Recorder(node, writer, list(topics) or ([] if all_topics else list(_RECORDED)),
                                all_topics=all_topics,
                                on_subscribed=lambda t, _ty: ros_log("INFO", _NODE, f"Subscribed to topic '{t}'"))
            ros_log("INFO", _NODE, f"Recording to '{out}'...")
            try:
                # Flushes in quiet spells too, so a crash never loses more than one interval.
                while not stop.wait(flush_interval / 2):
                    writer.flush_if_due()
            finally:
                recorder.close()
    finally:
        if folder is not None and folder.is_dir() and not any(folder.iterdir()):
            folder.rmdir()  # a recording that could not start leaves nothing behind
    if folder is not None:
        write_metadata(folder, writer)
    ros_log("INFO", _NODE, f"Recording stopped: {writer.messages} message(s) in '{out}'")
    return 0


def run_tf_export(bag: str, source_frame: str, target_frame: str, output: str, *, rate: float | None = None,
                  urdf: str | None = None, progress: bool | None = None) -> int:
    """Write ``target_frame``'s pose in ``source_frame`` over the recording to CSV (or Parquet); the exit code.

    At the recorded stamps, or every 1/``rate`` s; ``urdf`` and ``progress`` as in
    :func:`robotmodel.recording.load_recording`.
    """
    from robotmodel.recording._export import pose_series, write_poses
    from robotmodel.recording._load import load_recording

    if rate is not None and not 0 < rate < float("inf"):
        print("robotmodel tf-export: error: --rate must be a positive number", file=sys.stderr)
        return 2
    loaded = load_recording(bag, robot=urdf, progress=progress)
    series = pose_series(loaded.buffer, source_frame, target_frame, rate)
    write_poses(series, output)
    print(f"{len(series.stamps)} pose(s) of {target_frame} in {source_frame} written to {output}", file=sys.stderr)
    return 0
