"""What a node makes: publishers, subscriptions, timers, rates, services and clients, rclpy-shaped.

Everything that calls back queues its work as it arrives from the bus and runs it only when
an executor takes it (:mod:`robotmodel.rclpy.executors`): a subscription keeps the messages
its QoS history allows (keep last N drops the oldest), a service its requests, a client
its responses, a timer is due when its clock says so. Each waitable offers the executor
``ready()``, ``take()`` (the next job, or None) and, for timers, ``due_in()``.
"""

from __future__ import annotations

import threading
from collections import deque
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from robotmodel.bus import History
from robotmodel.rclpy.duration import Duration
from robotmodel.rclpy.task import Future

if TYPE_CHECKING:
    from robotmodel.bus import Publisher as BusPublisher
    from robotmodel.rclpy.callback_groups import CallbackGroup
    from robotmodel.rclpy.clock import Clock
    from robotmodel.rclpy.node import Node

__all__ = ["Client", "Publisher", "Rate", "Service", "Subscription", "Timer"]

Job = Callable[[], None]


class Publisher:
    """rclpy's Publisher: ``publish(msg)``, ``topic_name``, ``get_subscription_count()``."""

    def __init__(self, node: Node, inner: BusPublisher[Any], msg_type: Any, qos_profile: Any) -> None:
        self._node = node
        self._inner = inner
        self.msg_type = msg_type
        self.qos_profile = qos_profile

    @property
    def topic_name(self) -> str:
        """The fully qualified (remapped) topic."""
        return self._inner.topic_name

    @property
    def topic(self) -> str:
        """Same as :attr:`topic_name`."""
        return self._inner.topic_name

    def publish(self, msg: Any) -> None:
        """Send one message."""
        self._inner.publish(msg)

    def get_subscription_count(self) -> int:
        """Subscriptions the graph shows on the topic."""
        return self._inner.get_subscription_count()

    def destroy(self) -> None:
        """Withdraw it (rclpy's Node.destroy_publisher)."""
        self._inner.close()


class _Waitable:
    """Common to what an executor waits on: a callback group and a node to wake."""

    def __init__(self, node: Node, callback_group: CallbackGroup | None) -> None:
        self._node = node
        self.callback_group = callback_group if callback_group is not None else node.default_callback_group
        self._destroyed = False

    def ready(self) -> bool:
        """Whether :meth:`take` has work."""
        raise NotImplementedError

    def take(self) -> Job | None:
        """The next job, or None."""
        raise NotImplementedError

    def due_in(self) -> float | None:
        """Seconds until due (timers only)."""
        return None


class Subscription(_Waitable):
    """rclpy's Subscription: messages queue on arrival, the executor calls ``callback(msg)``."""

    def __init__(self, node: Node, msg_type: Any, topic: str, callback: Callable[[Any], None], qos: Any,
                 callback_group: CallbackGroup | None, raw: bool = False) -> None:
        super().__init__(node, callback_group)
        self.msg_type = msg_type
        self.callback = callback
        self._queue: deque[Any] = deque(maxlen=None if qos.history == History.KEEP_ALL else max(qos.depth, 1))
        self._raw = raw
        self._inner = node.bus_node.create_subscription(msg_type, topic, self._arrived, qos, raw=raw)
        self.topic_name = self._inner.topic_name

    def _arrived(self, msg: Any) -> None:
        if self._raw:
            msg = msg.payload
        self._queue.append(msg)
        self._node._notify()

    def ready(self) -> bool:
        """Whether a message waits."""
        return bool(self._queue)

    def take(self) -> Job | None:
        """The callback of the oldest waiting message."""
        try:
            msg = self._queue.popleft()
        except IndexError:
            return None
        return lambda: self.callback(msg)

    @property
    def topic(self) -> str:
        """The fully qualified topic."""
        return self.topic_name

    def destroy(self) -> None:
        """Withdraw it."""
        self._destroyed = True
        self._inner.close()
        self._node._forget(self)


