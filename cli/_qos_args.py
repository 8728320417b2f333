"""ros2cli's ``--qos-*`` options (``ros2topic.api.add_qos_arguments``).

:func:`robotmodel.topic.qos_from_short_keys` reads them.
"""

from __future__ import annotations

import argparse
from typing import Any

__all__ = ["add_qos_arguments", "qos_of"]

# rclpy's short keys (robotmodel.topic's, spelled out here so --help stays light).
_PROFILES = ("unknown", "default", "system_default", "sensor_data", "services_default", "parameters",
             "parameter_events", "action_status_default", "best_available")
_HISTORY = ("system_default", "keep_last", "keep_all", "unknown")
_RELIABILITY = ("system_default", "reliable", "best_effort", "unknown", "best_available")
_DURABILITY = ("system_default", "transient_local", "volatile", "unknown", "best_available")
_LIVELINESS = ("system_default", "automatic", "manual_by_topic", "unknown", "best_available")


def add_qos_arguments(parser: argparse.ArgumentParser, verb: str, default: str) -> None:
    """Add ``--qos-profile``, ``--qos-depth``, ``--qos-history``, ``--qos-reliability``, ``--qos-durability``, ...."""
    parser.add_argument("--qos-profile", choices=_PROFILES, default=default,
                        help=f"Quality of service preset profile to {verb} with (default: {default})")
    parser.add_argument("--qos-depth", metavar="N", type=int,
                        help=f"Queue size setting to {verb} with (overrides depth value of --qos-profile option)")
    parser.add_argument("--qos-history", choices=_HISTORY,
                        help=f"History of samples setting to {verb} with (overrides history value of --qos-profile "
                             "option, default: keep_last)")
    for name, keys in (("reliability", _RELIABILITY), ("durability", _DURABILITY)):
        parser.add_argument(f"--qos-{name}", choices=keys,
                            help=f"Quality of service {name} setting to {verb} with (overrides {name} value of "
                                 "--qos-profile option, default: Compatible profile with running endpoints )")
    parser.add_argument("--qos-liveliness", choices=_LIVELINESS,
                        help=f"Quality of service liveliness setting to {verb} with (overrides liveliness value of "
                             "--qos-profile option")
    parser.add_argument("--qos-liveliness-lease-duration-seconds", type=float,
                        help=f"Quality of service liveliness lease duration setting to {verb} with (overrides "
                             "liveliness lease duration value of --qos-profile option")


def qos_of(args: argparse.Namespace) -> Any:
    """The QoS the parsed ``--qos-*`` options name."""
    from robotmodel.topic import qos_from_short_keys

    return qos_from_short_keys(args.qos_profile, reliability=args.qos_reliability, durability=args.qos_durability,
                               depth=args.qos_depth, history=args.qos_history, liveliness=args.qos_liveliness,
                               liveliness_lease_duration_s=args.qos_liveliness_lease_duration_seconds)
