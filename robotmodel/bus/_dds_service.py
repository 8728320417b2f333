"""ROS 2 services on DDS, as rmw_cyclonedds_cpp carries them.

A service ``/add`` of ``example_interfaces/srv/AddTwoInts`` is two DDS topics: requests on
``rq/addRequest`` (type ``example_interfaces::srv::dds_::AddTwoInts_Request_``) and replies on
``rr/addReply`` (``..._Response_``), both reliable, volatile, keep last 10 (rmw's services
QoS). Every request and reply starts, after the CDR encapsulation header, with
rmw_cyclonedds_cpp's ``cdds_request_header_t``: the client's 64-bit id and the request's
64-bit sequence number, in the payload's byte order; the server copies both into its reply,
and each client keeps the replies carrying its own id (every client of a service reads
every reply). The client id is made from its request writer's GUID.

rmw_fastrtps_cpp carries the request id out of band instead (the RTPS inline QoS
``PID_RELATED_SAMPLE_IDENTITY``) and writes the bare message, which Cyclone 11.0.1 can
neither write nor show to a reader: as between rmw_cyclonedds_cpp and rmw_fastrtps_cpp
(ros2/rmw_cyclonedds#184), a Fast DDS client gets no reply from this wire. Its client
listener (rmw_fastrtps_shared_cpp's ``custom_client_info.hpp``) keeps a reply only when
``SampleInfo.related_sample_identity`` names its own request writer or reply reader, and
Fast DDS fills that from the DATA submessage's inline QoS alone (PID 0x800f, or the DDS-RPC
0x0083), never from the payload; libddsc 11.0.1 exports no call that puts a parameter in a
sample's inline QoS, so no form of the reply written here can reach it. A service here
still takes Fast DDS's requests (a second reader of the bare type keeps the samples of
writers whose GUID's vendor id is not Cyclone's, 01.10; the request id is the writer's
GUID and its count of requests), so a Fast DDS ``ros2 param set`` takes effect although
the client waits in vain for its answer.

A client here does call a Fast DDS service (rmw_fastrtps_shared_cpp, Jazzy). The server's
``__rmw_take_request`` (``rmw_request.cpp``) takes the request's sample identity, the
request writer's GUID and sequence number, and puts the related sample identity's GUID in
its place only when the DATA has one; a request written here has none, so its id is our
bare request writer's GUID and sequence number. ``__rmw_send_response`` (``rmw_response.cpp``)
waits for the client's reply reader, and drops the reply when that client is gone
(``check_for_subscription``, ``custom_service_info.hpp``), only when that GUID's entity kind
has the reader bit (0x04): a writer's has not, so the server answers at once, with the bare
response, to every reply reader it has matched. The client therefore writes the bare request
(on a bare-typed writer) to a server whose participant is another vendor's, and pairs each
bare reply with its oldest request to that participant (the reply writer's GUID prefix is
the server's): exact while nobody else calls that server at the same moment, as with one
request at a time per client (ros2cli's tools, ``robotmodel param``); a concurrent caller's
reply could be taken instead, which only the inline QoS would tell apart, and a reply lost on
the way (it is read best effort) would shift the pairing of a client that goes on calling. The reply reader
is best effort: Cyclone holds a reliable reader's first samples from a non-Cyclone writer
until that writer's first heartbeat, then starts after the heartbeat's last sequence number
(``handle_Heartbeat`` in ``ddsi_receive.c``), and Fast DDS sends a GAP and a HEARTBEAT that
already count the reply just before the reply itself, so a reliable reader lost every first
reply. The reader of rmw_cyclonedds' form, which matches the Fast DDS writer by type name
and would keep it reliable, is deleted before the first request to such a server. As the
server does not wait for our reply reader, the bare reader is created before the bare
request writer, so that the server learns of it first.

Only the DDS wire uses this module (it is below the backend seam).
"""

from __future__ import annotations

import itertools
import logging
import struct
import threading
import time
from collections import deque
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from cyclonedds.pub import DataWriter
from cyclonedds.sub import DataReader

from robotmodel.bus._backend import ClientHandle, Handle, RequestCallback, RequestId, ResponseCallback, ServiceType
from robotmodel.bus._dds_qos import qos_to_dds
from robotmodel.bus._dds_raw import Pump, destroy, take_raw, write_raw
from robotmodel.bus._dds_types import CYCLONE_VENDOR, reply_topic_name, request_topic_name
from robotmodel.bus._qos import QoS, Reliability
from robotmodel.errors import BusError

