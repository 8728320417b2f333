"""One zenoh session as the zenoh wire uses it: keyed puts with attachments, subscribers, liveliness tokens.

QoS is mapped onto zenoh as rmw_zenoh maps it:

- Reliable QoS -> reliable zenoh publisher; congestion control BLOCK when the QoS says so
  (:attr:`QoS.blocks`), DROP otherwise.
- Transient local (latched) -> zenoh-ext AdvancedPublisher with a cache of ``depth``
  samples and publisher detection (plus a 0.5 s sporadic heartbeat when reliable), and
  AdvancedSubscriber with history, late-publisher detection and subscriber detection
  (plus heartbeat recovery when reliable), exactly as rmw_zenoh sets them.
- Payloads carry no zenoh encoding, as rmw_zenoh's.
"""

from __future__ import annotations

import atexit
import json
import logging
import threading
import time
import weakref
from abc import abstractmethod
from collections.abc import Callable, Sequence
from typing import Any

import zenoh
import zenoh.ext as zx

from robotmodel._heap import sample_releasing
from robotmodel.bus._backend import Handle
from robotmodel.bus._config import (
    LOOPBACK_ANY_PORT,
    rendezvous_endpoint,
    session_config,
    user_session_config,
)
from robotmodel.bus._qos import QoS, Reliability
from robotmodel.bus._router import ensure_router
from robotmodel.errors import BusError

__all__ = ["RawCallback", "RawPublisher", "ZenohSession", "open_session"]

log = logging.getLogger("robotmodel.bus")
# rmw_zenoh's SAMPLE_MISS_DETECTION_HEARTBEAT_PERIOD (500 ms).
_HEARTBEAT_S = 0.5
# How long opening waits for its first link before going on without it.
_LINK_TIMEOUT_S = 2.0
# zenoh-python runs each Python callback on a thread of its own, named so.
_CALLBACK_THREAD = "(pyo3-closure)"
# How long close() waits for those threads to end once the session let their callbacks go.
_CALLBACK_JOIN_S = 5.0


def open_session(connect: Sequence[str] = ()) -> zenoh.Session:
    """Open a peer session: the user's config file, explicit endpoints, or the loopback rendezvous."""
    user = user_session_config(connect)
    try:
        if user is not None:
            return zenoh.open(user)
        if connect:
            return _linked(zenoh.open(session_config([LOOPBACK_ANY_PORT], connect)), connect)
        rendezvous = rendezvous_endpoint()
        config = session_config([LOOPBACK_ANY_PORT], [rendezvous])
        if _connects_to(config, rendezvous):
            # Meet at the router there; with nobody listening, start one with a life of its own,
            # as ros2cli starts its daemon (rmw_zenoh's nodes meet each other only through one).
            ensure_router()
        return _linked(zenoh.open(config), [rendezvous])
    except zenoh.ZError as exc:
        raise BusError(f"cannot open a zenoh session: {exc}") from exc


def _connects_to(config: zenoh.Config, endpoint: str) -> bool:
    """Whether ``config`` (after ZENOH_CONFIG_OVERRIDE) still meets at ``endpoint``."""
    endpoints = json.loads(config.get_json("connect/endpoints"))
    return isinstance(endpoints, list) and endpoint in endpoints


def _linked(session: zenoh.Session, endpoints: Sequence[str], timeout: float = _LINK_TIMEOUT_S) -> zenoh.Session:
    """Return once the session has a peer or a router (so the graph is visible), or at the timeout.

    Past the timeout the session keeps retrying in the background; nothing is lost.
    """
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        info = session.info
        if any(True for _ in info.peers_zid()) or any(True for _ in info.routers_zid()):
            return session
        time.sleep(0.001)
    log.warning("no zenoh peer or router answered at %s yet; still trying in the background", ", ".join(endpoints))
    return session


#: Called with (key, payload, attachment bytes or None) for each sample; plain arguments,
#: since building any object per sample costs on the receive path.
RawCallback = Callable[[str, bytes, "bytes | None"], None]
TokenCallback = Callable[[str, bool], None]


