"""The wires the conformance suite runs on, and a harness giving each case sessions and peers on one wire.

Every case takes the ``wire`` fixture and runs once per entry of :data:`WIRES`. A new wire
(ROS 1, DDS) adds itself there with what differs: whether it has processes (its peers
are then real child processes, killed with -9 in the killed-peer case), which QoS rules it
matches by (``"dds"``: rmw_dds_common's; ``"none"``: every pair matches, as rmw_zenoh and
ROS 1), whether parameters are node-local or a shared server, and whether a volatile
late joiner gets a latched sample (ROS 1 does), whether the graph knows endpoints' QoS and
how much history a latched publisher keeps. The ROS 1 wire's cases each get a private real
roscore (tests/ros1helpers), skipped with one line where Debian's ROS 1 is absent.
"""

from __future__ import annotations

import sys
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pytest

from robotmodel.bus import Context

HERE = Path(__file__).resolve().parent
PEER = HERE / "wire_peer.py"


@dataclass(frozen=True)
class WireSpec:
    """What the suite must know about a wire."""

    name: str
    processes: bool
    qos_rules: str  # "dds" or "none"
    parameters: str  # "node" (node-local) or "server" (ROS 1's parameter server)
    # ROS 1 latches for every subscriber: a volatile late joiner gets the latched sample there.
    volatile_gets_latched: bool
    # How long the graph may take to show a peer, or to lose a killed one.
    graph_deadline_s: float
    # ROS 1's master keeps a killed node's registrations (rosnode cleanup removes them); the
    # ROS 1 wire must say here whether it prunes nodes whose slave API no longer answers.
    killed_peer_leaves: bool = True
    # Whether the graph shows each endpoint's QoS (ROS 1's master knows none).
    endpoint_qos: bool = True
    # ROS 1 latches the last message only, whatever the depth.
    latches_last_only: bool = False
    # Topics every node of the wire has besides its own (ROS 1: /rosout).
    implicit_topics: tuple[str, ...] = ()
    # Whether the wire carries ROS 2 services (request/reply) through the seam.
    services: bool = True


WIRES = [
    WireSpec("inprocess", processes=False, qos_rules="dds", parameters="node", volatile_gets_latched=False,
             graph_deadline_s=1.0),
    WireSpec("zenoh", processes=True, qos_rules="none", parameters="node", volatile_gets_latched=False,
             graph_deadline_s=30.0),
    # A killed DDS peer leaves when its participant's lease (Cyclone's default: 10 s) runs out.
    WireSpec("dds", processes=True, qos_rules="dds", parameters="node", volatile_gets_latched=False,
             graph_deadline_s=30.0),
    WireSpec("ros1", processes=True, qos_rules="none", parameters="server", volatile_gets_latched=True,
             graph_deadline_s=30.0, killed_peer_leaves=False, endpoint_qos=False, latches_last_only=True,
             implicit_topics=("/rosout",), services=False),
]


class Peer:
    """A role played elsewhere: a child process on wires with processes, another session otherwise."""

    def __init__(self, wire: Wire, role: str, args: tuple[str, ...]) -> None:
        self._proc: Any = None
        self._ctx: Context | None = None
        self._keep: list[Any] = []
        if wire.spec.processes:
            self._proc = wire.procs.run([sys.executable, str(PEER), wire.spec.name, role, *args])
            self._proc.wait_line("ready", timeout=60.0)
        else:
            import bus.conformance.wire_peer as roles  # type: ignore[import-not-found]

            self._ctx = Context(backend=wire.spec.name, domain_id=wire.domain_id)
            self._keep = roles.ROLES[role](self._ctx, *args)

    def stop(self) -> None:
        """End the peer cleanly (its nodes withdraw)."""
        if self._proc is not None:
            assert self._proc.stop(20.0) == 0, self._proc.errors[-10:]
        if self._ctx is not None:
            self._ctx.close()

    def kill(self) -> None:
        """End the peer without a goodbye: SIGKILL for a process, closing its session in-process."""
        if self._proc is not None:
            self._proc.kill()
        if self._ctx is not None:
            self._ctx.close()


class Wire:
    """One test's view of one wire: sessions in this process and peers elsewhere, all closed at the end."""

    def __init__(self, spec: WireSpec, env: dict[str, str], procs: Any) -> None:
        self.spec = spec
        self.env = env
        self.procs = procs
        self.domain_id = int(env["ROS_DOMAIN_ID"])
        self._contexts: list[Context] = []
        self._peers: list[Peer] = []

    @property
    def name(self) -> str:
        """The wire's name."""
        return self.spec.name

    def context(self) -> Context:
        """A new session on the wire in this test's domain."""
        ctx = Context(backend=self.spec.name, domain_id=self.domain_id)
        self._contexts.append(ctx)
        return ctx

    def peer(self, role: str, *args: str) -> Peer:
        """Start ``role`` of wire_peer.py elsewhere and wait until it is ready."""
        peer = Peer(self, role, args)
        self._peers.append(peer)
        return peer

    def close(self) -> None:
        """Close every session and peer the test opened."""
        for peer in self._peers:
            peer.kill()
        for ctx in reversed(self._contexts):
            ctx.close()


@pytest.fixture(params=WIRES, ids=lambda spec: spec.name)
def wire(request: pytest.FixtureRequest, bus_env: dict[str, str], procs: Any, tmp_path: Path,
         monkeypatch: pytest.MonkeyPatch) -> Iterator[Wire]:
    """A wire of :data:`WIRES` with a private domain (zenoh: rendezvous port; ROS 1: roscore)."""
    world = None
    if request.param.name == "ros1":
        from ros1helpers import MISSING, Ros1World

        if MISSING:
            pytest.skip(MISSING)
        world = Ros1World(tmp_path / "ros_home")
        for key in ("ROS_MASTER_URI", "ROS_HOSTNAME", "ROS_HOME", "ROS_LOG_DIR"):
            bus_env[key] = world.env[key]
            monkeypatch.setenv(key, world.env[key])
        for key in ("ROS_IP", "ROS_NAMESPACE"):
            bus_env.pop(key, None)
            monkeypatch.delenv(key, raising=False)
    w = Wire(request.param, bus_env, procs)
    try:
        yield w
    finally:
        w.close()
        if world is not None:
            procs.reap()
            world.reap()