class Timer(_Waitable):
    """rclpy's Timer: ``callback()`` every period of its clock, while an executor spins."""

    def __init__(self, node: Node, period_sec: float, callback: Callable[..., Any] | None, clock: Clock,
                 callback_group: CallbackGroup | None, autostart: bool = True) -> None:
        super().__init__(node, callback_group)
        self.timer_period_ns = int(period_sec * 1_000_000_000)
        self.callback = callback
        self._clock = clock
        self._lock = threading.Lock()
        self._canceled = not autostart
        self._last_ns = clock.now().nanoseconds
        self._next_ns = self._last_ns + self.timer_period_ns

    @property
    def clock(self) -> Clock:
        """The clock it follows."""
        return self._clock

    @property
    def timer_period_sec(self) -> float:
        """The period in seconds."""
        return self.timer_period_ns / 1e9

    def ready(self) -> bool:
        """Whether it is due."""
        return self.is_ready()

    def is_ready(self) -> bool:
        """Whether it is due (and not canceled)."""
        with self._lock:
            return not self._canceled and self._clock.now().nanoseconds >= self._next_ns

    def due_in(self) -> float | None:
        """Seconds until due (None when canceled)."""
        with self._lock:
            if self._canceled:
                return None
            return max(0.0, (self._next_ns - self._clock.now().nanoseconds) / 1e9)

    def time_until_next_call(self) -> int | None:
        """Nanoseconds until due (None when canceled)."""
        left = self.due_in()
        return None if left is None else int(left * 1e9)

    def time_since_last_call(self) -> int:
        """Nanoseconds since it last fired (or was made or reset)."""
        return self._clock.now().nanoseconds - self._last_ns

    def take(self) -> Job | None:
        """Fire: the next call is one period on, skipping periods missed (as rcl)."""
        now = self._clock.now().nanoseconds
        with self._lock:
            if self._canceled or now < self._next_ns:
                return None
            self._last_ns = now
            self._next_ns += self.timer_period_ns
            if self._next_ns <= now and self.timer_period_ns > 0:
                self._next_ns = now + self.timer_period_ns - (now - self._next_ns) % self.timer_period_ns
        callback = self.callback
        return (lambda: None) if callback is None else callback

    def cancel(self) -> None:
        """Stop firing until :meth:`reset`."""
        with self._lock:
            self._canceled = True

    def is_canceled(self) -> bool:
        """Whether it is canceled."""
        return self._canceled

    def reset(self) -> None:
        """Start the period afresh from now (and uncancel)."""
        with self._lock:
            self._canceled = False
            self._last_ns = self._clock.now().nanoseconds
            self._next_ns = self._last_ns + self.timer_period_ns
        self._node._notify()

    def destroy(self) -> None:
        """Withdraw it."""
        self.cancel()
        self._destroyed = True
        self._node._forget(self)


class Rate:
    """rclpy's Rate: ``sleep()`` until the next period; needs another thread spinning, as rclpy's."""

    def __init__(self, node: Node, frequency: float, clock: Clock) -> None:
        if frequency <= 0:
            raise ValueError("frequency must be > 0")
        self._clock = clock
        self._node = node
        self._period = Duration(nanoseconds=int(1e9 / frequency))
        self._next = clock.now() + self._period

    def sleep(self) -> None:
        """Sleep until the next period of the clock (returns early at shutdown)."""
        self._clock.sleep_until(self._next, self._node.context)
        now = self._clock.now()
        self._next = self._next + self._period
        if self._next < now:
            self._next = now + self._period

    def destroy(self) -> None:
        """Nothing to withdraw (rclpy's signature)."""


class Service(_Waitable):
    """rclpy's Service: requests queue, the executor calls ``callback(request, response)``."""

    def __init__(self, node: Node, srv_type: Any, srv_name: str, callback: Callable[[Any, Any], Any],
                 callback_group: CallbackGroup | None) -> None:
        super().__init__(node, callback_group)
        self.srv_type = srv_type
        self.callback = callback
        self._queue: deque[tuple[Any, Callable[[Any], None]]] = deque()
        self._inner = node.bus_node.create_service(srv_type.__srvtype__, srv_name, self._arrived,
                                                   request_type=srv_type.Request, response_type=srv_type.Response)
        self.srv_name = self._inner.service_name

    def _arrived(self, request: Any, respond: Callable[[Any], None], _rid: Any) -> None:
        self._queue.append((request, respond))
        self._node._notify()

    def ready(self) -> bool:
        """Whether a request waits."""
        return bool(self._queue)

    def take(self) -> Job | None:
        """The callback of the oldest request, its return value the response."""
        try:
            request, respond = self._queue.popleft()
        except IndexError:
            return None

        def job() -> None:
            response = self.callback(request, self.srv_type.Response())
            respond(response)

        return job

    def destroy(self) -> None:
        """Withdraw it."""
        self._destroyed = True
        self._inner.close()
        self._node._forget(self)


class Client(_Waitable):
    """rclpy's Client: ``call_async(request)`` gives a Future completed by the executor."""

    def __init__(self, node: Node, srv_type: Any, srv_name: str, callback_group: CallbackGroup | None) -> None:
        super().__init__(node, callback_group)
        self.srv_type = srv_type
        self._queue: deque[tuple[Future, Any]] = deque()
        self._inner = node.bus_node.create_client(srv_type.__srvtype__, srv_name, request_type=srv_type.Request,
                                                  response_type=srv_type.Response)
        self.srv_name = self._inner.service_name

    def call_async(self, request: Any) -> Future:
        """Send ``request``; the Future gets the response once an executor handles it."""
        future = Future()

        def arrived(response: Any) -> None:
            self._queue.append((future, response))
            self._node._notify()

        self._inner.call_async(request, arrived)
        return future

    def call(self, request: Any, timeout_sec: float | None = None) -> Any:
        """Send and wait (another thread must spin the node, as in rclpy); None at the timeout."""
        future = self.call_async(request)
        if not future.wait(timeout_sec):
            return None
        return future.result()

    def ready(self) -> bool:
        """Whether a response waits."""
        return bool(self._queue)

    def take(self) -> Job | None:
        """Complete the oldest waiting response's future."""
        try:
            future, response = self._queue.popleft()
        except IndexError:
            return None
        return lambda: future.set_result(response)

    def service_is_ready(self) -> bool:
        """Whether a server is known."""
        return self._inner.service_is_ready()

    def wait_for_service(self, timeout_sec: float | None = None) -> bool:
        """Wait for a server; False at the timeout (or at shutdown)."""
        return self._inner.wait_for_service(timeout_sec)

    def destroy(self) -> None:
        """Withdraw it."""
        self._destroyed = True
        self._inner.close()
        self._node._forget(self)