if TYPE_CHECKING:
    from robotmodel.bus._dds import DdsNode

__all__ = ["DdsClient", "DdsService", "add_header", "split_header"]

log = logging.getLogger("robotmodel.bus")
#: rmw_qos_profile_services_default: reliable, volatile, keep last 10.
SERVICES_QOS = QoS(10)
_HEADER = 16
#: How long a server waits for a requesting client's reply reader to be discovered before it answers anyway.
_READER_WAIT_S = 2.0


def add_header(payload: bytes, guid: int, seq: int) -> bytes:
    """``payload`` (CDR with its encapsulation header) with rmw_cyclonedds' request header inserted."""
    order = "<" if len(payload) > 1 and payload[1] & 1 else ">"
    return payload[:4] + struct.pack(order + "Qq", guid, seq) + payload[4:]


def split_header(data: bytes) -> tuple[int, int, bytes] | None:
    """(client id, sequence number, payload without the header), or None when too short."""
    if len(data) < 4 + _HEADER:
        return None
    order = "<" if data[1] & 1 else ">"
    guid, seq = struct.unpack_from(order + "Qq", data, 4)
    return guid, seq, data[:4] + data[4 + _HEADER:]


def _client_id(gid: bytes) -> int:
    # 64 bits of the writer's GUID: its participant's prefix varies in the first half, the entity in the last.
    return int.from_bytes(gid[:8], "little") ^ int.from_bytes(gid[8:], "little")


ForeignCallback = Callable[[bytes, bytes, int], None]


