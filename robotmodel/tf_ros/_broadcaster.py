"""tf2_ros's broadcasters: TransformBroadcaster on ``/tf``, StaticTransformBroadcaster on ``/tf_static``."""

from __future__ import annotations

import threading
from collections.abc import Iterable
from types import TracebackType
from typing import TYPE_CHECKING, Any, Self

from robotmodel.msgs import TFMessage, TransformStamped
from robotmodel.tf_ros._node import OwnedNode

if TYPE_CHECKING:
    from robotmodel.bus import Node, QoS

__all__ = ["StaticTransformBroadcaster", "TransformBroadcaster"]


def _as_list(transform: TransformStamped | Iterable[TransformStamped]) -> list[TransformStamped]:
    # A transform is recognized by its fields, so any TransformStamped-shaped object works.
    if hasattr(transform, "child_frame_id"):
        return [transform]  # type: ignore[list-item]
    return list(transform)


class _Broadcaster:
    """Shared life cycle: a publisher on one topic of a node that may be ours to close."""

    _topic = ""
    _prefix = ""

    def __init__(self, node: Node | None, qos: QoS | int | None, default_qos: QoS, **node_options: Any) -> None:
        self._node = OwnedNode(node, self._prefix, **node_options)
        try:
            self._pub = self._node.node.create_publisher(TFMessage, self._topic, qos if qos is not None
                                                         else default_qos)
        except BaseException:
            self._node.close()
            raise
        self._closed = False

    @property
    def node(self) -> Node:
        """The bus node this broadcaster publishes from."""
        return self._node.node

    def close(self) -> None:
        """Withdraw the publisher (and close the node if this object opened it); harmless twice."""
        if self._closed:
            return
        self._closed = True
        try:
            self._pub.close()
        finally:
            self._node.close()

    def __enter__(self) -> Self:
        return self

    def __exit__(self, exc_type: type[BaseException] | None, exc: BaseException | None,
                 tb: TracebackType | None) -> None:
        self.close()


class TransformBroadcaster(_Broadcaster):
    """Sends transform updates on ``/tf``: ``TransformBroadcaster(node).send_transform(t)``.

    ``node`` is a :class:`robotmodel.bus.Node`; without one the broadcaster opens its own
    (``node_options`` go to its constructor) and closes it in :meth:`close`. ``qos`` defaults
    to tf2_ros's: keep-last 100, reliable, volatile.
    """

    _topic = "/tf"
    _prefix = "transform_broadcaster_"

    def __init__(self, node: Node | None = None, qos: QoS | int | None = None, **node_options: Any) -> None:
        from robotmodel.bus import QOS_TF

        super().__init__(node, qos, QOS_TF, **node_options)

    def send_transform(self, transform: TransformStamped | Iterable[TransformStamped]) -> None:
        """Publish one transform or a list of them, as one TFMessage."""
        self._pub.publish(TFMessage(transforms=_as_list(transform)))

    sendTransform = send_transform  # noqa: N815  (tf2_ros's spelling, so ported code runs)


class StaticTransformBroadcaster(_Broadcaster):
    """Publishes transforms that never change on ``/tf_static``, latched.

    Like tf2_ros's C++ broadcaster it keeps the latest transform per child frame and
    republishes the whole set on every call, so a late subscriber (the topic is transient
    local with depth 1) gets every static transform sent so far in one message.
    """

    _topic = "/tf_static"
    _prefix = "static_transform_broadcaster_"

    def __init__(self, node: Node | None = None, qos: QoS | int | None = None, **node_options: Any) -> None:
        from robotmodel.bus import QOS_TF_STATIC

        super().__init__(node, qos, QOS_TF_STATIC, **node_options)
        self._latest: dict[str, TransformStamped] = {}
        self._lock = threading.Lock()

    def send_transform(self, transform: TransformStamped | Iterable[TransformStamped]) -> None:
        """Record these transforms (replacing earlier ones for the same child) and publish the set."""
        with self._lock:
            for t in _as_list(transform):
                self._latest[t.child_frame_id] = t
            # Publishing under the lock keeps concurrent callers from reordering the sets.
            self._pub.publish(TFMessage(transforms=list(self._latest.values())))

    sendTransform = send_transform  # noqa: N815

    @property
    def transforms(self) -> list[TransformStamped]:
        """The set published last, one transform per child frame."""
        with self._lock:
            return list(self._latest.values())
