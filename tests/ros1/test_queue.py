"""The publisher's per-subscriber queue: a slow subscriber loses the oldest messages, never the newest."""

from __future__ import annotations

import socket
import struct

from ros1helpers import wait_until

from robotmodel.ros1._header import read_frame, read_header, write_header
from robotmodel.ros1._msgs import message_type
from robotmodel.ros1._publisher import Publication, TcprosServer

SIZE = 1 << 20  # big enough that a few messages fill the socket buffers of a subscriber that does not read


def test_stalled_subscriber_keeps_the_newest_messages() -> None:
    msg_type = message_type("std_msgs/String")
    publication = Publication("/big", msg_type, "/rm", queue_size=3)
    server = TcprosServer(lambda topic: publication if topic == "/big" else None, host="127.0.0.1",
                          bind="127.0.0.1", callerid="/rm", topics=lambda: [["/big", msg_type.name]])
    try:
        with socket.create_connection(("127.0.0.1", server.port), timeout=30) as sock:
            write_header(sock, {"callerid": "/slow", "topic": "/big", "md5sum": msg_type.md5sum,
                                "type": msg_type.name})
            assert read_header(sock)["md5sum"] == msg_type.md5sum
            wait_until(lambda: publication.subscriber_count == 1, 10, "the connection")
            count = 40
            for i in range(count):
                publication.publish(struct.pack("<I", SIZE) + bytes([i]) * SIZE)
            received = []
            while not received or received[-1] != count - 1:
                frame = read_frame(sock)
                received.append(frame[4])
        assert received == sorted(received) and received[-1] == count - 1  # in order, the newest arrives
        assert len(received) < count  # and older ones were dropped rather than queued without bound
        assert publication.bus_stats()[0] == "/big"
        # The writer counts a message once its send returns, which can be just after the reader has it.
        wait_until(lambda: publication.bus_stats()[2][0][2] == len(received), 10,
                   f"getBusStats counting the {len(received)} messages sent")
    finally:
        publication.close()
        server.close()
