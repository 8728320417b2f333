"""tf2_ros's TransformListener: fills a Buffer from ``/tf`` and ``/tf_static``."""

from __future__ import annotations

import logging
import threading
import time
from types import TracebackType
from typing import TYPE_CHECKING, Any

from robotmodel._heap import release_after_sample, release_free_memory
from robotmodel.errors import MessageError, TransformException
from robotmodel.msgs import TFMessage
from robotmodel.tf_ros._authority import PublisherNames
from robotmodel.tf_ros._node import OwnedNode

if TYPE_CHECKING:
    from robotmodel.bus import Node, QoS, RawMessage

__all__ = ["DEFAULT_AUTHORITY", "TransformListener"]

#: The authority tf2_ros's Python listener records for every transform.
DEFAULT_AUTHORITY = "default_authority"

_log = logging.getLogger("robotmodel.tf_ros")
_WARN_PERIOD_S = 5.0
#: Transforms in one message from which a listener gives freed memory back afterwards.
BIG_MESSAGE = 10_000


class TransformListener:
    """Subscribes to ``/tf`` and ``/tf_static`` and inserts what arrives into ``buffer``.

    Messages are handled on the bus's receiving thread, so ``buffer.lookup_transform(...,
    timeout=...)`` called from any other thread wakes as soon as the data it needs arrives.
    Payloads are decoded straight into records for the buffer's message-free ``insert``
    (static ones as static); a buffer without ``insert`` gets ``set_transform`` /
    ``set_transform_static`` with messages, as tf2_ros does.

    ``node`` is a :class:`robotmodel.bus.Node`; without one the listener opens its own
    (``node_options``, e.g. ``domain_id`` or ``connect``, go to its constructor) and closes
    it in :meth:`close`. The QoS defaults are tf2_ros's (depth 100; ``/tf_static`` transient
    local, so transforms latched before the listener started arrive too).

    ``authority`` is what the buffer records as each transform's broadcaster (shown by
    ``all_frames_as_yaml`` and view_frames). By default it is the publishing node's fully
    qualified name: the one the wire gives with each sample (ROS 1's callerid, as ROS 1's
    listener recorded it), else the publisher's GID in the sample's info looked up in the
    bus's graph;
    ``default_authority`` (tf2_ros Python's constant) while the publisher is not known.
    Pass a string to record that instead. ``spin_thread`` is accepted for tf2_ros
    compatibility: the bus always delivers on its own thread.

    A payload that does not decode as a TFMessage is dropped with a rate-limited warning.
    """

    def __init__(self, buffer: Any, node: Node | None = None, *, spin_thread: bool = True,
                 qos: QoS | int | None = None, static_qos: QoS | int | None = None, authority: str | None = None,
                 **node_options: Any) -> None:
        from robotmodel.bus import QOS_TF, QOS_TF_STATIC_LISTENER, TFRecords, codec_for

        del spin_thread
        self.buffer = buffer
        self._authority = authority
        self._names: PublisherNames | None = None
        # Which publisher sent the static transform each child frame has now, so that a late
        # re-attribution never overwrites a newer transform from someone else.
        self._static_owner: dict[str, bytes] = {}
        self._static_lock = threading.Lock()
        self._warn_lock = threading.Lock()
        self._last_warning = -1e9
        self._held = 0
        # robotmodel's buffers take message-free inserts; any other buffer gets messages.
        self._insert: Any = getattr(buffer, "insert", None)
        self._node = OwnedNode(node, "transform_listener_impl_", **node_options)
        self._subs: list[Any] = []
        self._closed = False
        try:
            n = self._node.node
            # Samples may arrive while a subscription is being created (latched ones do), so the
            # decoders (for the wire's encoding) must be ready before either exists.
            self._codec = codec_for(TFMessage, n.context.encoding)
            self._records = codec_for(TFRecords, n.context.encoding)
            if authority is None:
                # Start following the graph now, not on the receive thread at the first sample.
                self._names = PublisherNames(n.context.graph)
            self._subs.append(n.create_subscription(TFMessage, "/tf", self._on_tf,
                                                    qos if qos is not None else QOS_TF, raw=True))
            self._subs.append(n.create_subscription(TFMessage, "/tf_static", self._on_tf_static,
                                                    static_qos if static_qos is not None
                                                    else QOS_TF_STATIC_LISTENER, raw=True))
        except BaseException:
            self.close()
            raise

    @property
    def node(self) -> Node:
        """The bus node the subscriptions live on."""
        return self._node.node

    # The bus hands over undecoded samples so that the publisher's GID is at hand; they are
    # decoded straight into (parent, child, stamp, pose) records when the buffer takes them.
    def _on_tf(self, raw: RawMessage) -> None:
        self._handle(raw, False)

    def _on_tf_static(self, raw: RawMessage) -> None:
        self._handle(raw, True)

    def _handle(self, raw: RawMessage, is_static: bool) -> None:
        insert = self._insert
        try:
            if insert is not None:
                records = self._records.decode(raw.payload)
            else:
                msg: TFMessage = self._codec.decode(raw.payload)
        except MessageError as exc:  # a bad payload is dropped, never a crash
            self._warn(f"dropped a message on '{raw.topic}' that does not decode as tf2_msgs/msg/TFMessage: "
                       f"{type(exc).__name__}: {exc}")
            return
        gid = raw.info.gid
        # A wire that names the publishing node with each sample (ROS 1's callerid) is believed.
        who = raw.info.publisher if self._authority is None and raw.info.publisher else self._who(gid)
        if not (is_static and self._names is not None):
            self._insert_all(msg if insert is None else records, who, is_static)
            if insert is not None and len(records) >= BIG_MESSAGE:
                # The records' heap now, the payload's (and the wire's buffers) once the wire drops it.
                del records
                release_free_memory()
                release_after_sample()
            return
        items: list[Any] = list(msg.transforms) if insert is None else records
        with self._static_lock:
            for item in items:
                self._static_owner[item.child_frame_id if insert is None else item.child] = gid
            self._insert_all(msg if insert is None else records, who, True)
        if who == DEFAULT_AUTHORITY:
            # Sent once and latched: no later sample will carry the name, so put these in
            # again under it once the graph shows their publisher.
            self._names.when_known(gid, lambda name: self._reattribute(gid, items, name))

    def _insert_all(self, data: Any, who: str, is_static: bool) -> None:
        insert = self._insert
        if insert is None:
            (self.static_callback if is_static else self.callback)(data, who)
            return
        insert_records = getattr(self.buffer, "insert_records", None)
        if insert_records is not None:  # robotmodel's buffer: the whole message under one lock
            failures = insert_records(data, who, is_static)
        else:
            failures = []
            for rec in data:
                try:
                    insert(rec.parent, rec.child, rec.stamp_ns, rec.pose, who, is_static)
                except TransformException as exc:
                    failures.append((rec, exc))
        for rec, error in failures:
            # As tf2_ros's listener: one bad transform (e.g. a negative stamp) is reported
            # and the rest of the message still goes in.
            self._warn(f"Failure to set received transform from {rec.child} to {rec.parent} with error: {error}")

    def _reattribute(self, gid: bytes, items: list[Any], name: str) -> None:
        with self._static_lock:
            for item in items:
                if self._insert is None:
                    if self._static_owner.get(item.child_frame_id) == gid:
                        self.buffer.set_transform_static(item, name)
                elif self._static_owner.get(item.child) == gid:
                    self._insert(item.parent, item.child, item.stamp_ns, item.pose, name, True)

    def _warn(self, text: str) -> None:
        now = time.monotonic()
        with self._warn_lock:
            if now - self._last_warning < _WARN_PERIOD_S:
                self._held += 1
                return
            self._last_warning = now
            held, self._held = self._held, 0
        _log.warning("%s%s", text, f" ({held} more since the last warning)" if held else "")

    def _who(self, gid: bytes) -> str:
        if self._authority is not None:
            return self._authority
        assert self._names is not None
        return self._names.name(gid) or DEFAULT_AUTHORITY

    def callback(self, data: TFMessage, authority: str = DEFAULT_AUTHORITY) -> None:
        """Insert the transforms of one ``/tf`` message."""
        for transform in data.transforms:
            self._set(transform, authority, False)

    def static_callback(self, data: TFMessage, authority: str = DEFAULT_AUTHORITY) -> None:
        """Insert the transforms of one ``/tf_static`` message as static."""
        for transform in data.transforms:
            self._set(transform, authority, True)

    def _set(self, transform: Any, authority: str, is_static: bool) -> None:
        try:
            self.buffer.set_transform(transform, authority, is_static)
        except TransformException as exc:
            self._warn(f"Failure to set received transform from {transform.child_frame_id} to "
                       f"{transform.header.frame_id} with error: {exc}")

    def unregister(self) -> None:
        """Withdraw both subscriptions (tf2_ros's name); the buffer keeps its data."""
        subs, self._subs = self._subs, []
        for sub in subs:
            sub.close()

    def close(self) -> None:
        """Unregister, and close the node if this listener opened it; harmless twice."""
        if self._closed:
            return
        self._closed = True
        if self._names is not None:
            self._names.close()
        try:
            self.unregister()
        finally:
            self._node.close()

    def __enter__(self) -> TransformListener:
        return self

    def __exit__(self, exc_type: type[BaseException] | None, exc: BaseException | None,
                 tb: TracebackType | None) -> None:
        self.close()
