"""ROS 2 services on zenoh, in rmw_zenoh's form.

A service server declares a queryable on the service's key (the topic key form:
``<domain>/<name>/<pkg>::srv::dds_::<Name>_/<RIHS01 hash of the service>``, complete) and an
``SS`` liveliness token; a client declares an ``SC`` token and sends each request as a
``get`` on that key (target all-complete, no consolidation) with the request's CDR as the
payload and rmw_zenoh's attachment: the request's sequence number (from 1 per client), its
source time and the client's GID. The server replies on the same key with the response's CDR
and an attachment holding the request's sequence number and client GID, by which the
client pairs the reply with its request. A client knows a server is there from the
``SS`` tokens of the name and type.

Only the zenoh wire uses this module (it is below the backend seam).
"""

from __future__ import annotations

import itertools
import logging
import threading
import time
from typing import TYPE_CHECKING, Any

import zenoh

from robotmodel.bus._attachment import AttachmentWriter, read_attachment
from robotmodel.bus._backend import (
    ClientHandle,
    EntityKind,
    Handle,
    MessageType,
    RequestCallback,
    RequestId,
    ResponseCallback,
    ServiceType,
)
from robotmodel.bus._names import dds_type_name
from robotmodel.bus._qos import QoS
from robotmodel.bus._zenoh_names import ADMIN_SPACE, TOKEN_KINDS, mangle, topic_keyexpr
from robotmodel.errors import BusError

if TYPE_CHECKING:
    from robotmodel.bus._zenoh import ZenohNode

__all__ = ["ZenohClient", "ZenohService"]

log = logging.getLogger("robotmodel.bus")
#: rmw_qos_profile_services_default (reliable, volatile, keep last 10), as the tokens carry it.
SERVICES_QOS = QoS(10)
# rmw_zenoh's clients waited for replies as long as it took (ros2/rmw_zenoh#133); since #685 only
# ``**/_action/get_result/**`` does, other services end at the session's queries_default_timeout (60 s).
# Here one long bound for all: a lost server must not leak queries for ever.
_QUERY_TIMEOUT_S = 3600.0


def _key(node: ZenohNode, name: str, stype: ServiceType) -> str:
    return topic_keyexpr(node.backend.domain_id, name, stype.typename, stype.type_hash)


class ZenohService(Handle):
    """A service: a complete queryable on the service's key and its SS token."""

    def __init__(self, node: ZenohNode, name: str, stype: ServiceType, on_request: RequestCallback) -> None:
        session = node.backend.zenoh
        self.name = name
        self._key = _key(node, name, stype)
        self._on_request = on_request
        self.token = node.entity_token(EntityKind.SERVICE, name, MessageType(stype.typename, stype.type_hash),
                                       SERVICES_QOS)
        self._writer = AttachmentWriter(self.token.gid)
        self._open = True
        self._queryable: Any = session._with_callback_thread(
            lambda: session.session.declare_queryable(self._key, self._on_query, complete=True))
        self._token: Handle | None = session.declare_token(self.token.keyexpr)

    def _on_query(self, query: Any) -> None:
        payload = query.payload
        att = query.attachment
        fields = read_attachment(None if att is None else att.to_bytes())
        if payload is None or fields is None:
            log.warning("dropped a request to '%s' without rmw_zenoh's payload and attachment", self.name)
            return
        seq, _stamp, gid = fields
        lock = threading.Lock()
        pending = [query]

        def respond(response: bytes) -> None:
            with lock:
                if not pending or not self._open:
                    return
                q = pending.pop()
            # The reply names the request: its sequence number and the client's GID.
            q.reply(self._key, response, attachment=AttachmentWriter(gid)(seq, time.time_ns()))
            q.drop()  # the query ends (its final reply goes out) once the reply is sent

        self._on_request(payload.to_bytes(), RequestId(gid, seq), respond)

    def close(self) -> None:
        """Undeclare the queryable and the token."""
        if not self._open:
            return
        self._open = False
        self._queryable.undeclare()
        token, self._token = self._token, None
        if token is not None:
            token.close()


class ZenohClient(ClientHandle):
    """A client: its SC token, a ``get`` per request, and a watch on the service's SS tokens."""

    def __init__(self, node: ZenohNode, name: str, stype: ServiceType) -> None:
        backend = node.backend
        self._session = backend.zenoh
        self.name = name
        self._key = _key(node, name, stype)
        self.token = node.entity_token(EntityKind.CLIENT, name, MessageType(stype.typename, stype.type_hash),
                                       SERVICES_QOS)
        self._gid = self.token.gid
        self._attach = AttachmentWriter(self._gid)
        self._seq = itertools.count(1)
        self._lock = threading.Lock()
        self._servers: set[str] = set()
        self._open = True
        kind = TOKEN_KINDS[EntityKind.SERVICE]
        pattern = (f"{ADMIN_SPACE}/{backend.domain_id}/*/*/*/{kind}/*/*/*/{mangle(name)}/"
                   f"{dds_type_name(stype.typename)}/{stype.type_hash}/*")
        self._watch: Handle | None = self._session.watch_tokens(pattern, self._on_token)
        self._token: Handle | None = self._session.declare_token(self.token.keyexpr)

    def _on_token(self, token: str, alive: bool) -> None:
        with self._lock:
            if alive:
                self._servers.add(token)
            else:
                self._servers.discard(token)

    @property
    def gid(self) -> bytes:
        """See :attr:`ClientHandle.gid` (XXH3-128 of its token, as rmw_zenoh)."""
        return self._gid

    def request(self, payload: bytes, on_response: ResponseCallback) -> int:
        """See :meth:`ClientHandle.request`."""
        if not self._open:
            raise BusError(f"client of '{self.name}' is closed")
        seq = next(self._seq)
        answered = threading.Event()

        def on_reply(reply: Any) -> None:
            ok = reply.ok
            if ok is None or answered.is_set() or not self._open:
                return
            att = ok.attachment
            fields = read_attachment(None if att is None else att.to_bytes())
            if fields is not None and fields[0] != seq:
                return
            answered.set()
            on_response(ok.payload.to_bytes())

        self._session._with_callback_thread(lambda: self._session.session.get(
            self._key, on_reply, target=zenoh.QueryTarget.ALL_COMPLETE,
            consolidation=zenoh.ConsolidationMode.NONE, payload=payload,
            attachment=self._attach(seq, time.time_ns()), timeout=_QUERY_TIMEOUT_S))
        return seq

    def server_ready(self) -> bool:
        """See :meth:`ClientHandle.server_ready`: a live SS token of this name and type."""
        with self._lock:
            return bool(self._servers)

    def close(self) -> None:
        """Undeclare the token and stop watching; replies still to come are dropped."""
        self._open = False
        for attr in ("_watch", "_token"):
            handle = getattr(self, attr)
            setattr(self, attr, None)
            if handle is not None:
                handle.close()
