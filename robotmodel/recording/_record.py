"""Recording topics from the bus into MCAP, as ``ros2 bag record`` does (raw CDR, receive-time log stamps).

The usual topics have known types and are subscribed at once, latched ones
(/tf_static, /robot_description) with transient-local QoS so that data published before
the recorder started is recorded too. Any other topic is subscribed as soon as the bus's
graph names its type. With ``all_topics`` (``ros2 bag record -a``, ``rosbag record -a``)
every topic the graph shows, now or later, is recorded, hidden ones (a name part starting
with ``_``) excepted, as ros2 bag does without ``--include-hidden-topics``. Messages are
written undecoded; the log time is the receive time and the publish time the sender's
source timestamp, as rosbag2 records them.

On the ROS 1 wire the payloads are ROS 1 serialization; they are converted to CDR at the
byte level (rosbags' ``ros1_to_cdr``, no decoding) so that the file stays a rosbag2-shaped
MCAP every reader of recordings takes (rosbags' rosbag2 reader, ``tf2_echo --bag``, the
viewer, rosbag2 itself). What that drops is ROS 1's ``Header.seq``.
"""

from __future__ import annotations

import logging
import threading
import time
from collections.abc import Callable, Sequence
from typing import TYPE_CHECKING, Any

from robotmodel.errors import RobotModelError
from robotmodel.recording._mcap import McapWriter, qos_yaml

if TYPE_CHECKING:
    from robotmodel.bus import Node, RawMessage

__all__ = ["KNOWN_TOPICS", "Recorder"]

# topic: (type, depth, transient local)
KNOWN_TOPICS: dict[str, tuple[str, int, bool]] = {
    "/tf": ("tf2_msgs/msg/TFMessage", 100, False),
    "/tf_static": ("tf2_msgs/msg/TFMessage", 100, True),
    "/joint_states": ("sensor_msgs/msg/JointState", 100, False),
    "/robot_description": ("std_msgs/msg/String", 1, True),
}
_DISCOVERY_PERIOD_S = 0.25
_log = logging.getLogger("robotmodel.recording")


class Recorder:
    """Subscribes ``node`` to ``topics`` and writes what arrives to ``writer`` until :meth:`close`.

    ``on_subscribed(topic, msgtype)`` is called as each topic is subscribed (for logging).
    ``all_topics``: also every topic the graph shows, as it appears (hidden ones excepted).
    """

    def __init__(self, node: Node, writer: McapWriter, topics: Sequence[str],
                 on_subscribed: Callable[[str, str], None] | None = None, *, all_topics: bool = False) -> None:
        self.node = node
        self.writer = writer
        self._on_subscribed = on_subscribed
        self._all = all_topics
        # All topics: the known ones at once too, so that latched data is asked for as latched.
        wanted = [*topics, *(KNOWN_TOPICS if all_topics else ())]
        self._pending = [node.resolve_topic_name(t) for t in dict.fromkeys(wanted)]
        self._subscribed: dict[str, str] = {}
        self._refused: set[str] = set()
        self._stop = threading.Event()
        for topic in list(self._pending):
            known = KNOWN_TOPICS.get(topic)
            if known is not None:
                self._subscribe(topic, *known)
        self._thread: threading.Thread | None = None
        if self._pending or all_topics:
            self._thread = threading.Thread(target=self._discover, name="record-discovery", daemon=True)
            self._thread.start()

    @property
    def subscribed(self) -> dict[str, str]:
        """Topics subscribed so far and their types."""
        return dict(self._subscribed)

    def _subscribe(self, topic: str, msgtype: str, depth: int, latched: bool) -> None:
        from robotmodel.bus import Durability, QoS

        self.writer.add_topic(topic, msgtype, qos_yaml(depth, True, latched))
        qos = QoS(depth, durability=Durability.TRANSIENT_LOCAL if latched else Durability.VOLATILE)
        self.node.create_subscription(msgtype, topic, self._on_message, qos, raw=True)
        self._subscribed[topic] = msgtype
        self._pending.remove(topic)
        if self._on_subscribed is not None:
            self._on_subscribed(topic, msgtype)

    def _on_message(self, msg: RawMessage) -> None:
        if self._stop.is_set():
            return
        now = time.time_ns()
        payload = msg.payload
        if msg.encoding != "cdr":
            payload = self._to_cdr(msg)
            if not payload:
                return
        self.writer.write(msg.topic, now, payload, msg.info.source_timestamp_ns)

    def _to_cdr(self, msg: RawMessage) -> bytes:
        from rosbags.serde import SerdeError

        from robotmodel.msgs import typestore

        msgtype = self._subscribed.get(msg.topic, msg.typename)
        try:
            return bytes(typestore().ros1_to_cdr(msg.payload, msgtype))
        except (SerdeError, UnicodeDecodeError, IndexError, ValueError, KeyError) as exc:
            _log.warning("not recording a message on %s that is not a ROS 1 %s: %s", msg.topic, msgtype, exc)
            return b""

    def _discover(self) -> None:
        while (self._pending or self._all) and not self._stop.wait(_DISCOVERY_PERIOD_S):
            types = dict(self.node.get_topic_names_and_types())
            if self._all:
                self._pending.extend(t for t in types if t not in self._subscribed and t not in self._pending
                                     and t not in self._refused and not _hidden(t))
            for topic in list(self._pending):
                found: list[Any] = types.get(topic, [])
                if not found:
                    continue
                try:
                    self._subscribe(topic, str(found[0]), 100, False)
                except RobotModelError as exc:  # a type rosbags does not know: say so, record the rest
                    _log.warning("not recording %s: %s", topic, exc)
                    self._pending.remove(topic)
                    self._refused.add(topic)

    def close(self) -> None:
        """Stop recording (the writer stays open for its owner to close)."""
        self._stop.set()
        if self._thread is not None:
            self._thread.join(2.0)


def _hidden(topic: str) -> bool:
    """A hidden topic (rcl's rule: a name part starting with ``_``)."""
    return any(part.startswith("_") for part in topic.split("/"))
