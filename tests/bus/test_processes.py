"""Real processes on 127.0.0.1: latching in both orders, no loss under load, the rendezvous topology."""

from __future__ import annotations

import ast
import json
import re
import time
from pathlib import Path
from typing import Any

import zenoh

from robotmodel.bus import QOS_TF, Attachment, Node, gid_of, topic_keyexpr
from robotmodel.bus._config import rendezvous_endpoint
from robotmodel.bus._router import router_claim
from robotmodel.msgs import TFMessage, make_transform

TF_HASH = "RIHS01_e369d0f05a23ae52508854b66f6aa0437f3449d652e8cbf22d5abe85d020f087"


def static_frames(lines: list[str]) -> set[str]:
    return {ln for ln in lines if ln.startswith("static ")}


def test_latched_reaches_a_subscriber_started_after_the_publisher(procs: Any) -> None:
    pub = procs.peer("static-pub")
    pub.wait_line("ready")
    sub = procs.peer("static-print")
    assert sub.wait_for(lambda ls: len(static_frames(ls)) == 2, 20), sub.lines
    assert static_frames(sub.lines) == {"static world base", "static base camera"}


def test_latched_reaches_a_subscriber_started_before_the_publisher(procs: Any) -> None:
    sub = procs.peer("static-print")
    sub.wait_line("ready")
    time.sleep(0.5)  # the subscriber really is first
    procs.peer("static-pub")
    assert sub.wait_for(lambda ls: len(static_frames(ls)) == 2, 20), sub.lines
    assert static_frames(sub.lines) == {"static world base", "static base camera"}


def test_four_publishers_ten_thousand_each_none_lost(procs: Any) -> None:
    listener = procs.peer("tf-count", "40000")
    listener.wait_line("ready")
    pubs = [procs.peer("tf-pub", str(i), "10000") for i in range(4)]
    for p in pubs:
        p.wait_line("done", timeout=120)
    got = listener.wait_line("got", timeout=60)
    count, per_child = got.split(" ", 2)[1:]
    assert int(count) == 40000, got
    assert ast.literal_eval(per_child) == {f"c{i}": 10000 for i in range(4)}


def tf_stamps(lines: list[str], child: str) -> list[int]:
    return [int(ln.split()[2]) for ln in lines if ln.startswith(f"tf {child} ")]


def test_others_keep_talking_when_the_first_process_exits(procs: Any) -> None:
    first = procs.peer("hold")  # binds the well-known port
    first.wait_line("ready")
    listener = procs.peer("tf-print")
    listener.wait_line("ready")
    ticker = procs.peer("tf-tick", "a")
    ticker.wait_line("ready")
    assert listener.wait_for(lambda ls: len(tf_stamps(ls, "a")) >= 10, 20)
    first.kill()
    seen = len(tf_stamps(listener.lines, "a"))
    # Still flowing, peer to peer, without the process that held the port.
    assert listener.wait_for(lambda ls: len(tf_stamps(ls, "a")) >= seen + 25, 20)
    # A newcomer binds the port again and the survivors reconnect to it.
    late = procs.peer("tf-tick", "late")
    late.wait_line("ready")
    assert listener.wait_for(lambda ls: len(tf_stamps(ls, "late")) >= 5, 20), listener.lines[-5:]


def test_a_publisher_killed_and_restarted_is_heard_again(procs: Any) -> None:
    listener = procs.peer("tf-print")
    listener.wait_line("ready")
    ticker = procs.peer("tf-tick", "robot")
    assert listener.wait_for(lambda ls: len(tf_stamps(ls, "robot")) >= 5, 20)
    ticker.kill()
    assert max(tf_stamps(listener.lines, "robot")) < 1_000_000
    again = procs.peer("tf-tick", "robot", "1000000")  # the new run's stamps tell it apart
    again.wait_line("ready")
    assert listener.wait_for(lambda ls: sum(s >= 1_000_000 for s in tf_stamps(ls, "robot")) >= 5, 20)
    assert listener.popen.poll() is None
    assert not [e for e in listener.errors if "Traceback" in e]


