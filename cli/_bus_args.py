"""The options every graph tool shares (topic, node, param): where to meet the bus, how long to discover."""

from __future__ import annotations

import argparse

__all__ = ["SPIN_TIME", "add_bus_options"]

#: ros2cli's direct node spins this long (robotmodel.topic's default, not imported: --help stays light).
SPIN_TIME = 0.5


def add_bus_options(parser: argparse.ArgumentParser) -> None:
    """Add ``--connect`` and ``--spin-time``."""
    parser.add_argument("--connect", action="append", default=[], metavar="ENDPOINT",
                        help="zenoh endpoint to connect to instead of the local rendezvous (repeatable)")
    parser.add_argument("--spin-time", type=float, default=SPIN_TIME, metavar="S",
                        help=f"seconds to wait for discovery (default {SPIN_TIME})")
