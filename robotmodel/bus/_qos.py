"""Quality of service: rclpy's profile fields, tf2_ros's presets, and rmw_zenoh's compact token text.

rmw_zenoh writes an entity's QoS into its liveliness token as
``rel:dur:hist,depth:dl_s,dl_ns:ls_s,ls_ns:liv,lease_s,lease_ns``, leaving every field that
equals its own default (RELIABLE, VOLATILE, KEEP_LAST, depth 42, infinite durations,
AUTOMATIC liveliness) empty; enum fields are written as rmw's integer values.
Reading it back accepts, per policy, exactly the integers rmw_zenoh's own tables hold
(so a token rmw_zenoh ignores is ignored here too).
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
    "qos_from_keyexpr",
    "qos_to_keyexpr",
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

_BASE = QoS(DEFAULT_DEPTH, Reliability.RELIABLE, Durability.VOLATILE, History.KEEP_LAST)
_NS = 1_000_000_000


def _sec_nsec(ns: int) -> tuple[int, int]:
    # rmw_time_t splits a duration in whole seconds and the nanosecond rest.
    return divmod(ns, _NS)


def qos_to_keyexpr(qos: QoS) -> str:
    """rmw_zenoh's compact QoS text for a liveliness token (defaults left empty)."""
    q = qos.resolved()

    def field(value: int, default: int) -> str:
        return "" if value == default else str(int(value))

    dl_s, dl_ns = _sec_nsec(q.deadline_ns)
    ls_s, ls_ns = _sec_nsec(q.lifespan_ns)
    lv_s, lv_ns = _sec_nsec(q.liveliness_lease_ns)
    inf_s, inf_ns = _sec_nsec(DURATION_INFINITE_NS)
    return (
        f"{field(q.reliability, _BASE.reliability)}:{field(q.durability, _BASE.durability)}:"
        f"{field(q.history, _BASE.history)},{field(q.depth, _BASE.depth)}:"
        f"{field(dl_s, inf_s)},{field(dl_ns, inf_ns)}:{field(ls_s, inf_s)},{field(ls_ns, inf_ns)}:"
        f"{field(q.liveliness, _BASE.liveliness)},{field(lv_s, inf_s)},{field(lv_ns, inf_ns)}"
    )


def qos_from_keyexpr(text: str) -> QoS:
    """Parse rmw_zenoh's compact QoS text (empty fields are its defaults); raises BusError."""
    parts = text.split(":")
    groups = [p.split(",") for p in parts]
    if len(parts) < 6 or len(groups[2]) < 2 or len(groups[3]) < 2 or len(groups[4]) < 2 or len(groups[5]) < 3:
        raise BusError(f"invalid QoS text '{text}' in a liveliness token")
    inf_s, inf_ns = _sec_nsec(DURATION_INFINITE_NS)

    def num(s: str, default: int) -> int:
        if not s:
            return default
        if not s.isdigit():
            raise BusError(f"invalid QoS text '{text}' in a liveliness token")
        return int(s)

    def policy(s: str, default: int) -> int:
        # rmw_zenoh looks policies up by their exact decimal text ('01' is not 1).
        value = num(s, default)
        if s and s != str(value):
            raise BusError(f"invalid QoS text '{text}' in a liveliness token")
        return value

    def dur(s: str, ns: str) -> int:
        sec, nsec = num(s, inf_s), num(ns, inf_ns)
        return sec * _NS + nsec

    try:
        return QoS(
            depth=num(groups[2][1], DEFAULT_DEPTH),
            reliability=Reliability(policy(parts[0], Reliability.RELIABLE)),
            durability=Durability(policy(parts[1], Durability.VOLATILE)),
            history=History(policy(groups[2][0], History.KEEP_LAST)),
            deadline_ns=dur(groups[3][0], groups[3][1]),
            lifespan_ns=dur(groups[4][0], groups[4][1]),
            liveliness=Liveliness(policy(groups[5][0], Liveliness.AUTOMATIC)),
            liveliness_lease_ns=dur(groups[5][1], groups[5][2]),
        )
    except ValueError as exc:
        raise BusError(f"invalid QoS text '{text}' in a liveliness token: {exc}") from exc
