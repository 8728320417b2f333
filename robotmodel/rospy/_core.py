"""rospy's node life: init_node, the one node of the process, shutdown, spin, sleep, Rate.

As rospy: one node per process; SIGINT and SIGTERM start shutdown (then the handler that
was there before runs, its KeyboardInterrupt swallowed), so ``while not rospy.is_shutdown()``
loops end and :func:`spin` returns; ``on_shutdown`` hooks run once, with the reason.

Time: with ``/use_sim_time`` true at init_node the node follows ``/clock``, and
:func:`sleep` / :meth:`Rate.sleep` wait for simulated time as rospy's do (ROSInterruptException
at shutdown, ROSTimeMovedBackwardsException when ``/clock`` goes back). On the wall clock they
return early at shutdown instead of sleeping on (rospy's sleeps the full time) and raise nothing, as
rospy's wall-clock sleep.
"""

from __future__ import annotations

import atexit
import contextlib
import os
import signal
import sys
import threading
import time
from collections.abc import Callable, Sequence
from typing import TYPE_CHECKING, Any

from robotmodel.errors import ROSException, ROSInitException, ROSInterruptException, ROSTimeMovedBackwardsException
from robotmodel.rospy import _log, _time
from robotmodel.rospy._time import Duration, Time, get_rostime

if TYPE_CHECKING:
    from robotmodel.bus import Node

__all__ = ["Rate", "get_name", "get_namespace", "get_node", "init_node", "is_shutdown", "myargv",
           "on_shutdown", "resolve_name", "signal_shutdown", "sleep", "spin"]


class _State:
    """The process's node and its shutdown (rospy keeps these module-global too)."""

    def __init__(self) -> None:
        self.node: Node | None = None
        self.init_args: tuple[Any, ...] = ()
        self.name = "/unnamed"
        self.namespace = "/"
        self.shutdown = threading.Event()
        self.reason = ""
        self.hooks: list[Callable[..., Any]] = []
        self.subscriptions: list[Any] = []  # closed first at shutdown (see signal_shutdown)
        self.lock = threading.Lock()


_state = _State()


def get_node() -> Node | None:
    """The bus node init_node opened (None before): what tf2_ros's rospy-style classes use."""
    return _state.node


def get_name() -> str:
    """The node's fully qualified name (``/unnamed`` before init_node)."""
    return _state.name


def get_namespace() -> str:
    """The node's namespace, ending in ``/`` as rospy's."""
    return _state.namespace.rstrip("/") + "/"


def resolve_name(name: str, caller_id: str | None = None) -> str:
    """A name made global as rospy does: ``~x`` under the node, ``x`` under its namespace, ``/x`` kept."""
    node = caller_id or _state.name
    if name.startswith("/"):
        full = name
    elif name.startswith("~"):
        full = node.rstrip("/") + "/" + name[1:].lstrip("/")
    else:
        full = get_namespace() + name
    return "/" + "/".join(p for p in full.split("/") if p) if full != "/" else "/"


def myargv(argv: Sequence[str] | None = None) -> list[str]:
    """The words without ROS's remapping words (``x:=y``), as rospy.myargv."""
    return [w for w in (sys.argv if argv is None else argv) if ":=" not in w]


def _yaml_value(text: str) -> Any:
    import yaml

    try:
        return yaml.safe_load(text)
    except yaml.YAMLError:
        return text