def test_garbage_on_the_tf_key_is_dropped_with_a_warning(procs: Any, bus_env: dict[str, str]) -> None:
    listener = procs.peer("tf-print")
    listener.wait_line("ready")
    domain = int(bus_env["ROS_DOMAIN_ID"])
    key = topic_keyexpr(domain, "/tf", "tf2_msgs/msg/TFMessage", TF_HASH)
    with Node("vandal") as node:
        pub = node.create_publisher(TFMessage, "/tf", QOS_TF)
        assert pub.wait_for_subscriptions(1, 20)
        end = time.monotonic() + 20
        while not pub.matched() and time.monotonic() < end:
            time.sleep(0.01)
        session = node.context.backend.session  # type: ignore[attr-defined]
        good_attachment = Attachment(1, time.time_ns(), gid_of("vandal")).encode()
        session.put(key, b"\x00\x01\x00\x00\xff\xff\xff\x7fnot a TFMessage", attachment=good_attachment)
        session.put(key, b"garbage without attachment")
        session.put(key, b"\x07\x07", attachment=good_attachment)
        pub.publish(TFMessage([make_transform("world", "after_garbage", stamp_ns=42)]))
        assert listener.wait_for(lambda ls: any(ln.startswith("tf after_garbage 42") for ln in ls), 20)
    assert listener.wait_for(lambda es: any("'/tf'" in e for e in es), 5, stream="stderr"), listener.errors
    warning = next(e for e in listener.errors if "'/tf'" in e)
    assert "dropped" in warning
    assert listener.popen.poll() is None


def _listening_sockets(pid: int) -> list[str]:
    """Local addresses (hex, as /proc/net/tcp writes them) of the process's listening TCP sockets."""
    inodes = set()
    for fd in Path(f"/proc/{pid}/fd").iterdir():
        try:
            target = fd.readlink().name
        except OSError:
            continue
        m = re.fullmatch(r"socket:\[(\d+)\]", str(target))
        if m:
            inodes.add(m.group(1))
    found = []
    for table in ("/proc/net/tcp", "/proc/net/tcp6"):
        for line in Path(table).read_text().splitlines()[1:]:
            cols = line.split()
            if cols[3] == "0A" and cols[9] in inodes:  # 0A: LISTEN
                found.append(cols[1])
    return found


def test_sessions_listen_on_loopback_only(procs: Any) -> None:
    first = procs.peer("hold")
    first.wait_line("ready")
    second = procs.peer("hold")
    second.wait_line("ready")
    for proc in (first, second):
        addresses = _listening_sockets(proc.popen.pid)
        assert addresses, "no listening socket found"
        assert all(a.startswith("0100007F:") for a in addresses), addresses  # 127.0.0.1 only
    port = int(rendezvous_endpoint().rsplit(":", 1)[1])
    assert f"0100007F:{port:04X}" not in _listening_sockets(first.popen.pid)
    assert f"0100007F:{port:04X}" not in _listening_sockets(second.popen.pid)
    # The rendezvous port is the router's that the first started detached: loopback only too.
    assert _listening_sockets(int(router_claim().read_text())) == [f"0100007F:{port:04X}"]


def test_router_command_serves_the_peers(procs: Any) -> None:
    router = procs.cli("router")
    line = router.wait_line("Started Zenoh router with id")
    assert re.fullmatch(r"Started Zenoh router with id [0-9a-f]+\.", line), line
    addresses = _listening_sockets(router.popen.pid)
    port = int(rendezvous_endpoint().rsplit(":", 1)[1])
    assert addresses == [f"0100007F:{port:04X}"]
    listener = procs.peer("tf-print")
    listener.wait_line("ready")
    ticker = procs.peer("tf-tick", "via_router")
    ticker.wait_line("ready")
    assert listener.wait_for(lambda ls: len(tf_stamps(ls, "via_router")) >= 5, 20)
    assert router.terminate() == 0


