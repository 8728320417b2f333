"""The in-process backend: every session of this process shares one local bus, no sockets.

It behaves like the zenoh backend for what nodes rely on (keys with wildcards, attachments,
transient-local caches served to late subscribers, liveliness tokens), delivering each
sample synchronously in the publishing thread.
"""

from __future__ import annotations

import secrets
import threading
from collections import deque
from collections.abc import Callable

from robotmodel.bus._backend import (
    Backend,
    Handle,
    RawPublisher,
    RawSample,
    SampleCallback,
    TokenCallback,
    key_matches,
)
from robotmodel.bus._qos import QoS

__all__ = ["InProcessBackend"]


class _Sub:
    __slots__ = ("callback", "pattern")

    def __init__(self, pattern: str, callback: SampleCallback) -> None:
        self.pattern = pattern
        self.callback = callback


class _Pub:
    __slots__ = ("cache", "key")

    def __init__(self, key: str, depth: int | None) -> None:
        self.key = key
        self.cache: deque[RawSample] | None = deque(maxlen=depth) if depth else None


class _LocalBus:
    """State shared by all in-process sessions."""

    def __init__(self) -> None:
        self.lock = threading.RLock()
        self.subs: list[_Sub] = []
        self.pubs: list[_Pub] = []
        self.tokens: dict[str, int] = {}
        self.watchers: list[tuple[str, TokenCallback]] = []

    def set_token(self, key: str, alive: bool) -> None:
        with self.lock:
            count = self.tokens.get(key, 0) + (1 if alive else -1)
            if count > 0:
                self.tokens[key] = count
            else:
                self.tokens.pop(key, None)
            changed = count == 1 if alive else count == 0
            watchers = [cb for pat, cb in self.watchers if key_matches(pat, key)] if changed else []
        for cb in watchers:
            cb(key, alive)


_BUS = _LocalBus()


class _Closer(Handle):
    def __init__(self, fn: Callable[[], None]) -> None:
        self._fn: Callable[[], None] | None = fn

    def close(self) -> None:
        fn, self._fn = self._fn, None
        if fn is not None:
            fn()


class _LocalPublisher(RawPublisher):
    def __init__(self, bus: _LocalBus, pub: _Pub) -> None:
        self._bus = bus
        self._pub: _Pub | None = pub

    def put(self, payload: bytes, attachment: bytes) -> None:
        pub = self._pub
        if pub is None:
            return
        sample = RawSample(pub.key, bytes(payload), bytes(attachment))
        with self._bus.lock:
            if pub.cache is not None:
                pub.cache.append(sample)
            targets = [s.callback for s in self._bus.subs if key_matches(s.pattern, pub.key)]
        for cb in targets:
            cb(sample)

    def matched(self) -> bool:
        pub = self._pub
        with self._bus.lock:
            return pub is not None and any(key_matches(s.pattern, pub.key) for s in self._bus.subs)

    def close(self) -> None:
        pub, self._pub = self._pub, None
        if pub is not None:
            with self._bus.lock:
                self._bus.pubs.remove(pub)


class InProcessBackend(Backend):
    """A session on this process's local bus."""

    def __init__(self) -> None:
        self._zid = secrets.token_hex(16)
        self._bus = _BUS
        self._handles: list[Handle] = []
        self._closed = False

    @property
    def zid(self) -> str:
        """See :attr:`Backend.zid`."""
        return self._zid

    def _track(self, handle: Handle) -> Handle:
        self._handles.append(handle)
        return handle

    def declare_publisher(self, key: str, qos: QoS) -> RawPublisher:
        """See :meth:`Backend.declare_publisher`."""
        q = qos.resolved()
        pub = _Pub(key, q.depth if q.transient_local else None)
        with self._bus.lock:
            self._bus.pubs.append(pub)
        handle = _LocalPublisher(self._bus, pub)
        self._track(handle)
        return handle

    def declare_subscriber(self, key: str, qos: QoS, callback: SampleCallback) -> Handle:
        """See :meth:`Backend.declare_subscriber`."""
        sub = _Sub(key, callback)
        with self._bus.lock:
            self._bus.subs.append(sub)
            history: list[RawSample] = []
            if qos.transient_local:
                for pub in self._bus.pubs:
                    if pub.cache is not None and key_matches(key, pub.key):
                        history.extend(list(pub.cache)[-qos.resolved().depth:])
        for sample in history:
            callback(sample)

        def remove() -> None:
            with self._bus.lock:
                self._bus.subs.remove(sub)

        return self._track(_Closer(remove))

    def declare_token(self, key: str) -> Handle:
        """See :meth:`Backend.declare_token`."""
        self._bus.set_token(key, True)
        return self._track(_Closer(lambda: self._bus.set_token(key, False)))

    def watch_tokens(self, pattern: str, callback: TokenCallback) -> Handle:
        """See :meth:`Backend.watch_tokens`."""
        entry = (pattern, callback)
        with self._bus.lock:
            current = [k for k in self._bus.tokens if key_matches(pattern, k)]
            self._bus.watchers.append(entry)
        for key in current:
            callback(key, True)

        def remove() -> None:
            with self._bus.lock:
                self._bus.watchers.remove(entry)

        return self._track(_Closer(remove))

    def get_tokens(self, pattern: str, timeout: float) -> list[str]:
        """See :meth:`Backend.get_tokens`."""
        with self._bus.lock:
            return [k for k in self._bus.tokens if key_matches(pattern, k)]

    def close(self) -> None:
        """See :meth:`Backend.close`."""
        if self._closed:
            return
        self._closed = True
        # Tokens last: peers see the entities leave after their data stops.
        for handle in reversed(self._handles):
            handle.close()
        self._handles.clear()
