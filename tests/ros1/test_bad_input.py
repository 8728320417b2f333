"""Bad input on the ROS 1 wire: one log line, that connection closed, nothing crashes, service goes on."""

from __future__ import annotations

import logging
import socket
import struct
import threading
from typing import Any

import pytest
from ros1helpers import Ros1World, wait_until

from robotmodel.ros1 import SlaveServer, encode_header, typestore, xmlrpc_call

GARBAGE = {
    "http": b"GET / HTTP/1.1\r\nHost: x\r\n\r\n",
    "no fields": struct.pack("<I", 0),
    "no equals sign": struct.pack("<II", 11, 7) + b"garbage",
    "no topic": encode_header({"callerid": "/x", "md5sum": "*"}),
}


def _closed_by_peer(sock: socket.socket) -> bool:
    sock.settimeout(30)
    try:
        while sock.recv(4096):  # an error header may come first
            pass
    except ConnectionResetError:
        pass
    return True


def test_garbage_to_robotmodels_publisher(ros1: Ros1World, caplog: pytest.LogCaptureFixture) -> None:
    caplog.set_level(logging.INFO, logger="robotmodel.ros1")
    node = ros1.node("rm_pub")
    pub = node.advertise("/chatter", "std_msgs/String", latch=True)
    pub.publish(typestore().types["std_msgs/msg/String"](data="still here"))
    _, _, (_, host, port) = xmlrpc_call(node.uri, "requestTopic", "/x", "/chatter", [["TCPROS"]])
    for kind, garbage in GARBAGE.items():
        with socket.create_connection((host, port), timeout=30) as sock:
            me = f"{host}:{sock.getsockname()[1]}"
            sock.sendall(garbage)
            assert _closed_by_peer(sock), kind
        lines = wait_until(lambda me=me: [r.getMessage() for r in caplog.records if me in r.getMessage()], 10,
                           f"the log line for {kind}")
        assert len(lines) == 1, (kind, lines)
    # the node still serves: a real subscriber gets the latched message
    assert 'data: "still here"' in ros1.tool("rostopic", "echo", "-n", "1", "/chatter")


class _FakePublisher:
    """A 'publisher' whose slave API is real but whose TCPROS port answers with garbage."""

    def __init__(self, reply: bytes) -> None:
        self.listener = socket.create_server(("127.0.0.1", 0))
        self.reply = reply
        port = self.listener.getsockname()[1]
        self.slave = SlaveServer({"requestTopic": lambda caller, topic, protocols: [1, "", ["TCPROS", "127.0.0.1",
                                                                                             port]]},
                                 host="127.0.0.1", bind="127.0.0.1")
        threading.Thread(target=self._serve, daemon=True).start()

    def _serve(self) -> None:
        while True:
            try:
                conn, _ = self.listener.accept()
            except OSError:
                return
            conn.recv(65536)
            conn.sendall(self.reply)
            conn.close()

    def close(self) -> None:
        self.listener.close()
        self.slave.close()


REPLIES = {"no fields": b"\x00\x00\x00\x00", "http": b"HTTP/1.0 400 Bad\r\n\r\n",
           "no type": encode_header({"callerid": "/fake", "md5sum": "*"})}


def test_garbage_from_publishers_to_robotmodels_subscriber(ros1: Ros1World,
                                                           caplog: pytest.LogCaptureFixture) -> None:
    caplog.set_level(logging.INFO, logger="robotmodel.ros1")
    fakes = {kind: _FakePublisher(reply) for kind, reply in REPLIES.items()}
    try:
        for fake in fakes.values():
            ros1.master.call("registerPublisher", "/chatter", "std_msgs/String", fake.slave.uri)
        got: list[str] = []
        ros1.node("rm_sub").subscribe("/chatter", "std_msgs/String", lambda m: got.append(m.data))

        def logged(uri: str) -> list[str]:
            return [r.getMessage() for r in caplog.records if uri in r.getMessage()]

        for kind, fake in fakes.items():
            wait_until(lambda uri=fake.slave.uri: logged(uri), 30, f"the log line for {kind}")
        talker = ros1.rospy("pub", "/chatter", "std_msgs/String", "--text", "real")
        talker.wait_line("^ready")  # its registration sends a publisherUpdate listing the fakes again
        wait_until(lambda: got, 30, "messages of the real publisher after the fake ones")
        for kind, fake in fakes.items():
            assert len(logged(fake.slave.uri)) == 1, (kind, logged(fake.slave.uri))
    finally:
        for fake in fakes.values():
            fake.close()


WRONG_CALLS: list[tuple[str, tuple[Any, ...]]] = [
    ("getPid", ()), ("publisherUpdate", ("/x", "/t", "notalist")), ("requestTopic", ("/x",)),
    ("noSuchMethod", ("/x",))]


def test_slave_api_with_wrong_arguments(ros1: Ros1World, caplog: pytest.LogCaptureFixture) -> None:
    caplog.set_level(logging.INFO, logger="robotmodel.ros1")
    node = ros1.node("rm_rpc")
    for method, args in WRONG_CALLS:
        code, status, _ = xmlrpc_call(node.uri, method, *args)
        assert code == -1 and status.startswith("ERROR:"), (method, status)
        if method != "publisherUpdate":  # a validation answer, as rospy's; the others are logged
            assert len([r for r in caplog.records if method in r.getMessage()]) == 1, method
    assert xmlrpc_call(node.uri, "getPid", "/x")[0] == 1
