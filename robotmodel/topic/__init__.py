"""ros2cli's ``ros2 topic`` on the bus: which topics there are, and their messages as YAML.

- :func:`run_topic_list`: ``ros2 topic list`` (``-t`` types, ``-c`` count, hidden topics),
  after ros2cli's discovery spin.
- :func:`run_topic_echo`: ``ros2 topic echo`` (type from the graph, QoS following the
  publishers' or ``--qos-*``, ``--field``, ``--filter``, ``--once``, ``--raw``, ``--csv``,
  ``-i``; :class:`EchoFormat` how it prints, truncation and ``--no-arr``/``--no-str``).
- :func:`run_topic_hz`, :func:`run_topic_bw`: ``ros2 topic hz`` / ``bw`` (:class:`HzMeter` and
  :func:`rate_stats` the arithmetic; ``--filter`` and ``--wall-time`` as ros2's).
- :func:`run_topic_info`, :func:`run_topic_type`: ``ros2 topic info [-v]`` / ``type``.
- :func:`run_topic_pub`: ``ros2 topic pub`` (:func:`message_from_yaml` its YAML form,
  :func:`qos_from_short_keys` its ``--qos-*`` options).
- :func:`message_to_yaml`, :func:`message_to_csv`: a message as rosidl_runtime_py writes it.
"""

from __future__ import annotations

from robotmodel.topic._convert import message_to_csv, message_to_yaml
from robotmodel.topic._echo import DEFAULT_TRUNCATE_LENGTH, EchoFormat, run_topic_echo
from robotmodel.topic._hz import HzMeter, run_topic_hz
from robotmodel.topic._info import run_topic_info, run_topic_type
from robotmodel.topic._pub import message_from_yaml, run_topic_pub
from robotmodel.topic._qos import qos_from_short_keys
from robotmodel.topic._rate import RateStats, rate_stats, run_topic_bw
from robotmodel.topic._tools import DEFAULT_SPIN_TIME, run_topic_list

__all__ = ["DEFAULT_SPIN_TIME", "DEFAULT_TRUNCATE_LENGTH", "EchoFormat", "HzMeter", "RateStats", "message_from_yaml",
           "message_to_csv", "message_to_yaml", "qos_from_short_keys", "rate_stats", "run_topic_bw", "run_topic_echo",
           "run_topic_hz", "run_topic_info", "run_topic_list", "run_topic_pub", "run_topic_type"]
