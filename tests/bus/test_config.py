"""QoS text, type hashes and session configuration (rmw_zenoh's environment variables)."""

from __future__ import annotations

import json
import threading
from pathlib import Path
from typing import Any

import pytest

from robotmodel.bus import (
    QOS_TF,
    QOS_TF_STATIC,
    QOS_TF_STATIC_LISTENER,
    BusError,
    Durability,
    History,
    Node,
    QoS,
    Reliability,
    qos_from_keyexpr,
    qos_to_keyexpr,
    typestore,
)
from robotmodel.bus._codec import KNOWN_TYPE_HASHES
from robotmodel.bus._config import rendezvous_port, session_config
from robotmodel.msgs import String


@pytest.mark.parametrize(("qos", "text"), [
    # tf2_ros's broadcaster: keep-last 100, the rest rmw_zenoh's defaults.
    (QOS_TF, "::,100:,:,:,,"),
    # tf2_ros's static broadcaster: transient local (1), depth 1.
    (QOS_TF_STATIC, ":1:,1:,:,:,,"),
    (QOS_TF_STATIC_LISTENER, ":1:,100:,:,:,,"),
    # Depth 0 is "system default": rmw_zenoh makes it 42, its own default, so it is left empty.
    (QoS(0), "::,:,:,:,,"),
    (QoS(7, Reliability.BEST_EFFORT, Durability.VOLATILE, History.KEEP_ALL), "2::2,7:,:,:,,"),
    (QoS(10, deadline_ns=1_500_000_000, lifespan_ns=20), "::,10:1,500000000:0,20:,,"),
])
def test_qos_text(qos: QoS, text: str) -> None:
    assert qos_to_keyexpr(qos) == text
    back = qos_from_keyexpr(text)
    assert qos_to_keyexpr(back) == text
    assert back.depth == (qos.depth or 42)


@pytest.mark.parametrize("bad", ["", "::,:", "x::,:,:,:,,", "::,10:,:,:", "9::,:,:,:,,"])
def test_bad_qos_text_raises(bad: str) -> None:
    with pytest.raises(BusError):
        qos_from_keyexpr(bad)


def test_known_type_hashes_are_rosbags_hashes() -> None:
    store = typestore()
    for typename, digest in KNOWN_TYPE_HASHES.items():
        assert store.hash_rihs01(typename) == digest


def test_default_session_config_is_loopback_peer_with_timestamps() -> None:
    config = session_config(["tcp/127.0.0.1:0"], ["tcp/127.0.0.1:7447"])
    assert json.loads(config.get_json("mode")) == "peer"
    assert json.loads(config.get_json("listen/endpoints")) == ["tcp/127.0.0.1:0"]
    assert json.loads(config.get_json("scouting/multicast/enabled")) is False
    assert json.loads(config.get_json("timestamping/enabled")) is True
    with pytest.raises(BusError, match="endpoint"):
        session_config(["127.0.0.1:0"], [])


def test_bad_port_variable(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("ROBOTMODEL_ZENOH_PORT", "70000")
    with pytest.raises(BusError, match="ROBOTMODEL_ZENOH_PORT"):
        rendezvous_port()
    monkeypatch.delenv("ROBOTMODEL_ZENOH_PORT")
    assert rendezvous_port() == 7447


def _talk(sender: Node, receiver: Node) -> bool:
    got = threading.Event()
    receiver.create_subscription(String, "/cfg", lambda m: got.set(), 10)
    pub = sender.create_publisher(String, "/cfg", 10)
    assert pub.wait_for_subscriptions(1, 10)
    pub.publish(String("x"))
    return got.wait(10)


def test_session_config_uri_and_explicit_connect(tmp_path: Path, bus_env: dict[str, str],
                                                 monkeypatch: pytest.MonkeyPatch, new_port: Any) -> None:
    port = new_port()
    config = tmp_path / "session.json5"
    config.write_text(
        f"{{ mode: 'peer', listen: {{ endpoints: ['tcp/127.0.0.1:{port}'] }},"
        " scouting: { multicast: { enabled: false } } }")
    monkeypatch.setenv("ZENOH_SESSION_CONFIG_URI", str(config))
    with Node("from_file") as a:
        monkeypatch.delenv("ZENOH_SESSION_CONFIG_URI")
        with Node("connecting", connect=[f"tcp/127.0.0.1:{port}"]) as b:
            assert _talk(a, b)


def test_config_override(bus_env: dict[str, str], monkeypatch: pytest.MonkeyPatch, new_port: Any) -> None:
    port = new_port()
    monkeypatch.setenv("ZENOH_CONFIG_OVERRIDE", f'listen/endpoints=["tcp/127.0.0.1:{port}"]')
    with Node("overridden", connect=["tcp/127.0.0.1:1"]) as a:
        monkeypatch.delenv("ZENOH_CONFIG_OVERRIDE")
        with Node("connecting", connect=[f"tcp/127.0.0.1:{port}"]) as b:
            assert _talk(b, a)
    monkeypatch.setenv("ZENOH_CONFIG_OVERRIDE", "no equals sign")
    with pytest.raises(BusError, match="ZENOH_CONFIG_OVERRIDE"):
        Node("bad")


def test_a_config_file_without_listen_endpoints_stays_on_loopback(tmp_path: Path,
                                                                  monkeypatch: pytest.MonkeyPatch) -> None:
    from robotmodel.bus._config import router_config, user_session_config

    config = tmp_path / "bare.json5"
    config.write_text("{ mode: 'peer' }")
    monkeypatch.setenv("ZENOH_SESSION_CONFIG_URI", str(config))
    session = user_session_config()
    assert session is not None
    assert json.loads(session.get_json("listen/endpoints")) == ["tcp/127.0.0.1:0"]
    assert json.loads(session.get_json("timestamping/enabled")) is True
    monkeypatch.setenv("ZENOH_ROUTER_CONFIG_URI", str(config))
    monkeypatch.setenv("ROBOTMODEL_ZENOH_PORT", "17999")
    assert json.loads(router_config().get_json("listen/endpoints")) == ["tcp/127.0.0.1:17999"]
    config.write_text("{ mode: 'peer', listen: { endpoints: ['tcp/127.0.0.1:17998'] } }")
    session = user_session_config()
    assert session is not None
    assert json.loads(session.get_json("listen/endpoints")) == ["tcp/127.0.0.1:17998"]
