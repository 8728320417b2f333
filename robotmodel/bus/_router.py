"""A zenoh router in this process (eclipse-zenoh in router mode), as rmw_zenoh's ``rmw_zenohd``.

Below the seam: it is the zenoh wire's meeting point, nothing a node uses. It listens on
tcp/127.0.0.1:7447 by default (``ROBOTMODEL_ZENOH_PORT`` changes the port); ``listen`` and
``connect`` endpoints and ``ZENOH_ROUTER_CONFIG_URI`` / ``ZENOH_CONFIG_OVERRIDE`` apply as
rmw_zenohd reads them (see :func:`robotmodel.bus._config.router_config`).
"""

from __future__ import annotations

from collections.abc import Sequence

__all__ = ["run_router"]


def run_router(listen: Sequence[str] = (), connect: Sequence[str] = ()) -> int:
    """Run the router until SIGINT/SIGTERM; the exit code (0). BusError if it cannot start."""
    import zenoh

    from robotmodel.bus._config import router_config
    from robotmodel.errors import BusError
    from robotmodel.signals import stop_on_signals

    stop = stop_on_signals()
    config = router_config(list(listen), list(connect))
    try:
        session = zenoh.open(config)
    except zenoh.ZError as exc:
        raise BusError(f"cannot start the router: {exc}") from exc
    try:
        # rmw_zenohd's start line.
        print(f"Started Zenoh router with id {session.zid()}.", flush=True)
        stop.wait()
    finally:
        session.close()  # type: ignore[no-untyped-call]
    return 0