class _Pair:
    """A reader on one of a service's topics and a writer on the other, with a pump for the reader.

    With ``on_foreign``, a second reader of the bare type takes other vendors' samples
    (``on_foreign(payload, writer GUID, its count)``); each reader keeps only its vendors'.
    It is best effort when ``foreign_reliable`` is False (a client's: see :class:`DdsClient`).
    """

    def __init__(self, node: DdsNode, name: str, read: tuple[str, str], write: tuple[str, str],
                 on_data: Callable[[bytes, bytes], None], type_hash: str,
                 on_foreign: ForeignCallback | None = None, foreign_reliable: bool = True) -> None:
        backend = node.backend
        self._node = node
        self.name = name
        self._on_data = on_data
        self._on_foreign = on_foreign
        self._write_typename = write[1]
        self._open = True
        self._reader: Any = None
        self._foreign: Any = None
        self._writers: dict[tuple[int, int], bytes] = {}
        self._counts: dict[bytes, int] = {}
        self._pump = Pump(f"dds-srv {name}", self._drain)
        self._listener = self._pump.listener()
        qos = qos_to_dds(SERVICES_QOS, type_hash)
        self._writer: Any = DataWriter(backend.participant, backend.dds_topic(write[0], write[1], True), qos)
        self._bare: Any = None
        self._reader = DataReader(backend.participant, backend.dds_topic(read[0], read[1], True), qos,
                                  listener=self._listener)
        if on_foreign is not None:
            foreign_qos = qos if foreign_reliable else qos_to_dds(
                QoS(SERVICES_QOS.depth, Reliability.BEST_EFFORT), type_hash)
            self._foreign = DataReader(backend.participant, backend.dds_topic(read[0], read[1]), foreign_qos,
                                       listener=self._listener)
            # A bare-typed writer beside it: a client writes other vendors' requests on it, and
            # a server never writes on it, but rmw_fastrtps_cpp finds a server available only
            # when the request readers and reply writers it discovers are as many.
            self._bare = DataWriter(backend.participant, backend.dds_topic(write[0], write[1]), qos)
        self.reader_gid: bytes = self._reader.guid.bytes
        self.writer_gid: bytes = self._writer.guid.bytes
        self._lock = threading.Lock()
        self._pump.poke()

    def _writer_of(self, reader: Any, handle: int) -> bytes:
        key = (id(reader), handle)
        gid = self._writers.get(key)
        if gid is None:
            data = reader.get_matched_publication_data(handle)
            gid = data.key.bytes if data is not None else b""
            self._writers[key] = gid
        return gid

    def _drain(self) -> None:
        for reader, foreign in ((self._reader, False), (self._foreign, True)):
            while reader is not None and self._open and (batch := take_raw(reader)):
                for data, info in batch:
                    if not info.valid_data:
                        continue
                    gid = self._writer_of(reader, info.publication_handle)
                    if (gid[:2] != CYCLONE_VENDOR) != foreign:
                        continue  # the other reader's vendor: that reader reads it in its own form
                    try:
                        if foreign and self._on_foreign is not None:
                            count = self._counts[gid] = self._counts.get(gid, 0) + 1
                            self._on_foreign(data, gid, count)
                        elif not foreign:
                            self._on_data(data, gid)
                    except Exception:  # one bad callback must not stop the service
                        log.exception("service '%s' failed on a sample", self.name)

    def drop_reader(self) -> None:
        """Delete the reader of rmw_cyclonedds' form; the bare one, announced in its place, stays."""
        with self._lock:
            reader, self._reader = self._reader, None
            foreign = self._foreign
        if reader is not None and foreign is not None and self._open:
            destroy(reader)
            self._node.replace_reader(self.reader_gid, foreign.guid.bytes)
            self.reader_gid = foreign.guid.bytes

    def write(self, payload: bytes, bare: bool = False) -> None:
        """Write on the writer with rmw_cyclonedds' header, or (``bare``) on the bare-typed one."""
        with self._lock:
            writer = self._bare if bare else self._writer
            if writer is None:
                raise BusError(f"service endpoint of '{self.name}' is closed")
            write_raw(writer, payload, self.name, self._write_typename)

    def peers(self, cyclone: bool) -> tuple[set[bytes], set[bytes]]:
        """The participants (GUID prefixes) of Cyclone's, or the other vendors', matched endpoints.

        (Those our reader reads from, those our writer writes to), each in the form that vendor reads.
        """
        reader = self._reader if cyclone else self._foreign
        writer = self._writer if cyclone else self._bare
        found: tuple[set[bytes], set[bytes]] = (set(), set())
        for entity, into, handles, data_of in (
                (reader, found[0], "get_matched_publications", "get_matched_publication_data"),
                (writer, found[1], "get_matched_subscriptions", "get_matched_subscription_data")):
            if entity is None:
                continue
            for handle in getattr(entity, handles)():
                data = getattr(entity, data_of)(handle)
                if data is not None and (data.key.bytes[:2] == CYCLONE_VENDOR) == cyclone:
                    into.add(data.key.bytes[:12])
        return found

    def wait_for_reader_of(self, participant: bytes, timeout: float) -> bool:
        """Wait until our writer has matched a reader of that participant (GUID prefix); False at the deadline.

        A reliable, volatile reply reaches only the readers matched when it is written: a server
        can read a client's request before it has discovered that client's reply reader, as
        rmw_cyclonedds_cpp knows (it waits for the reader before it sends a response).
        """
        deadline = time.monotonic() + timeout
        while True:
            writer = self._writer
            if writer is None:
                return False
            for handle in writer.get_matched_subscriptions():
                data = writer.get_matched_subscription_data(handle)
                if data is not None and data.key.bytes[:12] == participant:
                    return True
            if time.monotonic() >= deadline:
                return False
            time.sleep(0.005)

    def close(self) -> None:
        with self._lock:
            if not self._open:
                return
            self._open = False
            reader, self._reader = self._reader, None
            foreign, self._foreign = self._foreign, None
            writer, self._writer = self._writer, None
            bare, self._bare = self._bare, None
        self._pump.close()
        for entity in (reader, foreign, bare, writer):
            if entity is not None:
                destroy(entity)
        self._node.forget_pair(self, self.reader_gid, self.writer_gid)  # type: ignore[arg-type]


class DdsService(Handle):
    """A service: reads ``rq/<name>Request``, answers on ``rr/<name>Reply`` with the request's header."""

    def __init__(self, node: DdsNode, name: str, stype: ServiceType, on_request: RequestCallback) -> None:
        self._on_request = on_request
        self._warned = False
        self.pair = _Pair(node, name, (request_topic_name(name), stype.request.typename),
                          (reply_topic_name(name), stype.response.typename), self._on_data, stype.type_hash,
                          self._on_foreign)
        self.reader_gid = self.pair.reader_gid
        self.writer_gid = self.pair.writer_gid

    def _on_data(self, data: bytes, writer: bytes) -> None:
        parts = split_header(data)
        if parts is None:
            return
        guid, seq, payload = parts
        answered = threading.Event()

        def respond(response: bytes) -> None:
            if not answered.is_set():
                answered.set()
                # The client's reply reader lives in the participant of its request writer.
                self.pair.wait_for_reader_of(writer[:12], _READER_WAIT_S)
                self.pair.write(add_header(response, guid, seq))

        self._on_request(payload, RequestId(guid.to_bytes(8, "little") + bytes(8), seq), respond)

    def _on_foreign(self, payload: bytes, writer: bytes, count: int) -> None:
        def respond(_response: bytes) -> None:
            if not self._warned:
                self._warned = True
                log.warning("service '%s' cannot answer a request from another DDS vendor's client "
                            "(writer %s): Cyclone DDS cannot send the request id rmw_fastrtps_cpp needs",
                            self.pair.name, writer.hex())

        self._on_request(payload, RequestId(writer, count), respond)

    def close(self) -> None:
        """Delete the service's reader and writer."""
        self.pair.close()