class RawPublisher(Handle):
    """A declared zenoh publisher: puts payloads with attachments on one key."""

    @abstractmethod
    def put(self, payload: bytes, attachment: bytes) -> None:
        """Send one sample."""

    @abstractmethod
    def matched(self) -> bool:
        """Whether a subscriber (ours, ROS's or plain zenoh's) is known to match the key now."""


_LIVE: weakref.WeakSet[ZenohSession] = weakref.WeakSet()


@atexit.register
def _close_all() -> None:
    # zenoh can hang the interpreter's exit on a session nobody closed.
    for backend in list(_LIVE):
        backend.close()


def _close_at_thread_shutdown() -> None:
    # At exit Python joins the non-daemon threads before it runs atexit handlers, and zenoh's
    # callback threads (non-daemon when declared from the main thread) end only once their
    # session closes: a script that ended without closing its node (an uncaught exception,
    # Ctrl-C) waited forever. This runs first (threading's own exit hook, as concurrent.futures
    # uses): the script's own threads finish with the bus still open, then the sessions close.
    try:
        while True:
            others = [t for t in threading.enumerate() if not t.daemon and t is not threading.current_thread()
                      and not t.name.endswith(_CALLBACK_THREAD)]
            if not others:
                break
            for thread in others:
                thread.join()
    finally:
        _close_all()


threading._register_atexit(_close_at_thread_shutdown)  # type: ignore[attr-defined]


class _Undeclare(Handle):
    def __init__(self, backend: ZenohSession, obj: Any) -> None:
        self._backend = backend
        self._obj: Any = obj

    def close(self) -> None:
        obj, self._obj = self._obj, None
        if obj is not None:
            self._backend._forget(self)
            if not self._backend.closed:
                obj.undeclare()


class _Publisher(RawPublisher):
    def __init__(self, backend: ZenohSession, pub: Any, probe: Any = None) -> None:
        self._backend = backend
        self._pub: Any = pub
        self._probe: Any = probe
        self._put = pub.put

    def put(self, payload: bytes, attachment: bytes) -> None:
        try:
            self._put(payload, attachment=attachment)
        except zenoh.ZError as exc:  # e.g. the session was closed under a timer thread
            raise BusError(f"cannot publish: {exc}") from exc

    def matched(self) -> bool:
        pub = self._pub
        if pub is None:
            return False
        return bool((self._probe or pub).matching_status.matching)

    def close(self) -> None:
        pub, self._pub = self._pub, None
        probe, self._probe = self._probe, None
        if pub is not None:
            self._backend._forget(self)
            if not self._backend.closed:
                pub.undeclare()
                if probe is not None:
                    probe.undeclare()


