"""Which address a ROS 1 node advertises in its URIs and which one its servers bind.

ROS 1 takes the host from ``__hostname:=`` / ``__ip:=``, then ROS_HOSTNAME, then ROS_IP
(rosgraph.network.get_address_override). Without any, rospy advertises the machine's host name
and binds every interface; robotmodel instead advertises and binds 127.0.0.1 when the master is
on this machine, and the address of the interface that reaches the master otherwise. It binds
0.0.0.0 only when asked (``bind_all``).
"""

from __future__ import annotations

import ipaddress
import os
import socket
import urllib.parse
from collections.abc import Mapping, Sequence
from dataclasses import dataclass

from robotmodel.errors import Ros1Error

__all__ = ["NodeAddress", "address_override", "is_local_host", "node_address"]


@dataclass(frozen=True)
class NodeAddress:
    """``host`` goes into the node's URIs; ``bind`` is the address its servers listen on."""

    host: str
    bind: str


def address_override(args: Sequence[str] = (), env: Mapping[str, str] | None = None) -> str | None:
    """The host a user asked for: ``__hostname:=``/``__ip:=`` in ``args``, ROS_HOSTNAME, ROS_IP, else None.

    Raises :class:`Ros1Error` with ROS's wording for a value holding a scheme or a port.
    """
    env = os.environ if env is None else env
    for arg in args:
        for prefix in ("__hostname:=", "__ip:="):
            if arg.startswith(prefix):
                return arg[len(prefix) :] or None
    for var in ("ROS_HOSTNAME", "ROS_IP"):
        value = env.get(var)
        if value is None:
            continue
        if not value:
            raise Ros1Error(f"invalid {var} (an empty string)")
        if "://" in value:
            raise Ros1Error(f"invalid {var} (protocol should not be included)")
        if _has_port(value):
            raise Ros1Error(f"invalid {var} (port should not be included)")
        return value
    return None


def _has_port(host: str) -> bool:
    try:
        ipaddress.ip_address(host)
    except ValueError:
        return ":" in host
    return False


def is_local_host(host: str) -> bool:
    """True when ``host`` names this machine's loopback (``localhost``, 127/8, ::1) or resolves there."""
    if host in ("localhost", "::1") or host.startswith("127."):
        return True
    try:
        addresses = {info[4][0] for info in socket.getaddrinfo(host, None, proto=socket.IPPROTO_TCP)}
    except OSError:
        return False
    return bool(addresses) and all(str(a).startswith("127.") or a == "::1" for a in addresses)


def _route_to(host: str, port: int) -> str:
    """The local address the kernel would use to reach ``host`` (no packet is sent)."""
    try:
        with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as probe:
            probe.connect((host, port))
            return str(probe.getsockname()[0])
    except OSError as exc:
        raise Ros1Error(f"cannot find a local address that reaches the master at {host}: {exc}") from None


def _bind_for(host: str) -> str:
    if host == "localhost" or host.startswith("127."):
        return "127.0.0.1" if host == "localhost" else host
    try:
        return str(ipaddress.ip_address(host))
    except ValueError:
        pass
    try:
        return str(socket.getaddrinfo(host, None, socket.AF_INET, proto=socket.IPPROTO_TCP)[0][4][0])
    except (OSError, IndexError):
        raise Ros1Error(f"cannot resolve the host name '{host}' (ROS_HOSTNAME) to an address to bind") from None


def node_address(master_uri: str, *, args: Sequence[str] = (), env: Mapping[str, str] | None = None,
                 bind_all: bool = False) -> NodeAddress:
    """Where a node reached through ``master_uri`` advertises itself and binds (see the module text)."""
    override = address_override(args, env)
    if override is not None:
        host = override
    else:
        parsed = urllib.parse.urlsplit(master_uri)
        master_host = parsed.hostname or "localhost"
        host = "127.0.0.1" if is_local_host(master_host) else _route_to(master_host, parsed.port or 11311)
    return NodeAddress(host=host, bind="0.0.0.0" if bind_all else _bind_for(host))