def init_node(name: str, argv: Sequence[str] | None = None, anonymous: bool = False, log_level: int | None = None,
              disable_rostime: bool = False, disable_rosout: bool = False, disable_signals: bool = False,
              xmlrpc_port: int = 0, tcpros_port: int = 0, **bus_options: Any) -> None:
    """Start the process's node on the bus (``default_wire()``: ROS 1 with ROS_MASTER_URI and ROS_VERSION=1).

    ``argv`` (default ``sys.argv``) is read for ``__name:=``, ``__ns:=``, ``_param:=value``
    (a private parameter, its value read as YAML) and ``from:=to`` topic remaps;
    ``ROS_NAMESPACE`` sets the namespace. ``/use_sim_time`` true (on wires without a parameter
    server: ``_use_sim_time:=true``) makes the node follow ``/clock``; log lines go to
    ``/rosout`` unless ``disable_rosout``. ``bus_options`` (robotmodel's, e.g. ``backend``,
    ``domain_id``) go to :class:`robotmodel.bus.Node`. Called again with the same arguments
    (``bus_options`` aside) it does nothing, with others it raises ROSException, as rospy.
    """
    del xmlrpc_port, tcpros_port
    from robotmodel.bus import Node

    args = (name, argv, anonymous, log_level, disable_rostime, disable_signals)
    if _state.node is not None:
        # As rospy: the same call again is a no-op (so a harness may open the node first, on a
        # wire of its choosing, and then run a program that calls init_node as usual).
        if args == _state.init_args:
            return
        raise ROSException(f"rospy.init_node() has already been called with different arguments: {_state.init_args}")
    if "/" in name:
        raise ValueError("namespaces are not allowed in node names")
    words = list(sys.argv if argv is None else argv)
    namespace = os.environ.get("ROS_NAMESPACE", "/") or "/"
    remaps: list[str] = []
    params: dict[str, Any] = {}
    renamed: str | None = None
    for word in words:
        if ":=" not in word:
            continue
        lhs, rhs = word.split(":=", 1)
        if lhs in ("__name", "__node"):
            renamed = rhs
        elif lhs == "__ns":
            namespace = rhs
        elif lhs.startswith("__"):
            continue  # __master, __ip, __hostname, __log: the environment decides these here
        elif lhs.startswith("_"):
            params[lhs[1:]] = _yaml_value(rhs)
        else:
            remaps.append(word)
    if renamed is not None:
        name = renamed
    elif anonymous:
        name = f"{name}_{os.getpid()}_{int(time.time() * 1000)}"
    namespace = "/" + namespace.strip("/")
    node = Node(name, namespace, remappings=remaps, **bus_options)
    with _state.lock:
        _state.node = node
        _state.init_args = args
        _state.name = node.fully_qualified_name
        _state.namespace = node.namespace
    store = node.parameters
    for key, value in params.items():
        store.set(resolve_name("~" + key), value)
    if log_level is not None:
        _log.set_level(log_level)
    if not disable_rostime and _wants_sim_time(store):
        _follow_clock(node)
    if not disable_rosout:
        from robotmodel.rospy._rosout import rosout_sink

        _log.set_sink(rosout_sink(node), _state.name)
    # Handlers can only be installed from the main thread; rospy skips them elsewhere too.
    if not disable_signals and threading.current_thread() is threading.main_thread():
        for sig in (signal.SIGINT, signal.SIGTERM):
            _chain[sig] = signal.signal(sig, _on_signal)
    requested = getattr(node.handle, "shutdown_requested", None)
    if callable(requested):
        # ROS 1's master or rosnode may ask the node to end (shutdown over XML-RPC).
        event = requested()
        threading.Thread(target=_follow, args=(event,), name="rospy-shutdown", daemon=True).start()


def _wants_sim_time(store: Any) -> bool:
    from robotmodel.bus import LocalParameters

    keys = ["/use_sim_time"]
    if isinstance(store, LocalParameters):  # no parameter server: the node's own, as ROS 2's
        keys.append(resolve_name("~use_sim_time"))
    for key in keys:
        try:
            if store.get(key) is True:
                return True
        except KeyError:
            continue
    return False


def _follow_clock(node: Node) -> None:
    from robotmodel.bus import QoS
    from robotmodel.msgs.rosgraph_msgs import Clock

    _time.use_sim_time()

    def tick(msg: Clock) -> None:
        _time.set_rostime(msg.clock.sec * 1_000_000_000 + msg.clock.nanosec)

    _state.subscriptions.append(node.create_subscription(Clock, "/clock", tick, QoS(1)))


def _follow(event: threading.Event) -> None:
    while not _state.shutdown.is_set():
        if event.wait(0.5):
            signal_shutdown("shutdown request")
            return


_chain: dict[int, Any] = {}


def _on_signal(sig: int, frame: Any) -> None:
    signal_shutdown(f"signal-{sig}")
    previous = _chain.get(sig)
    if callable(previous):
        # As rospy: shutdown is the answer to Ctrl-C, not a KeyboardInterrupt.
        with contextlib.suppress(KeyboardInterrupt):
            previous(sig, frame)


def is_shutdown() -> bool:
    """Whether shutdown has begun."""
    return _state.shutdown.is_set()


def on_shutdown(hook: Callable[..., Any]) -> None:
    """Run ``hook`` at shutdown (with the reason when it takes one argument); at once if already shut down."""
    with _state.lock:
        if not _state.shutdown.is_set():
            _state.hooks.append(hook)
            return
    _run(hook, _state.reason)


