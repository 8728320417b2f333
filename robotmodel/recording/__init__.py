"""TF from recordings (ROS 1 bags, ROS 2 bags, MCAP) and recording the bus to MCAP.

- :func:`load_buffer` / :func:`load_recording`: a recording's /tf, /tf_static (and
  /joint_states through the kinematics) in an unbounded :class:`robotmodel.tf.Buffer`,
  streamed and inserted in bulk.
- :class:`Recording`: any supported file opened with rosbags, its topics and raw messages.
- :func:`pose_series` and :func:`write_poses`: a frame pair's poses over time, to CSV or Parquet;
  :func:`sample_times`: evenly spaced instants over a span, refused when absurdly many.
- :class:`McapWriter` and :class:`Recorder`: MCAP files in rosbag2's ros2 profile (CDR),
  written from the bus, crash-tolerant chunk by chunk.
- :func:`bag_info` / :func:`format_bag_info`: ``ros2 bag info``'s summary of any recording.
- :class:`Player` and :class:`PlayOptions`: a recording played onto the bus (``ros2 bag play``),
  with /clock for ``use_sim_time``.
- :func:`run_record`, :func:`run_tf_export`, :func:`run_bag_info` and :func:`run_bag_play`: the
  ``record``, ``tf-export``, ``bag info`` and ``bag play`` programs.

The core (:mod:`robotmodel.tf`) does not depend on this package: a buffer is filled from
here, not the other way round.
"""

from __future__ import annotations

from robotmodel.recording._export import (
    COLUMNS,
    MAX_ROWS,
    MAX_STEPS,
    PoseSeries,
    pose_series,
    sample_times,
    write_poses,
)
from robotmodel.recording._info import BagInfo, BagTopic, bag_info, format_bag_info, run_bag_info
from robotmodel.recording._load import DEFAULT_TOPICS, Loaded, load_buffer, load_recording
from robotmodel.recording._mcap import McapWriter, qos_yaml
from robotmodel.recording._open import Format, Recording, Topic, detect_format, ros1_typestore
from robotmodel.recording._play import DEFAULT_CLOCK_HZ, LATCHED_TOPICS, Player, PlayOptions, parse_topics, run_bag_play
from robotmodel.recording._programs import run_record, run_tf_export
from robotmodel.recording._record import KNOWN_TOPICS, Recorder

__all__ = [
    "COLUMNS",
    "DEFAULT_CLOCK_HZ",
    "DEFAULT_TOPICS",
    "KNOWN_TOPICS",
    "LATCHED_TOPICS",
    "MAX_ROWS",
    "MAX_STEPS",
    "BagInfo",
    "BagTopic",
    "Format",
    "Loaded",
    "McapWriter",
    "PlayOptions",
    "Player",
    "PoseSeries",
    "Recorder",
    "Recording",
    "Topic",
    "bag_info",
    "detect_format",
    "format_bag_info",
    "load_buffer",
    "load_recording",
    "parse_topics",
    "pose_series",
    "qos_yaml",
    "ros1_typestore",
    "run_bag_info",
    "run_bag_play",
    "run_record",
    "run_tf_export",
    "sample_times",
    "write_poses",
]