class ZenohSession:
    """A zenoh session (see :mod:`robotmodel.bus._config` for how it finds the others)."""

    def __init__(self, connect: Sequence[str] = (), session: zenoh.Session | None = None) -> None:
        self._session = session if session is not None else open_session(connect)
        self._zid = str(self._session.zid())
        self._lock = threading.Lock()
        self._handles: list[Handle] = []
        self._callback_threads: list[threading.Thread] = []
        self.closed = False
        _LIVE.add(self)

    @property
    def session(self) -> zenoh.Session:
        """The underlying zenoh session."""
        return self._session

    @property
    def zid(self) -> str:
        """The session id as rmw_zenoh writes it in tokens: zenoh's text, lowercase hex without leading zeros."""
        return self._zid

    def _track(self, handle: Handle) -> Handle:
        with self._lock:
            self._handles.append(handle)
        return handle

    def _with_callback_thread(self, declare: Callable[[], Any]) -> Any:
        """``declare()``, keeping the callback thread it starts, for :meth:`close` to wait for.

        That thread inherits the daemon flag of the thread that declared: declared from a
        daemon thread, it is not waited for at exit, and if it wakes (its callback let go by
        the closed session) while the interpreter finalizes, CPython ends it by unwinding
        through zenoh's Rust frames and the process aborts (SIGABRT).
        """
        before = set(threading.enumerate())
        obj = declare()
        started = [t for t in threading.enumerate() if t not in before and t.name.endswith(_CALLBACK_THREAD)]
        with self._lock:
            self._callback_threads.extend(started)
        return obj

    def _forget(self, handle: Handle) -> None:
        with self._lock:
            if handle in self._handles:
                self._handles.remove(handle)

    def declare_publisher(self, key: str, qos: QoS) -> RawPublisher:
        """A publisher on ``key``; transient-local QoS keeps the last ``depth`` samples for late joiners."""
        q = qos.resolved()
        reliable = q.reliability == Reliability.RELIABLE
        common: dict[str, Any] = {
            "congestion_control": zenoh.CongestionControl.BLOCK if qos.blocks else zenoh.CongestionControl.DROP,
            "reliability": zenoh.Reliability.RELIABLE if reliable else zenoh.Reliability.BEST_EFFORT,
        }
        pub: Any
        probe: Any = None
        if q.transient_local:
            pub = zx.declare_advanced_publisher(
                self._session, key, cache=zx.CacheConfig(q.depth), publisher_detection=True,
                sample_miss_detection=zx.MissDetectionConfig(heartbeat=None, sporadic_heartbeat=_HEARTBEAT_S)
                if reliable else None,
                **common)
            # zenoh-python's AdvancedPublisher reports no matching; a plain publisher on the
            # same key that never puts does, and sends nothing.
            probe = self._session.declare_publisher(key)
        else:
            pub = self._session.declare_publisher(key, **common)
        handle = _Publisher(self, pub, probe)
        self._track(handle)
        return handle

    def declare_subscriber(self, key: str, qos: QoS, callback: RawCallback) -> Handle:
        """Call ``callback`` for each sample on ``key`` (which may hold ``*``/``**`` wildcards)."""
        q = qos.resolved()
        # On an exact key the sample's key is the subscription's: skip converting it (~1 us).
        exact = "*" not in key

        def on_sample(sample: zenoh.Sample) -> None:
            att = sample.attachment
            callback(key if exact else str(sample.key_expr), sample.payload.to_bytes(),
                     None if att is None else att.to_bytes())
            sample_releasing()  # the sample goes once this returns (a callback may have asked for the heap back)

        if q.transient_local:
            sub: Any = self._with_callback_thread(lambda: zx.declare_advanced_subscriber(
                self._session, key, on_sample,
                history=zx.HistoryConfig(detect_late_publishers=True, max_samples=q.depth),
                recovery=zx.RecoveryConfig(periodic_queries=None, heartbeat=True)
                if q.reliability == Reliability.RELIABLE else None,
                subscriber_detection=True))
        else:
            sub = self._with_callback_thread(lambda: self._session.declare_subscriber(key, on_sample))
        return self._track(_Undeclare(self, sub))

    def declare_token(self, key: str) -> Handle:
        """Declare a liveliness token, alive until closed or until this session ends."""
        return self._track(_Undeclare(self, self._session.liveliness().declare_token(key)))

    def watch_tokens(self, pattern: str, callback: TokenCallback) -> Handle:
        """Call ``callback(token, alive)`` for tokens matching ``pattern``, current ones first."""

        def on_token(sample: zenoh.Sample) -> None:
            callback(str(sample.key_expr), sample.kind == zenoh.SampleKind.PUT)

        sub = self._with_callback_thread(
            lambda: self._session.liveliness().declare_subscriber(pattern, on_token, history=True))
        return self._track(_Undeclare(self, sub))

    def get_tokens(self, pattern: str, timeout: float) -> list[str]:
        """The live tokens matching ``pattern`` now."""
        tokens = []
        for reply in self._session.liveliness().get(pattern, timeout=timeout):
            if reply.ok is not None:
                tokens.append(str(reply.ok.key_expr))
        return tokens

    def close(self) -> None:
        """End the session (undeclares everything it declared)."""
        with self._lock:
            if self.closed:
                return
            handles = list(reversed(self._handles))
        for handle in handles:
            handle.close()
        with self._lock:
            self.closed = True
            threads, self._callback_threads = self._callback_threads, []
        self._session.close()  # type: ignore[no-untyped-call]
        # Their callbacks are let go now: wait for the threads to end (see _with_callback_thread).
        deadline = time.monotonic() + _CALLBACK_JOIN_S
        for thread in threads:
            if thread is not threading.current_thread():
                thread.join(max(0.0, deadline - time.monotonic()))
