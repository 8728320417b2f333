"""Quality of service: rclpy's profile fields, tf2_ros's presets, and rmw_dds_common's matching rules.

The wires map these profiles onto their own terms (zenoh: :mod:`._zenoh_names` writes them
into liveliness tokens; ROS 1: latching; DDS: its QoS policies).
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from enum import IntEnum

from robotmodel.errors import BusError

__all__ = [
    "DEFAULT_DEPTH",
    "DURATION_INFINITE_NS",
    "QOS_DEFAULT",
    "QOS_LATCHED",
    "QOS_TF",
    "QOS_TF_STATIC",
    "QOS_TF_STATIC_LISTENER",
    "Durability",
    "History",
    "Liveliness",
    "QoS",
    "Reliability",
    "incompatible_policy",
]

# rmw_zenoh's choice for a depth of 0 ("system default").
DEFAULT_DEPTH = 42
# rmw's RMW_DURATION_INFINITE: {sec: INT64_MAX / 1e9, nsec: INT64_MAX % 1e9}, i.e. INT64_MAX ns.
DURATION_INFINITE_NS = 2**63 - 1


class Reliability(IntEnum):
    """rmw_qos_reliability_policy_e values (the integers go on the wire)."""

    SYSTEM_DEFAULT = 0
    RELIABLE = 1
    BEST_EFFORT = 2
    # rmw_zenoh reads UNKNOWN from tokens but not BEST_AVAILABLE (4), so neither do we.
    UNKNOWN = 3


class Durability(IntEnum):
    """rmw_qos_durability_policy_e values."""

    SYSTEM_DEFAULT = 0
    TRANSIENT_LOCAL = 1
    VOLATILE = 2
    # As for Reliability: UNKNOWN is read from tokens, BEST_AVAILABLE (4) is not.
    UNKNOWN = 3


class History(IntEnum):
    """rmw_qos_history_policy_e values."""

    SYSTEM_DEFAULT = 0
    KEEP_LAST = 1
    KEEP_ALL = 2
    UNKNOWN = 3


class Liveliness(IntEnum):
    """rmw_qos_liveliness_policy_e values."""

    SYSTEM_DEFAULT = 0
    AUTOMATIC = 1
    # 2 is rmw's deprecated MANUAL_BY_NODE, which rmw_zenoh does not read.
    MANUAL_BY_TOPIC = 3
    UNKNOWN = 4
    BEST_AVAILABLE = 5


@dataclass(frozen=True, slots=True)
class QoS:
    """A QoS profile in rclpy's terms (``QoS(10)`` is keep-last 10, reliable, volatile).

    ``block`` is ours, not rmw's, and not in the token: when True a reliable publisher
    waits for the network instead of dropping (zenoh's congestion control BLOCK); when
    None, the default and what every preset uses, it follows rmw_zenoh (BLOCK only for
    reliable + keep-all).
    Durations are integer nanoseconds; ``DURATION_INFINITE_NS`` means none, and 0 is rclpy's
    unspecified ``Duration()``, which :meth:`resolved` makes infinite as rmw_zenoh does.
    """

    depth: int = 10
    reliability: Reliability = Reliability.RELIABLE
    durability: Durability = Durability.VOLATILE
    history: History = History.KEEP_LAST
    deadline_ns: int = DURATION_INFINITE_NS
    lifespan_ns: int = DURATION_INFINITE_NS
    liveliness: Liveliness = Liveliness.AUTOMATIC
    liveliness_lease_ns: int = DURATION_INFINITE_NS
    block: bool | None = None

    def __post_init__(self) -> None:
        if self.depth < 0:
            raise BusError(f"QoS depth must be >= 0, got {self.depth}")

    def resolved(self) -> QoS:
        """The profile rmw_zenoh actually uses: system defaults replaced, depth 0 made 42.

        rmw_zenoh's best_available_qos also turns an unspecified duration ({0 s, 0 ns}) into
        its default, infinite, so such a profile writes the same token text as the default.
        """
        return replace(
            self,
            depth=self.depth or DEFAULT_DEPTH,
            deadline_ns=self.deadline_ns or DURATION_INFINITE_NS,
            lifespan_ns=self.lifespan_ns or DURATION_INFINITE_NS,
            liveliness_lease_ns=self.liveliness_lease_ns or DURATION_INFINITE_NS,
            reliability=self.reliability or Reliability.RELIABLE,
            durability=self.durability or Durability.VOLATILE,
            history=self.history or History.KEEP_LAST,
            liveliness=self.liveliness or Liveliness.AUTOMATIC,
        )

    @property
    def transient_local(self) -> bool:
        """Whether late subscribers get the publisher's cached samples (latched)."""
        return self.durability == Durability.TRANSIENT_LOCAL

    @property
    def blocks(self) -> bool:
        """Whether a publisher with this profile uses congestion control BLOCK."""
        q = self.resolved()
        if q.reliability != Reliability.RELIABLE:
            return False
        if self.block is not None:
            return self.block
        return q.history == History.KEEP_ALL


# rclpy's common choice, QoS(10).
QOS_DEFAULT = QoS(10)
# tf2_ros DynamicBroadcasterQoS / DynamicListenerQoS: depth 100. Keep-last, so rmw_zenoh
# sends it with congestion control DROP; so do we.
QOS_TF = QoS(100)
# tf2_ros StaticBroadcasterQoS: depth 1, transient local.
QOS_TF_STATIC = QoS(1, durability=Durability.TRANSIENT_LOCAL)
# tf2_ros StaticListenerQoS: depth 100, transient local.
QOS_TF_STATIC_LISTENER = QoS(100, durability=Durability.TRANSIENT_LOCAL)
# robot_state_publisher's /robot_description: depth 1, transient local, reliable.
QOS_LATCHED = QoS(1, durability=Durability.TRANSIENT_LOCAL)



def incompatible_policy(publisher: QoS, subscription: QoS) -> str:
    """The policy that keeps a publisher and a subscription apart under rmw_dds_common's rules ('' if none).

    As ``qos_profile_check_compatible``'s errors (its warnings about unknown policies do
    not stop a match): a best-effort publisher and a reliable subscription (RELIABILITY), a
    volatile publisher and a transient-local subscription (DURABILITY), a subscription
    deadline the publisher does not keep (DEADLINE), automatic liveliness against manual by
    topic or a shorter subscription lease (LIVELINESS). Named as rclpy names the policy in
    its incompatible-QoS warning.
    """
    pub, sub = publisher.resolved(), subscription.resolved()
    if pub.reliability == Reliability.BEST_EFFORT and sub.reliability == Reliability.RELIABLE:
        return "RELIABILITY"
    if pub.durability == Durability.VOLATILE and sub.durability == Durability.TRANSIENT_LOCAL:
        return "DURABILITY"
    if sub.deadline_ns != DURATION_INFINITE_NS and not pub.deadline_ns <= sub.deadline_ns:
        return "DEADLINE"
    if pub.liveliness == Liveliness.AUTOMATIC and sub.liveliness == Liveliness.MANUAL_BY_TOPIC:
        return "LIVELINESS"
    if sub.liveliness_lease_ns != DURATION_INFINITE_NS and not pub.liveliness_lease_ns <= sub.liveliness_lease_ns:
        return "LIVELINESS"
    return ""
