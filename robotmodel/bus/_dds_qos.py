"""ROS 2 QoS as DDS QoS, and back; DDS policy ids as rmw names them; Cyclone's discovery configuration.

The mapping is rmw_cyclonedds_cpp's: reliability, durability, history and depth one to one
(reliable writers block without limit, as there), deadline, lifespan and liveliness with
their lease where not infinite, and Jazzy's ``typehash=RIHS01_...;`` in USER_DATA.

Discovery follows REP 2016 as rmw_cyclonedds_cpp turns it into Cyclone's configuration:
``ROS_AUTOMATIC_DISCOVERY_RANGE`` LOCALHOST (robotmodel's default) keeps Cyclone on the
loopback interface without multicast and finds the others by unicast to the well-known
ports of participant indices on localhost; SUBNET uses Cyclone's defaults (multicast on
the machine's interface); OFF finds no one; ``ROS_STATIC_PEERS`` (``;``-separated hosts)
are added as unicast peers. As rcl (Jazzy) reads them, the deprecated
``ROS_LOCALHOST_ONLY=1`` means LOCALHOST with the range and static peers ignored, and OFF
ignores static peers, each with rcl's warning. With LOCALHOST a static peer beyond loopback frees
Cyclone from the loopback interface (as in rmw_cyclonedds_cpp, which never restricts it),
multicast staying off.

Only the DDS wire uses this module (it is below the backend seam).
"""

from __future__ import annotations

import logging
import os
import re
import socket
from collections.abc import Mapping, Sequence
from typing import Any
from xml.sax.saxutils import quoteattr

from cyclonedds.core import Policy, Qos

from robotmodel.bus._qos import DURATION_INFINITE_NS, Durability, History, Liveliness, QoS, Reliability
from robotmodel.errors import BusError

log = logging.getLogger("robotmodel.bus")

__all__ = [
    "POLICY_NAMES",
    "check_peers",
    "cyclone_config",
    "discovery_range",
    "qos_from_dds",
    "qos_to_dds",
    "type_hash_of",
]

#: DDS QoS policy ids (DDS 1.4, Table 2.4's ids as Cyclone numbers them) -> rmw's policy names.
POLICY_NAMES: dict[int, str] = {
    2: "DURABILITY",
    4: "DEADLINE",
    8: "LIVELINESS",
    11: "RELIABILITY",
    13: "HISTORY",
    21: "LIFESPAN",
}
# Cyclone's infinite duration (DDS_INFINITY).
_INFINITY = 2**63 - 1
# rmw_cyclonedds_cpp's MaxAutoParticipantIndex for a localhost or static-peer domain.
_MAX_PARTICIPANT_INDEX = 32
_RANGES = ("OFF", "LOCALHOST", "SUBNET", "SYSTEM_DEFAULT")
_LOOPBACK_PEERS = ("localhost", "127.0.0.1", "::1")


def qos_to_dds(qos: QoS, type_hash: str = "") -> Qos:
    """The DDS QoS of a ROS endpoint (as rmw_cyclonedds_cpp sets it)."""
    q = qos.resolved()
    policies: list[Any] = [
        Policy.Reliability.Reliable(max_blocking_time=_INFINITY) if q.reliability == Reliability.RELIABLE
        else Policy.Reliability.BestEffort,
        Policy.Durability.TransientLocal if q.durability == Durability.TRANSIENT_LOCAL
        else Policy.Durability.Volatile,
        Policy.History.KeepAll if q.history == History.KEEP_ALL else Policy.History.KeepLast(q.depth),
    ]
    if q.durability == Durability.TRANSIENT_LOCAL:
        # Cyclone keeps for late joiners what DURABILITY_SERVICE's history says (default: the
        # last 1), so it is set to the endpoint's history, which is what ROS means.
        policies.append(Policy.DurabilityService(0, policies[2], -1, -1, -1))
    if q.deadline_ns != DURATION_INFINITE_NS:
        policies.append(Policy.Deadline(q.deadline_ns))
    if q.lifespan_ns != DURATION_INFINITE_NS:
        policies.append(Policy.Lifespan(q.lifespan_ns))
    lease = q.liveliness_lease_ns if q.liveliness_lease_ns != DURATION_INFINITE_NS else _INFINITY
    if q.liveliness == Liveliness.MANUAL_BY_TOPIC:
        policies.append(Policy.Liveliness.ManualByTopic(lease))
    elif lease != _INFINITY:
        policies.append(Policy.Liveliness.Automatic(lease))
    if type_hash:
        policies.append(Policy.Userdata(f"typehash={type_hash};".encode()))
    return Qos(*policies)


def _ns(value: int) -> int:
    return DURATION_INFINITE_NS if value >= _INFINITY else int(value)


def qos_from_dds(qos: Qos) -> QoS:
    """The ROS QoS of a discovered endpoint (what rmw reports for it)."""
    rel = qos[Policy.Reliability]
    dur = qos[Policy.Durability]
    hist = qos[Policy.History]
    deadline = qos[Policy.Deadline]
    lifespan = qos[Policy.Lifespan]
    live = qos[Policy.Liveliness]
    keep_all = hist is not None and hist == Policy.History.KeepAll
    depth = 0 if hist is None or keep_all else int(getattr(hist, "depth", 0))
    return QoS(
        depth=depth,
        reliability=Reliability.BEST_EFFORT if rel == Policy.Reliability.BestEffort else Reliability.RELIABLE,
        durability=Durability.TRANSIENT_LOCAL if dur == Policy.Durability.TransientLocal else Durability.VOLATILE,
        history=History.KEEP_ALL if keep_all else History.KEEP_LAST,
        deadline_ns=_ns(getattr(deadline, "deadline", _INFINITY)),
        lifespan_ns=_ns(getattr(lifespan, "lifespan", _INFINITY)),
        liveliness=Liveliness.MANUAL_BY_TOPIC if isinstance(live, Policy.Liveliness.ManualByTopic)
        else Liveliness.AUTOMATIC,
        liveliness_lease_ns=_ns(getattr(live, "lease_duration", _INFINITY)),
    )