def test_a_plain_zenoh_client_of_the_router_sees_the_graph(procs: Any, bus_env: dict[str, str]) -> None:
    router = procs.cli("router")
    router.wait_line("Started Zenoh router")
    holder = procs.peer("static-pub")
    holder.wait_line("ready")
    config = zenoh.Config()
    config.insert_json5("mode", '"client"')
    config.insert_json5("connect/endpoints", json.dumps([rendezvous_endpoint()]))
    config.insert_json5("scouting/multicast/enabled", "false")
    session = zenoh.open(config)
    domain = bus_env["ROS_DOMAIN_ID"]
    tokens: list[str] = []
    end = time.monotonic() + 20
    try:
        # The peer's tokens reach the router a moment after it says ready: ask until they are in.
        while len(tokens) < 2 and time.monotonic() < end:
            tokens = [str(r.ok.key_expr) for r in session.liveliness().get(f"@ros2_lv/{domain}/**", timeout=5)
                      if r.ok is not None]
            time.sleep(0.05)
    finally:
        session.close()
    assert any("/MP/%/%/peer_static_pub/%tf_static/tf2_msgs::msg::dds_::TFMessage_/" in t for t in tokens), tokens
    assert any(t.endswith("/NN/%/%/peer_static_pub") for t in tokens), tokens


def test_two_routers_chained_as_in_the_two_machine_recipe(procs: Any, bus_env: dict[str, str],
                                                         new_port: Any) -> None:
    # Two "machines" on one host: each has its router on its own port; one router connects
    # to the other, and each machine's tools meet their local router.
    robot_port = bus_env["ROBOTMODEL_ZENOH_PORT"]
    laptop_port = str(new_port())
    robot_router = procs.cli("router")
    robot_router.wait_line("Started Zenoh router")
    laptop_env = dict(bus_env, ROBOTMODEL_ZENOH_PORT=laptop_port)
    laptop_router = procs.run([*procs.cli_args("router", "--connect", f"tcp/127.0.0.1:{robot_port}")], env=laptop_env)
    laptop_router.wait_line("Started Zenoh router")
    procs.peer("static-pub").wait_line("ready")
    laptop_listener = procs.run(procs.peer_args("static-print"), env=laptop_env)
    assert laptop_listener.wait_for(lambda ls: len(static_frames(ls)) == 2, 20), laptop_listener.lines


def test_router_config_uri(procs: Any, bus_env: dict[str, str], new_port: Any, tmp_path: Path) -> None:
    port = new_port()
    config = tmp_path / "router.json5"
    config.write_text(f"{{ mode: 'router', listen: {{ endpoints: ['tcp/127.0.0.1:{port}'] }},"
                      " scouting: { multicast: { enabled: false } } }")
    env = dict(bus_env, ZENOH_ROUTER_CONFIG_URI=str(config), ROBOTMODEL_ZENOH_PORT=str(port))
    router = procs.run(procs.cli_args("router"), env=env)
    router.wait_line("Started Zenoh router")
    assert _listening_sockets(router.popen.pid) == [f"0100007F:{port:04X}"]
    peers_env = dict(bus_env, ROBOTMODEL_ZENOH_PORT=str(port))
    procs.run(procs.peer_args("static-pub"), env=peers_env).wait_line("ready")
    listener = procs.run(procs.peer_args("static-print"), env=peers_env)
    assert listener.wait_for(lambda ls: len(static_frames(ls)) == 2, 20), listener.lines
    assert router.terminate() == 0


def test_ros_domain_id_separates_processes(procs: Any, bus_env: dict[str, str]) -> None:
    other = dict(bus_env, ROS_DOMAIN_ID=str(int(bus_env["ROS_DOMAIN_ID"]) + 1))
    stranger = procs.run(procs.peer_args("static-print"), env=other)
    stranger.wait_line("ready")
    procs.peer("static-pub").wait_line("ready")
    neighbour = procs.peer("static-print")  # same domain as the publisher: the control
    assert neighbour.wait_for(lambda ls: len(static_frames(ls)) == 2, 20)
    # The stranger shares the port and the links, but not the domain's keys.
    assert not stranger.wait_for(lambda ls: bool(static_frames(ls)), 1.0), stranger.lines
