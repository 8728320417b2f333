"""What a transport gives the nodes: keyed puts with attachments, subscribers, liveliness tokens.

Two implementations share this interface: :mod:`._zenoh` (processes and machines) and
:mod:`._inprocess` (one process, no sockets; for library users and unit tests).
"""

from __future__ import annotations

from abc import ABC, abstractmethod
from collections.abc import Callable
from typing import NamedTuple

from robotmodel.bus._qos import QoS

__all__ = ["Backend", "Handle", "RawPublisher", "RawSample", "key_matches"]


class RawSample(NamedTuple):
    """A received sample as it came off the wire: key, CDR payload, attachment bytes (or None)."""

    key: str
    payload: bytes
    attachment: bytes | None


SampleCallback = Callable[[RawSample], None]
TokenCallback = Callable[[str, bool], None]


class Handle(ABC):
    """Something declared on a backend that must be released."""

    @abstractmethod
    def close(self) -> None:
        """Undeclare it; closing twice is harmless."""


class RawPublisher(Handle):
    """A declared publisher: puts payloads with attachments on one key."""

    @abstractmethod
    def put(self, payload: bytes, attachment: bytes) -> None:
        """Send one sample."""

    @abstractmethod
    def matched(self) -> bool:
        """Whether a subscriber (ours, ROS's or plain zenoh's) is known to match the key now."""


class Backend(ABC):
    """One session on a transport (rmw_zenoh's context)."""

    @property
    @abstractmethod
    def zid(self) -> str:
        """The session id as rmw_zenoh writes it in tokens: zenoh's text, lowercase hex without leading zeros."""

    @abstractmethod
    def declare_publisher(self, key: str, qos: QoS) -> RawPublisher:
        """A publisher on ``key``; transient-local QoS keeps the last ``depth`` samples for late joiners."""

    @abstractmethod
    def declare_subscriber(self, key: str, qos: QoS, callback: SampleCallback) -> Handle:
        """Call ``callback`` for each sample on ``key`` (which may hold ``*``/``**`` wildcards)."""

    @abstractmethod
    def declare_token(self, key: str) -> Handle:
        """Declare a liveliness token, alive until closed or until this session ends."""

    @abstractmethod
    def watch_tokens(self, pattern: str, callback: TokenCallback) -> Handle:
        """Call ``callback(token, alive)`` for tokens matching ``pattern``, current ones first."""

    @abstractmethod
    def get_tokens(self, pattern: str, timeout: float) -> list[str]:
        """The live tokens matching ``pattern`` now."""

    @abstractmethod
    def close(self) -> None:
        """End the session (undeclares everything it declared)."""


def key_matches(pattern: str, key: str) -> bool:
    """Zenoh's matching of a key by a pattern with ``*`` (one chunk) and ``**`` (any chunks).

    Chunks starting with '@' (hermetic, like ``@ros2_lv``) are only matched literally.
    """
    return _match(pattern.split("/"), key.split("/"))


def _match(pat: list[str], key: list[str]) -> bool:
    if not pat:
        return not key
    head = pat[0]
    if head == "**":
        if len(pat) == 1:
            return not any(k.startswith("@") for k in key)
        return any(_match(pat[1:], key[i:]) for i in range(len(key) + 1)
                   if not any(k.startswith("@") for k in key[:i]))
    if not key:
        return False
    if head == "*":
        return not key[0].startswith("@") and _match(pat[1:], key[1:])
    return head == key[0] and _match(pat[1:], key[1:])
