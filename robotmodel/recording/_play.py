"""Playing a recording onto the bus, as ``ros2 bag play`` (and ``rosbag play``) do.

Each topic is published with its recorded type and QoS: the recorded durability and
reliability (rosbag2's ``offered_qos_profiles``, a ROS 1 connection's ``latching``), and
/tf_static and /robot_description transient local whatever was recorded, so a late joiner
gets them as from the original publishers. Messages go out at their log times' pace
scaled by ``rate``; with ``clock_hz`` the player also publishes rosgraph_msgs/Clock on
/clock at that rate, the clock being the recording's log time now playing (what nodes
with ``use_sim_time`` read as their time). Payloads are sent undecoded, converted at the
byte level between ROS 1 serialization and CDR when the recording and the wire differ.
"""

from __future__ import annotations

import logging
import struct
import threading
import time
from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from robotmodel.errors import RecordingError

if TYPE_CHECKING:
    from robotmodel.bus import Node, Publisher, QoS
    from robotmodel.recording._open import Recording

__all__ = ["DEFAULT_CLOCK_HZ", "LATCHED_TOPICS", "PlayOptions", "Player", "parse_topics", "run_bag_play"]

#: ``ros2 bag play --clock`` without a value: rosbag2's 40 Hz.
DEFAULT_CLOCK_HZ = 40.0
#: Topics always played transient local (depth), as their publishers in ROS latch them.
LATCHED_TOPICS: dict[str, int] = {"/tf_static": 100, "/robot_description": 1}
_NODE = "rosbag2_player"
_VOLATILE_DEPTH = 1000  # rosbag2's player default queue
_log = logging.getLogger("robotmodel.recording")


@dataclass(frozen=True, slots=True)
class PlayOptions:
    """How to play a recording; invalid values raise :class:`RecordingError`.

    ``rate`` (1.0 is real time), ``loop``, ``start_offset_ns`` into the recording,
    ``topics`` (empty: all, by their recorded names), ``clock_hz`` (None: no /clock),
    ``delay_ns`` slept before each pass (rosbag2's ``--delay``), ``remaps``: ROS 2 remap rules
    (``/tf:=/replayed/tf``) for the player node, as rosbag2 hands ``--remap`` to it, so they
    rename what is published (/clock included).
    """

    rate: float = 1.0
    loop: bool = False
    start_offset_ns: int = 0
    topics: tuple[str, ...] = ()
    clock_hz: float | None = None
    delay_ns: int = 0
    remaps: tuple[str, ...] = ()

    def __post_init__(self) -> None:
        if not 0 < self.rate < float("inf"):
            raise RecordingError(f"rate must be a positive number, got {self.rate}")
        if self.start_offset_ns < 0:
            raise RecordingError(f"start offset must be >= 0, got {self.start_offset_ns / 1e9} s")
        if self.clock_hz is not None and not 0 < self.clock_hz < float("inf"):
            raise RecordingError(f"clock rate must be a positive number of Hz, got {self.clock_hz}")
        if self.delay_ns < 0:
            raise RecordingError(f"delay must be >= 0, got {self.delay_ns / 1e9} s")
        from robotmodel.bus._remap import rule_problem

        for rule in self.remaps:
            problem = rule_problem(rule)
            if problem:
                raise RecordingError(f"--remap {rule!r}: {problem}")