_TYPE_HASH = re.compile(rb"typehash=([^;]*);")


def type_hash_of(qos: Qos) -> str:
    """The RIHS01 hash a Jazzy endpoint announces in its USER_DATA ('' when none)."""
    user = qos[Policy.Userdata]
    data = getattr(user, "data", b"") or b""
    found = _TYPE_HASH.search(bytes(data))
    return found.group(1).decode(errors="replace") if found else ""


def discovery_range(env: Mapping[str, str] | None = None) -> str:
    """ROS_AUTOMATIC_DISCOVERY_RANGE as robotmodel reads it (LOCALHOST unless widened); raises BusError."""
    env = os.environ if env is None else env
    text = env.get("ROS_AUTOMATIC_DISCOVERY_RANGE", "").strip().upper()
    if not text:
        return "LOCALHOST"
    if text not in _RANGES:
        raise BusError(f"ROS_AUTOMATIC_DISCOVERY_RANGE is '{env['ROS_AUTOMATIC_DISCOVERY_RANGE']}' "
                       f"(expected one of {', '.join(_RANGES)})")
    return text


def static_peers(env: Mapping[str, str] | None = None) -> list[str]:
    """ROS_STATIC_PEERS: hosts separated by ';' (REP 2016)."""
    env = os.environ if env is None else env
    text = env.get("ROS_STATIC_PEERS", "")
    return [p.strip() for p in text.split(";") if p.strip()]


def _peer_host(peer: str) -> str:
    # Cyclone's peer forms: a host name or IPv4 address with an optional ':port' (an IPv6
    # address, bracketed before a port, is taken apart too, to be refused by name).
    if peer.startswith("["):
        return peer[1:].split("]", 1)[0]
    host, sep, port = peer.rpartition(":")
    return host if sep and host.count(":") == 0 and port.isdigit() else peer


def check_peers(connect: Sequence[str] = (), env: Mapping[str, str] | None = None) -> None:
    """Raise BusError naming the first peer (``connect``, then ROS_STATIC_PEERS) that is not a host here.

    Cyclone aborts the whole process on a peer address it cannot resolve, so each is resolved
    first; a zenoh endpoint (``tcp/HOST:PORT``) given on the DDS wire is named as one.
    """
    origins = [(p, "connect") for p in connect] + [(p, "ROS_STATIC_PEERS") for p in static_peers(env)]
    for peer, origin in origins:
        where = f"DDS peer '{peer}' (from {origin})"
        if "/" in peer:
            raise BusError(f"{where} is not a host: the DDS wire takes host names or addresses, as "
                           "ROS_STATIC_PEERS does (a zenoh endpoint needs RMW_IMPLEMENTATION=rmw_zenoh_cpp)")
        host = _peer_host(peer.strip())
        try:
            if not host or any(c.isspace() for c in host):
                raise OSError("not a host name")
            # Cyclone runs on UDP over IPv4 here: an IPv6-only peer would abort it too.
            socket.getaddrinfo(host, None, socket.AF_INET)
        except (OSError, UnicodeError) as exc:
            raise BusError(f"{where} is not a host name or IPv4 address this machine can resolve ({exc})") from None


def cyclone_config(connect: Sequence[str] = (), env: Mapping[str, str] | None = None) -> str:
    """Cyclone's configuration XML for a domain, from the discovery range, static peers and ``connect``."""
    env = os.environ if env is None else env
    rng = discovery_range(env)
    statics = static_peers(env)
    if env.get("ROS_LOCALHOST_ONLY", "").strip() == "1":
        # rcl (Jazzy): honoured, warned about, and the range and static peers are ignored.
        log.warning("ROS_LOCALHOST_ONLY is deprecated but still honored if it is enabled. "
                    "Use ROS_AUTOMATIC_DISCOVERY_RANGE and ROS_STATIC_PEERS instead.")
        rng, statics = "LOCALHOST", []
    elif rng == "OFF" and statics:
        log.warning("Note: ROS_AUTOMATIC_DISCOVERY_RANGE is set to OFF, but found static peers in "
                    "ROS_STATIC_PEERS. ROS_STATIC_PEERS will be ignored.")
        statics = []
    peers = [*statics, *connect]
    general = discovery = ""
    if rng in ("LOCALHOST", "OFF"):
        general = "<AllowMulticast>false</AllowMulticast>"
        # Loopback only unless a peer beyond it was named: then Cyclone's own interface, as
        # rmw_cyclonedds_cpp leaves it, or that peer could never be reached.
        if rng == "OFF" or not [p for p in peers if p not in _LOOPBACK_PEERS]:
            general = '<Interfaces><NetworkInterface address="127.0.0.1" multicast="false"/></Interfaces>' + general
        if rng == "LOCALHOST":
            peers = ["localhost", *peers]
    if peers or rng in ("LOCALHOST", "OFF"):
        discovery = (f"<ParticipantIndex>auto</ParticipantIndex>"
                     f"<MaxAutoParticipantIndex>{_MAX_PARTICIPANT_INDEX}</MaxAutoParticipantIndex>")
        if peers:
            discovery += "<Peers>" + "".join(f"<Peer address={quoteattr(p)}/>" for p in peers) + "</Peers>"
    return ('<CycloneDDS><Domain Id="any">'
            f"<General>{general}</General><Discovery>{discovery}</Discovery>"
            "</Domain></CycloneDDS>")
