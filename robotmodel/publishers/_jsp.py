"""joint_state_publisher on the bus: JointState on ``joint_states`` at a rate, robot from a file or the topic."""

from __future__ import annotations

import logging
import threading
import time
from collections.abc import Callable, Mapping, Sequence
from types import TracebackType
from typing import Any

from robotmodel.errors import RobotModelError
from robotmodel.msgs import JointState, String
from robotmodel.publishers._errors import PublisherError
from robotmodel.publishers._jsp_joints import FreeJoint
from robotmodel.publishers._jsp_state import JointStateLogic
from robotmodel.publishers._source import RobotSource, resolve
from robotmodel.time import Clock, SystemClock

__all__ = ["JointStatePublisher"]

_LOG = logging.getLogger("joint_state_publisher")


class JointStatePublisher:
    """ROS 2's joint_state_publisher as an object.

    Publishes a JointState on ``joint_states`` every ``1/rate`` seconds for every movable
    joint (mimic joints computed), with joint_state_publisher's defaults, ``zeros``, and
    values merged from the ``source_list`` topics (latest value per joint wins). The robot
    is ``description`` (a :class:`RobotDescription`, URDF text or a file) or, without one, the
    next message on ``robot_description``; as joint_state_publisher does, it always
    listens there and takes each new description (values reset to their defaults), except
    on the ROS 1 wire, where ROS 1's reads the parameter only.

    :meth:`set` changes free joints' values (a viewer's sliders call it). ``bus`` is a
    :class:`robotmodel.bus.Node` left open on :meth:`close`; without one, a node named
    ``joint_state_publisher`` is opened with ``node_options`` and closed again.
    ``rate=0`` starts no timer: call :meth:`publish` by hand. A ``clock`` other than the
    system's stamps the messages and paces the timer (``/clock`` on ROS 1's sim time, as rospy.Rate).
    """

    def __init__(
        self,
        description: RobotSource | None = None,
        *,
        bus: Any | None = None,
        rate: float = 10.0,
        zeros: Mapping[str, float] | None = None,
        source_list: Sequence[str] = (),
        use_mimic_tags: bool = True,
        use_smallest_joint_limits: bool = True,
        publish_default_positions: bool = True,
        publish_default_velocities: bool = False,
        publish_default_efforts: bool = False,
        delta: float = 0.0,
        dependent_joints: Mapping[str, tuple[str, float, float]] | None = None,
        clock: Clock | None = None,
        logger: logging.Logger | None = None,
        **node_options: Any,
    ) -> None:
        if not rate >= 0:
            raise PublisherError(f"rate must be >= 0 Hz, got {rate}")
        self.log = logger or _LOG
        self.logic = JointStateLogic(
            zeros=zeros, use_mimic_tags=use_mimic_tags, use_smallest_joint_limits=use_smallest_joint_limits,
            publish_default_positions=publish_default_positions,
            publish_default_velocities=publish_default_velocities,
            publish_default_efforts=publish_default_efforts, delta=delta, dependent_joints=dependent_joints,
            logger=self.log)
        self.clock: Clock = clock or SystemClock()
        self.rate = rate
        self._lock = threading.Lock()
        self._stop = threading.Event()
        self._thread: threading.Thread | None = None
        self._description_cbs: list[Callable[[], None]] = []
        self._source_cbs: list[Callable[[], None]] = []
        self._subs: list[Any] = []
        self._pub: Any = None
        if description is not None:
            text = resolve(description)[1]
            self.logic.configure(text)
        else:
            self.log.info("Waiting for robot_description to be published on the robot_description topic...")
        self._owned = bus is None
        if bus is None:
            from robotmodel.bus import Node

            bus = Node("joint_state_publisher", **node_options)
        self.node: Any = bus
        try:
            self._open(source_list)
        except BaseException:
            self.close()
            raise

    def _open(self, source_list: Sequence[str]) -> None:
        from robotmodel.bus import QOS_LATCHED

        node = self.node
        # ROS 1's joint_state_publisher reads the robot_description parameter only, never a topic.
        if node.context.backend.name != "ros1":
            self._subs.append(node.create_subscription(String, "robot_description", self._on_description,
                                                       QOS_LATCHED))
        for topic in source_list:
            self._subs.append(node.create_subscription(JointState, topic, self._on_source, 10))
        self._pub = node.create_publisher(JointState, "joint_states", 10)
        if self.rate > 0:
            self._thread = threading.Thread(target=self._run, name="joint_state_publisher", daemon=True)
            self._thread.start()

    # -- inputs -----------------------------------------------------------------------------------
    def _on_description(self, msg: String) -> None:
        try:
            with self._lock:
                self.logic.configure(msg.data)
        except RobotModelError as exc:
            self.log.warning("%s", exc)
            return
        for cb in list(self._description_cbs):
            cb()

    def _on_source(self, msg: JointState) -> None:
        with self._lock:
            self.logic.merge(msg)
        for cb in list(self._source_cbs):
            cb()

    def set(self, values: Mapping[str, float] | None = None, /, **named: float) -> None:
        """Set free joints' positions by name; see :meth:`JointStateLogic.set`."""
        with self._lock:
            self.logic.set(values, **named)

    def positions(self) -> dict[str, float]:
        """The free joints' current positions."""
        with self._lock:
            return self.logic.positions()

    @property
    def free_joints(self) -> Mapping[str, FreeJoint]:
        """The joints :meth:`set` takes, with their limits and defaults (empty before a robot)."""
        with self._lock:
            return self.logic.free_joints

    def add_robot_description_callback(self, callback: Callable[[], None]) -> None:
        """Call ``callback()`` after each new description from the topic (a GUI rebuilds its sliders)."""
        self._description_cbs.append(callback)

    def add_source_callback(self, callback: Callable[[], None]) -> None:
        """Call ``callback()`` after each message from a source topic has been merged."""
        self._source_cbs.append(callback)

    # -- output -----------------------------------------------------------------------------------
    def publish(self) -> JointState | None:
        """Publish the current JointState now (what the timer does); returns it, or None if nothing to send."""
        with self._lock:
            msg = self.logic.message(self.clock.now().nanoseconds)
            if msg is not None and self._pub is not None:
                self._pub.publish(msg)
        return msg

    def _run(self) -> None:
        if not isinstance(self.clock, SystemClock):
            self._run_on_clock()
            return
        period = 1.0 / self.rate
        deadline = time.monotonic() + period
        while not self._stop.wait(max(0.0, deadline - time.monotonic())):
            try:
                self.publish()
            except RobotModelError:
                # The timer must outlive one bad tick (a closed session at shutdown, say).
                self.log.exception("publishing joint states failed")
            deadline += period
            now = time.monotonic()
            if deadline < now:  # fell behind (a stalled machine): skip, do not burst
                deadline = now + period

    def _run_on_clock(self) -> None:
        # Another clock (/clock on sim time) paces the timer too, as rospy.Rate does there.
        from robotmodel.time import Duration

        period, step = Duration(seconds=1.0 / self.rate), Duration(seconds=0.1)
        last = self.clock.now()
        due = last + period
        while not self._stop.is_set():
            if not self.clock.sleep_until(due, step):
                now = self.clock.now()
                if now < last:  # a jump back while waiting: as rcl's timer, next call a period from now
                    last, due = now, now + period
                continue
            try:
                self.publish()
            except RobotModelError:
                self.log.exception("publishing joint states failed")
            now = last = self.clock.now()
            due = due + period
            # the clock jumped ahead, or back (a looping bag): start again from now
            if due < now or due - now > period + period:
                due = now + period

    # -- life cycle -------------------------------------------------------------------------------
    def close(self) -> None:
        """Stop the timer, withdraw the publisher and subscriptions (and the node, if it is ours)."""
        self._stop.set()
        thread, self._thread = self._thread, None
        if thread is not None and thread is not threading.current_thread():
            thread.join()
        with self._lock:
            pub, self._pub = self._pub, None
            subs, self._subs = self._subs, []
        for handle in [*subs, pub]:
            if handle is not None:
                handle.close()
        if self._owned:
            self._owned = False
            self.node.close()

    def __enter__(self) -> JointStatePublisher:
        return self

    def __exit__(self, exc_type: type[BaseException] | None, exc: BaseException | None,
                 tb: TracebackType | None) -> None:
        self.close()