class Player:
    """Publishes ``recording``'s messages on ``node`` as :class:`PlayOptions` say; :meth:`play` runs it.

    Unknown ``options.topics`` are refused here, before anything is published.
    """

    def __init__(self, recording: Recording, node: Node, options: PlayOptions) -> None:
        self.recording = recording
        self.node = node
        self.options = options
        present = {t.name for t in recording.topics()}
        missing = [t for t in options.topics if t not in present]
        if missing:
            raise RecordingError(f"{recording.path}: no topic {', '.join(missing)} in the recording "
                                 f"(it has {', '.join(sorted(present)) or 'none'})")
        self.topics = list(options.topics) or sorted(present)
        self.published = 0
        self._convert = self._converter()
        self._pubs: dict[str, Publisher[Any]] = {}
        for topic in self.topics:
            msgtype = recording.msgtype(topic) or ""
            self._pubs[topic] = node.create_publisher(msgtype, topic, self._qos(topic))
        self._clock: Publisher[Any] | None = None
        if options.clock_hz is not None:
            from robotmodel.msgs.rosgraph_msgs import Clock

            self._clock = node.create_publisher(Clock, "/clock", 10)

    def _qos(self, topic: str) -> QoS:
        from robotmodel.bus import Durability, QoS, Reliability

        latched_depth = LATCHED_TOPICS.get(topic)
        reliable, latched, depth = True, latched_depth is not None, latched_depth or _VOLATILE_DEPTH
        for conn in self.recording.connections(topic):
            ext = conn.ext
            if getattr(ext, "latching", None):
                latched = True
                depth = latched_depth or 1
            for profile in getattr(ext, "offered_qos_profiles", None) or ():
                # rosbags gives its own enums (not ints) for the profiles a robotmodel/rosbag2 MCAP carries
                if int(getattr(profile.durability, "value", profile.durability)) == int(Durability.TRANSIENT_LOCAL):
                    latched = True
                    depth = latched_depth or max(int(profile.depth), 1)
                if int(getattr(profile.reliability, "value", profile.reliability)) == int(Reliability.BEST_EFFORT):
                    reliable = False
        return QoS(depth, reliability=Reliability.RELIABLE if reliable else Reliability.BEST_EFFORT,
                   durability=Durability.TRANSIENT_LOCAL if latched else Durability.VOLATILE)

    def _converter(self) -> Callable[[str, bytes], bytes] | None:
        """Byte-level ROS 1 <-> CDR conversion when the recording's serialization is not the wire's."""
        from robotmodel.msgs import typestore

        wire = self.node.context.encoding
        store = typestore()
        if self.recording.ros1 and wire == "cdr":
            return lambda msgtype, data: bytes(store.ros1_to_cdr(data, msgtype))
        if not self.recording.ros1 and wire == "ros1":
            return lambda msgtype, data: bytes(store.cdr_to_ros1(data, msgtype))
        return None

    def play(self, stop: threading.Event) -> None:
        """Play until the end (every pass with ``loop``, each after ``delay_ns``) or ``stop``."""
        first = self.recording.start_ns + self.options.start_offset_ns
        while not stop.is_set():
            if self.options.delay_ns:
                from robotmodel.rcl import ros_log

                ros_log("INFO", _NODE, f"Sleep {self.options.delay_ns} ns")
                if stop.wait(self.options.delay_ns / 1e9):
                    return
            self._pass(first, stop)
            if not self.options.loop:
                return

    def _pass(self, first: int, stop: threading.Event) -> None:
        rate, period = self.options.rate, None
        if self.options.clock_hz is not None:
            period = 1.0 / self.options.clock_hz
        start = time.monotonic()
        next_tick = start

        def bag_now() -> int:
            return first + int((time.monotonic() - start) * rate * 1e9)

        def wait_until(wall: float, due_ns: int) -> bool:
            """Sleep to ``wall``, publishing /clock on its ticks; False when stopped.

            A tick never runs the clock past ``due_ns``, the recorded time of the message about
            to be played: a player held up (a loaded machine) would otherwise send sim-time nodes
            a time whose messages they have not had yet, even past the recording's end.
            """
            nonlocal next_tick
            while not stop.is_set():
                now = time.monotonic()
                if period is not None and next_tick <= now:
                    self._publish_clock(min(bag_now(), due_ns))
                    next_tick = max(next_tick + period, now)
                    continue
                if now >= wall:
                    return True
                stop.wait(min(wall, next_tick) - now if period is not None else wall - now)
            return False

        for topic, t, data in self._messages(first):
            if not wait_until(start + (t - first) / 1e9 / rate, t):
                return
            self._publish(topic, data)

    def _messages(self, first: int) -> Iterator[tuple[str, int, bytes]]:
        for topic, t, data in self.recording.messages(self.topics):
            if t >= first:
                yield topic, t, data

    def _publish(self, topic: str, data: bytes) -> None:
        if self._convert is not None:
            from rosbags.serde import SerdeError

            msgtype = self.recording.msgtype(topic) or ""
            try:
                data = self._convert(msgtype, data)
            except (SerdeError, UnicodeDecodeError, IndexError, ValueError, KeyError, struct.error) as exc:
                _log.warning("not playing a message on %s that does not convert as %s: %s", topic, msgtype, exc)
                return
        self._pubs[topic].publish_raw(data)
        self.published += 1

    def _publish_clock(self, ns: int) -> None:
        from robotmodel.msgs.builtin_interfaces import Time
        from robotmodel.msgs.rosgraph_msgs import Clock

        assert self._clock is not None
        self._clock.publish(Clock(clock=Time(sec=ns // 1_000_000_000, nanosec=ns % 1_000_000_000)))


def parse_topics(words: Sequence[str]) -> tuple[str, ...]:
    """Topic names as given (``--topics a b``), made absolute as rosbag2 matches them."""
    return tuple(w if w.startswith("/") else "/" + w for w in words)


def run_bag_play(bag: str, options: PlayOptions, *, connect: Sequence[str] = ()) -> int:
    """``ros2 bag play``: publish the recording ``bag`` on the bus; the exit code.

    Runs to the recording's end (forever with ``loop``) or SIGINT/SIGTERM. Bad files and
    unknown topics raise :class:`RecordingError` before anything is published.
    """
    from robotmodel.bus import Node
    from robotmodel.rcl import ros_log
    from robotmodel.recording._open import Recording
    from robotmodel.signals import stop_on_signals

    stop = stop_on_signals()
    with Recording(bag) as rec, Node(_NODE, connect=list(connect), remappings=options.remaps) as node:
        player = Player(rec, node, options)
        ros_log("INFO", _NODE, f"Playing '{bag}': {len(player.topics)} topic(s) at rate {options.rate:g}"
                + (f", /clock at {options.clock_hz:g} Hz" if options.clock_hz is not None else ""))
        player.play(stop)
    ros_log("INFO", _NODE, f"Playback finished: {player.published} message(s)")
    return 0
