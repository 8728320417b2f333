"""ros2cli's ``ros2 topic`` on the bus: which topics there are, and their messages as YAML.

- :func:`run_topic_list`: ``ros2 topic list`` (``-t`` types, ``-c`` count, hidden topics),
  after ros2cli's discovery spin.
- :func:`run_topic_echo`: ``ros2 topic echo`` (type from the graph, QoS following the
  publishers', ``--field``, ``--once``, ``--raw``, truncation).
- :func:`message_to_yaml`: a message as ros2's ``message_to_yaml`` writes it.
"""

from __future__ import annotations

from robotmodel.topic._tools import (
    DEFAULT_SPIN_TIME,
    DEFAULT_TRUNCATE_LENGTH,
    message_to_yaml,
    run_topic_echo,
    run_topic_list,
)

__all__ = ["DEFAULT_SPIN_TIME", "DEFAULT_TRUNCATE_LENGTH", "message_to_yaml", "run_topic_echo", "run_topic_list"]
