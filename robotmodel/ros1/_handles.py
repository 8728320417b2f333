"""The handles a :class:`robotmodel.ros1.Ros1Node` gives out: one per ``advertise`` and ``subscribe`` call.

Several handles may share one topic's registration; the last one closed unregisters it.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from typing import TYPE_CHECKING, Any

from robotmodel.errors import Ros1Error
from robotmodel.ros1._msgs import Ros1Type, deserialize, serialize
from robotmodel.ros1._publisher import Publication
from robotmodel.ros1._subscriber import Subscription

if TYPE_CHECKING:
    from robotmodel.ros1._node import Ros1Node

__all__ = ["Ros1Publisher", "Ros1Subscriber"]


class Ros1Publisher:
    """A handle on a topic the node publishes; :meth:`publish` takes a rosbags message of the type."""

    def __init__(self, node: Ros1Node, publication: Publication) -> None:
        self._node = node
        self._publication = publication
        self.topic = publication.topic
        self.type: Ros1Type = publication.type

    def publish(self, message: Any) -> None:
        """Serialize ``message`` and send it to every subscriber.

        After :meth:`close` this raises :class:`Ros1Error`; after the node shut down (``rosnode
        kill`` may come between a loop's check and its publish) it does nothing, as roscpp does.
        """
        self.publish_raw(serialize(message, self.type.name))

    def publish_raw(self, data: bytes) -> None:
        """Send already serialized ROS 1 bytes (see :meth:`publish`)."""
        try:
            self._publication.publish(data)
        except Ros1Error:
            if not self._node.is_shutdown:
                raise

    @property
    def subscriber_count(self) -> int:
        """TCPROS subscribers connected now."""
        return self._publication.subscriber_count

    def close(self) -> None:
        """Stop publishing; the last handle on a topic unregisters it at the master."""
        self._node._release_publication(self.topic, self)


class Ros1Subscriber:
    """A handle on a subscription; its callback gets each message (or its bytes when ``raw``)."""

    def __init__(self, node: Ros1Node, subscription: Subscription, callback: Callable[..., None],
                 raw: bool, with_header: bool = False) -> None:
        self._node = node
        self.subscription = subscription
        self.topic = subscription.topic
        self.type: Ros1Type = subscription.type
        self.callback = callback
        self.raw = raw
        self.with_header = with_header

    def deliver(self, data: bytes, header: Mapping[str, str]) -> None:
        """Hand ``data`` to the callback, decoded unless raw (with the publisher's header when asked)."""
        if self.with_header:
            self.callback(data, header)
        else:
            self.callback(data if self.raw else deserialize(data, self.type.name))

    @property
    def publisher_uris(self) -> list[str]:
        """Slave URIs of the publishers connected now."""
        return self.subscription.publisher_uris

    def close(self) -> None:
        """Stop receiving; the last handle on a topic unregisters it at the master."""
        self._node._release_subscription(self.topic, self)