class DdsClient(ClientHandle):
    """A client: writes ``rq/<name>Request``, keeps the replies on ``rr/<name>Reply`` meant for it.

    A Cyclone DDS server's replies carry our id in rmw_cyclonedds' header. A server of another
    vendor (rmw_fastrtps_cpp) gets the bare request, and its bare replies, which name their
    request only in an inline QoS Cyclone does not show, are paired in order with our requests
    to that server's participant (see the module docstring).
    """

    def __init__(self, node: DdsNode, name: str, stype: ServiceType) -> None:
        self._pending: dict[int, ResponseCallback] = {}
        self._queued: deque[tuple[bytes, ResponseCallback]] = deque()
        self._lock = threading.Lock()
        self._seq = itertools.count(1)
        self._id = 0
        self.pair = _Pair(node, name, (reply_topic_name(name), stype.response.typename),
                          (request_topic_name(name), stype.request.typename), self._on_data, stype.type_hash,
                          self._on_foreign, foreign_reliable=False)
        self._id = _client_id(self.pair.writer_gid)
        self.writer_gid = self.pair.writer_gid

    @property
    def reader_gid(self) -> bytes:
        """The GUID of the reply reader the node announces (the bare one once a Fast DDS server is called)."""
        return self.pair.reader_gid

    @property
    def gid(self) -> bytes:
        """See :attr:`ClientHandle.gid` (its request writer's GUID)."""
        return self.writer_gid

    def _on_data(self, data: bytes, _writer: bytes) -> None:
        parts = split_header(data)
        if parts is None or parts[0] != self._id:
            return
        with self._lock:
            callback = self._pending.pop(parts[1], None)
        if callback is not None:
            callback(parts[2])

    def _on_foreign(self, payload: bytes, writer: bytes, _count: int) -> None:
        # Every client of the service reads every reply: the oldest request to that server's
        # participant is the one answered, as long as no other client calls it meanwhile.
        with self._lock:
            found = next((entry for entry in self._queued if entry[0] == writer[:12]), None)
            if found is not None:
                self._queued.remove(found)
        if found is not None:
            found[1](payload)

    def _cyclone_server(self) -> bool:
        """Whether a Cyclone DDS participant has both a request reader and a reply writer we matched."""
        writers, readers = self.pair.peers(cyclone=True)
        return bool(writers & readers)

    def _foreign_server(self) -> bytes | None:
        """A participant of another vendor whose request reader and reply writer we have both matched."""
        writers, readers = self.pair.peers(cyclone=False)
        both = sorted(writers & readers)
        return both[0] if both else None

    def request(self, payload: bytes, on_response: ResponseCallback) -> int:
        """See :meth:`ClientHandle.request`: in rmw_cyclonedds' form, or bare to another vendor's server."""
        seq = next(self._seq)
        server = None if self._cyclone_server() else self._foreign_server()
        entry = (server or b"", on_response)
        with self._lock:
            if server is None:
                self._pending[seq] = on_response
            else:
                self._queued.append(entry)
        try:
            if server is None:
                self.pair.write(add_header(payload, self._id, seq))
            else:
                # Cyclone holds a reliable reader's first sample of a non-Cyclone writer until
                # that writer's first heartbeat, and drops it when that heartbeat (which Fast DDS
                # sends just before the reply) already counts it: only best-effort readers left
                # on the server's reply writer take the reply as it comes.
                self.pair.drop_reader()
                self.pair.write(payload, bare=True)
        except BaseException:
            with self._lock:
                self._pending.pop(seq, None)
                if entry in self._queued:
                    self._queued.remove(entry)
            raise
        return seq

    def server_ready(self) -> bool:
        """See :meth:`ClientHandle.server_ready`: a server reads our requests and writes replies we read."""
        return self._cyclone_server() or self._foreign_server() is not None

    def close(self) -> None:
        """Delete the client's readers and writers; pending requests get no response."""
        with self._lock:
            self._pending.clear()
            self._queued.clear()
        self.pair.close()
