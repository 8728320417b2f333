"""``robotmodel router``: a zenoh router (eclipse-zenoh in router mode), as ``ros2 run rmw_zenoh_cpp rmw_zenohd``.

It listens on tcp/127.0.0.1:7447 (``ROBOTMODEL_ZENOH_PORT`` changes the port); give
``--listen tcp/0.0.0.0:7447`` to serve other machines and ``--connect tcp/HOST:7447`` to
join another machine's router. ``ZENOH_ROUTER_CONFIG_URI`` names a zenoh config file to use
instead, and ``ZENOH_CONFIG_OVERRIDE`` patches it, as rmw_zenohd reads them. A zenoh-wire
tool that finds no router starts this one detached; ``--stop`` ends it (as ``ros2 daemon stop``).
"""

from __future__ import annotations

import argparse
from typing import Any

__all__ = ["register", "run"]


def register(sub: Any) -> None:
    """Add the ``router`` subcommand."""
    parser: argparse.ArgumentParser = sub.add_parser(
        "router", aliases=["rmw_zenohd"],
        help="run a zenoh router for processes and machines to meet (as rmw_zenohd)",
        description="Run a zenoh router until Ctrl-C or SIGTERM. By default it listens on "
        "tcp/127.0.0.1:7447 only; --listen tcp/0.0.0.0:7447 serves other machines.",
    )
    parser.add_argument("--listen", action="append", default=[], metavar="ENDPOINT",
                        help="zenoh endpoint to listen on (repeatable; default tcp/127.0.0.1:7447)")
    parser.add_argument("--connect", action="append", default=[], metavar="ENDPOINT",
                        help="another router to connect to, e.g. tcp/192.168.1.10:7447 (repeatable)")
    parser.add_argument("--stop", action="store_true",
                        help="stop the router of ours on this port (the one a tool started in the background)")
    parser.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    """Run the router until a signal, or stop the one running."""
    from robotmodel.bus import run_router, stop_router

    if args.stop:
        # ros2 daemon stop's words and exit code.
        print("The router has been stopped" if stop_router() else "The router is not running", flush=True)
        return 0
    return run_router(args.listen, args.connect)
