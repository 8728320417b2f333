"""Zenoh session and router configurations: rmw_zenoh's settings, loopback-only by default.

Topology with nothing started by hand: sessions have multicast scouting off and gossip
on, and meet at a well-known loopback port (7447, where rmw_zenoh's router listens;
``ROBOTMODEL_ZENOH_PORT`` changes it) as peers of the router there: ``rmw_zenohd``, or
ours, which the first session to find the port free starts detached (see
:mod:`robotmodel.bus._router`). A router it must be: rmw_zenoh's sessions send their gossip
to routers only, so behind a peer they would never learn each other's endpoints, nor ours,
and a peer forwards nothing for others. Each session also listens on an ephemeral loopback
port so gossip links the peers directly; they reconnect (retry every 100 ms, backing off to
1 s) to whoever binds the port next.

Environment, as rmw_zenoh: ``ZENOH_SESSION_CONFIG_URI`` / ``ZENOH_ROUTER_CONFIG_URI`` name
a zenoh JSON5 config file used instead of these defaults, and ``ZENOH_CONFIG_OVERRIDE``
(``key=json5;key=json5``) patches the config in use. Timestamping is always switched on
(latched topics need it), and a file that names no listen endpoints listens on loopback.
"""

from __future__ import annotations

import json
import os
from collections.abc import Sequence
from typing import TYPE_CHECKING

from robotmodel.errors import BusError

if TYPE_CHECKING:
    import zenoh

__all__ = [
    "WELL_KNOWN_PORT",
    "rendezvous_endpoint",
    "rendezvous_port",
    "router_config",
    "session_config",
    "user_session_config",
]

WELL_KNOWN_PORT = 7447
LOOPBACK_ANY_PORT = "tcp/127.0.0.1:0"
# Retry quickly at first so start order does not matter (zenoh's default starts at 1 s).
_RETRY = "{period_init_ms: 100, period_max_ms: 1000, period_increase_factor: 2}"


def rendezvous_port() -> int:
    """The well-known loopback port: ``ROBOTMODEL_ZENOH_PORT`` or 7447."""
    text = os.environ.get("ROBOTMODEL_ZENOH_PORT", "").strip()
    if not text:
        return WELL_KNOWN_PORT
    if not text.isdigit() or not 0 < int(text) < 65536:
        raise BusError(f"ROBOTMODEL_ZENOH_PORT must be a port number, got '{text}'")
    return int(text)


def rendezvous_endpoint() -> str:
    """``tcp/127.0.0.1:<well-known port>``."""
    return f"tcp/127.0.0.1:{rendezvous_port()}"


def _check_endpoints(endpoints: Sequence[str]) -> list[str]:
    out = []
    for ep in endpoints:
        proto, sep, addr = ep.partition("/")
        if not sep or not proto or not addr:
            raise BusError(f"invalid zenoh endpoint '{ep}': expected e.g. tcp/192.168.1.10:7447")
        out.append(ep)
    return out


def _insert(config: zenoh.Config, key: str, value: str) -> None:
    import zenoh

    try:
        config.insert_json5(key, value)
    except zenoh.ZError as exc:
        raise BusError(f"zenoh config: cannot set {key}={value}: {exc}") from exc


def _common(config: zenoh.Config, mode: str) -> zenoh.Config:
    _insert(config, "mode", json.dumps(mode))
    _insert(config, "scouting/multicast/enabled", "false")
    _insert(config, "scouting/gossip/enabled", "true")
    # AdvancedPublisher caches (latched topics) need timestamps, as in rmw_zenoh's configs.
    _insert(config, "timestamping/enabled", "true")
    return config


def apply_override(config: zenoh.Config) -> zenoh.Config:
    """Apply ``ZENOH_CONFIG_OVERRIDE`` (``key=json5;...``) as rmw_zenoh does."""
    text = os.environ.get("ZENOH_CONFIG_OVERRIDE", "").strip()
    for item in filter(None, (part.strip() for part in text.split(";"))):
        key, sep, value = item.partition("=")
        if not sep:
            raise BusError(f"ZENOH_CONFIG_OVERRIDE: expected key=value, got '{item}'")
        _insert(config, key.strip(), value.strip())
    return config


def _loopback_unless_set(config: zenoh.Config, endpoint: str) -> None:
    # A file that names no listen endpoints would get zenoh's default, every interface;
    # like rmw_zenoh's own files, stay on loopback unless the file asks otherwise.
    if isinstance(json.loads(config.get_json("listen/endpoints")), dict):
        _insert(config, "listen/endpoints", json.dumps([endpoint]))


def _from_file(env: str) -> zenoh.Config | None:
    import zenoh

    path = os.environ.get(env, "").strip()
    if not path:
        return None
    try:
        config = zenoh.Config.from_file(path)
    except zenoh.ZError as exc:
        raise BusError(f"{env}: cannot load zenoh config '{path}': {exc}") from exc
    return config


def user_session_config(connect: Sequence[str] = ()) -> zenoh.Config | None:
    """The config named by ``ZENOH_SESSION_CONFIG_URI`` (with overrides), or None."""
    config = _from_file("ZENOH_SESSION_CONFIG_URI")
    if config is None:
        return None
    _insert(config, "timestamping/enabled", "true")
    _loopback_unless_set(config, LOOPBACK_ANY_PORT)
    if connect:
        _insert(config, "connect/endpoints", json.dumps(_check_endpoints(connect)))
    return apply_override(config)


def session_config(listen: Sequence[str], connect: Sequence[str]) -> zenoh.Config:
    """A peer session config with explicit endpoints (never zenoh's all-interfaces default)."""
    import zenoh

    config = _common(zenoh.Config(), "peer")
    _insert(config, "listen/endpoints", json.dumps(_check_endpoints(listen)))
    _insert(config, "connect/endpoints", json.dumps(_check_endpoints(connect)))
    _insert(config, "connect/retry", _RETRY)
    _insert(config, "queries_default_timeout", "60000")
    # zenoh's open() otherwise sometimes idles its whole 500 ms scouting delay although the
    # link is up; the caller waits for the link itself (see _zenoh.open_session).
    _insert(config, "scouting/delay", "0")
    return apply_override(config)


def router_config(listen: Sequence[str] = (), connect: Sequence[str] = ()) -> zenoh.Config:
    """A router config: ``ZENOH_ROUTER_CONFIG_URI`` if set, else loopback on the well-known port."""
    config = _from_file("ZENOH_ROUTER_CONFIG_URI")
    if config is None:
        import zenoh

        config = _common(zenoh.Config(), "router")
        _insert(config, "listen/endpoints", json.dumps(_check_endpoints(listen or [rendezvous_endpoint()])))
        # Routers pass on gossip so the peers behind them link up directly.
        _insert(config, "routing/router/peers_failover_brokering", "true")
        # rmw_zenohd's: open() would otherwise idle zenoh's default 500 ms scouting delay.
        _insert(config, "scouting/delay", "1")
    else:
        _insert(config, "timestamping/enabled", "true")
        _loopback_unless_set(config, rendezvous_endpoint())
        if listen:
            _insert(config, "listen/endpoints", json.dumps(_check_endpoints(listen)))
    if connect:
        _insert(config, "connect/endpoints", json.dumps(_check_endpoints(connect)))
        _insert(config, "connect/retry", _RETRY)
    return apply_override(config)