def _run(hook: Callable[..., Any], reason: str) -> None:
    import inspect

    try:
        takes = len(inspect.signature(hook).parameters)
    except (TypeError, ValueError):
        takes = 0
    try:
        hook(reason) if takes else hook()
    except Exception as exc:
        _log.logwarn("signal_shutdown hook error[%s]", exc)


def signal_shutdown(reason: str) -> None:
    """Begin shutdown: hooks run (once), the node's publishers and subscriptions close."""
    with _state.lock:
        if _state.shutdown.is_set():
            return
        _state.reason = reason
        _state.shutdown.set()
        hooks, _state.hooks = _state.hooks, []
        node = _state.node
    with _time.clock_cond:
        _time.clock_cond.notify_all()  # a sleep in simulated time ends now
    for hook in hooks:
        _run(hook, reason)
    _log.set_sink(None, _state.name)
    # Subscriptions before publishers: one fed by this node's own publisher (a simulator's
    # /clock) would otherwise see it vanish and try to reconnect, warning, while the node ends.
    for sub in _state.subscriptions:
        with contextlib.suppress(Exception):
            sub.close()
    if node is not None:
        node.close()


atexit.register(lambda: signal_shutdown("atexit"))


def spin() -> None:
    """Block until shutdown (Ctrl-C, SIGTERM, signal_shutdown, the master's request)."""
    if _state.node is None:
        raise ROSInitException("client code must call rospy.init_node() first")
    try:
        while not _state.shutdown.is_set():
            _state.shutdown.wait(0.2)
    except KeyboardInterrupt:
        signal_shutdown("keyboard interrupt")


def _seconds(duration: Any) -> float:
    if isinstance(duration, Duration):
        return duration.to_sec()
    if hasattr(duration, "nanoseconds"):
        return int(duration.nanoseconds) / 1e9
    return float(duration)


def sleep(duration: Any) -> None:
    """Sleep ``duration`` (seconds or a Duration) of ROS time; a negative one returns at once.

    On the wall clock shutdown ends it early, silently; in simulated time it raises
    ROSInterruptException at shutdown and ROSTimeMovedBackwardsException if ``/clock`` went back.
    """
    if _time.is_wallclock():
        seconds = _seconds(duration)
        if seconds > 0:
            _state.shutdown.wait(seconds)
        return
    sim_sleep(round(_seconds(duration) * 1e9))


def sim_sleep(nanoseconds: int, stop: threading.Event | None = None) -> None:
    """Wait ``nanoseconds`` of ``/clock`` time (ended early by ``stop``), as rospy's sleep in simulated time."""
    cond = _time.clock_cond

    def ended() -> bool:
        return _state.shutdown.is_set() or (stop is not None and stop.is_set())

    with cond:
        start = get_rostime()
        while start.is_zero() and not ended():  # no /clock yet
            cond.wait(0.3)
            start = get_rostime()
        end = start + Duration._of(nanoseconds)
        while start <= get_rostime() < end and not ended():
            cond.wait(0.5)
        now = get_rostime()
    if now < start:
        raise ROSTimeMovedBackwardsException((start - now).to_sec())
    if _state.shutdown.is_set():
        raise ROSInterruptException("ROS shutdown request")


class Rate:
    """Loop at ``hz``: ``r = Rate(10)`` then ``r.sleep()`` each time round, as rospy.Rate."""

    def __init__(self, hz: float, reset: bool = False) -> None:
        self.last_time = get_rostime()
        self.sleep_dur = Duration(int(1e9 / hz) // 1_000_000_000, int(1e9 / hz) % 1_000_000_000)
        self._reset = reset

    def remaining(self) -> Duration:
        """What is left of this cycle."""
        return self._remaining(get_rostime())

    def _remaining(self, now: Time) -> Duration:
        self.last_time = min(self.last_time, now)  # time moved backwards
        elapsed: Duration = now - self.last_time
        left: Duration = self.sleep_dur - elapsed
        return left

    def sleep(self) -> None:
        """Sleep what is left of this cycle, keeping the loop on its period.

        A Rate made with ``reset=True`` starts afresh when ``/clock`` goes back, instead of raising.
        """
        now = get_rostime()
        try:
            sleep(self._remaining(now))
        except ROSTimeMovedBackwardsException:
            if not self._reset:
                raise
            self.last_time = get_rostime()
            return
        self.last_time = self.last_time + self.sleep_dur
        # A loop that fell behind by more than two periods starts afresh instead of bursting.
        if now - self.last_time > self.sleep_dur * 2:
            self.last_time = now
