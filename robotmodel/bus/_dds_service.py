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
A client here cannot call a Fast DDS service.

Only the DDS wire uses this module (it is below the backend seam).
"""

from __future__ import annotations

import itertools
import logging
import struct
import threading
import time
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from cyclonedds.pub import DataWriter
from cyclonedds.sub import DataReader

from robotmodel.bus._backend import ClientHandle, Handle, RequestCallback, RequestId, ResponseCallback, ServiceType
from robotmodel.bus._dds_qos import qos_to_dds
from robotmodel.bus._dds_raw import Pump, destroy, take_raw, write_raw
from robotmodel.bus._dds_types import reply_topic_name, request_topic_name
from robotmodel.bus._qos import QoS
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


#: The vendor id Cyclone DDS puts at the start of its GUIDs (RTPS 2.5, 9.3.1.5: Eclipse 01.10).
CYCLONE_VENDOR = b"\x01\x10"
ForeignCallback = Callable[[bytes, bytes, int], None]


class _Pair:
    """A reader on one of a service's topics and a writer on the other, with a pump for the reader.

    With ``on_foreign``, a second reader of the bare type takes other vendors' samples
    (``on_foreign(payload, writer GUID, its count)``); each reader keeps only its vendors'.
    """

    def __init__(self, node: DdsNode, name: str, read: tuple[str, str], write: tuple[str, str],
                 on_data: Callable[[bytes, bytes], None], type_hash: str,
                 on_foreign: ForeignCallback | None = None) -> None:
        backend = node.backend
        self._node = node
        self.name = name
        self._on_data = on_data
        self._on_foreign = on_foreign
        self._write_typename = write[1]
        self._reader: Any = None
        self._foreign: Any = None
        self._writers: dict[tuple[int, int], bytes] = {}
        self._counts: dict[bytes, int] = {}
        self._pump = Pump(f"dds-srv {name}", self._drain)
        self._listener = self._pump.listener()
        qos = qos_to_dds(SERVICES_QOS, type_hash)
        self._writer: Any = DataWriter(backend.participant, backend.dds_topic(write[0], write[1], True), qos)
        self._idle: Any = None
        self._reader = DataReader(backend.participant, backend.dds_topic(read[0], read[1], True), qos,
                                  listener=self._listener)
        if on_foreign is not None:
            self._foreign = DataReader(backend.participant, backend.dds_topic(read[0], read[1]), qos,
                                       listener=self._listener)
            # rmw_fastrtps_cpp finds a server available only when the request readers and reply
            # writers it discovers are as many: a bare-typed writer that never writes evens them.
            self._idle = DataWriter(backend.participant, backend.dds_topic(write[0], write[1]), qos)
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
            while reader is not None and self._reader is not None and (batch := take_raw(reader)):
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

    def write(self, payload: bytes) -> None:
        with self._lock:
            writer = self._writer
            if writer is None:
                raise BusError(f"service endpoint of '{self.name}' is closed")
            write_raw(writer, payload, self.name, self._write_typename)

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

    def matched(self) -> bool:
        reader, writer = self._reader, self._writer
        return (reader is not None and writer is not None
                and writer.get_publication_matched_status().current_count > 0
                and reader.get_subscription_matched_status().current_count > 0)

    def close(self) -> None:
        reader, self._reader = self._reader, None
        foreign, self._foreign = self._foreign, None
        idle, self._idle = self._idle, None
        with self._lock:
            writer, self._writer = self._writer, None
        if reader is None:
            return
        self._pump.close()
        destroy(reader)
        for extra in (foreign, idle):
            if extra is not None:
                destroy(extra)
        if writer is not None:
            destroy(writer)
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
    """A client: writes ``rq/<name>Request``, keeps the replies on ``rr/<name>Reply`` carrying its id."""

    def __init__(self, node: DdsNode, name: str, stype: ServiceType) -> None:
        self._pending: dict[int, ResponseCallback] = {}
        self._lock = threading.Lock()
        self._seq = itertools.count(1)
        self._id = 0
        self.pair = _Pair(node, name, (reply_topic_name(name), stype.response.typename),
                          (request_topic_name(name), stype.request.typename), self._on_data, stype.type_hash)
        self._id = _client_id(self.pair.writer_gid)
        self.reader_gid = self.pair.reader_gid
        self.writer_gid = self.pair.writer_gid

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

    def request(self, payload: bytes, on_response: ResponseCallback) -> int:
        """See :meth:`ClientHandle.request`."""
        seq = next(self._seq)
        with self._lock:
            self._pending[seq] = on_response
        try:
            self.pair.write(add_header(payload, self._id, seq))
        except BaseException:
            with self._lock:
                self._pending.pop(seq, None)
            raise
        return seq

    def server_ready(self) -> bool:
        """See :meth:`ClientHandle.server_ready`: a server reads our requests and writes replies we read."""
        return self.pair.matched()

    def close(self) -> None:
        """Delete the client's reader and writer; pending requests get no response."""
        with self._lock:
            self._pending.clear()
        self.pair.close()
