"""A subscriber's request for the C heap back is carried out by the wire once it lets go of the sample.

A listener that has handled one huge /tf message asks for it (robotmodel._heap); the DDS wire
does it after the batch the sample came in, zenoh as its callback returns. Without the wire's
part the request would stay pending and the payload's memory would stay mapped.
"""

from __future__ import annotations

import threading
import time
from typing import Any

import pytest

from robotmodel import _heap
from robotmodel.bus import Context, Node, QoS
from robotmodel.msgs import String

DEADLINE_S = 30.0


@pytest.mark.parametrize("bus_wire", ["dds", "zenoh"])
def test_the_wire_carries_out_a_subscribers_request_after_the_sample(bus_env: dict[str, str],
                                                                      bus_wire: str) -> None:
    contexts = [Context(backend=bus_wire, domain_id=int(bus_env["ROS_DOMAIN_ID"])) for _ in range(2)]
    try:
        asked = threading.Event()
        pending_in_callback: list[bool] = []

        def on_raw(raw: Any) -> None:
            if not asked.is_set():
                _heap.release_after_sample()
                pending_in_callback.append(_heap._requested.is_set())
                asked.set()

        listener = Node("heap_listener", context=contexts[0])
        listener.create_subscription(String, "/heap_release", on_raw, QoS(10), raw=True)
        pub = Node("heap_talker", context=contexts[1]).create_publisher(String, "/heap_release", QoS(10))
        deadline = time.monotonic() + DEADLINE_S
        while not asked.is_set():
            assert time.monotonic() < deadline, "the sample never arrived"
            if pub.matched():
                pub.publish(String(data="x" * 100_000))
            asked.wait(0.1)
        while _heap._requested.is_set():
            assert time.monotonic() < deadline, f"the {bus_wire} wire never carried out the request"
            time.sleep(0.01)
        assert pending_in_callback == [True]  # pending while the callback held the sample
    finally:
        _heap._requested.clear()
        for ctx in contexts:
            ctx.close()
