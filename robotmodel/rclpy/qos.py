"""rclpy.qos: QoSProfile, its policies and the presets, mapped onto robotmodel's bus QoS."""

from __future__ import annotations

from enum import IntEnum
from typing import Any

from robotmodel.bus import QoS, Reliability
from robotmodel.bus._qos import Durability, History, Liveliness

__all__ = [
    "DurabilityPolicy",
    "HistoryPolicy",
    "LivelinessPolicy",
    "QoSPresetProfiles",
    "QoSProfile",
    "ReliabilityPolicy",
    "qos_profile_action_status_default",
    "qos_profile_parameter_events",
    "qos_profile_parameters",
    "qos_profile_sensor_data",
    "qos_profile_services_default",
    "qos_profile_system_default",
    "to_bus_qos",
]


class HistoryPolicy(IntEnum):
    """rmw's history policies."""

    SYSTEM_DEFAULT = 0
    KEEP_LAST = 1
    KEEP_ALL = 2
    UNKNOWN = 3


class ReliabilityPolicy(IntEnum):
    """rmw's reliability policies."""

    SYSTEM_DEFAULT = 0
    RELIABLE = 1
    BEST_EFFORT = 2
    UNKNOWN = 3
    BEST_AVAILABLE = 4


class DurabilityPolicy(IntEnum):
    """rmw's durability policies."""

    SYSTEM_DEFAULT = 0
    TRANSIENT_LOCAL = 1
    VOLATILE = 2
    UNKNOWN = 3
    BEST_AVAILABLE = 4


class LivelinessPolicy(IntEnum):
    """rmw's liveliness policies."""

    SYSTEM_DEFAULT = 0
    AUTOMATIC = 1
    MANUAL_BY_TOPIC = 3
    UNKNOWN = 4
    BEST_AVAILABLE = 5


class QoSProfile:
    """rclpy's QoSProfile: ``QoSProfile(depth=10)``, keyword policies; KEEP_LAST needs a depth, as rclpy."""

    def __init__(self, **kwargs: Any) -> None:
        history = kwargs.get("history", HistoryPolicy.KEEP_LAST)
        if "depth" not in kwargs and HistoryPolicy(history) == HistoryPolicy.KEEP_LAST:
            raise ValueError("History policy KEEP_LAST requires a depth to be specified")
        self.history = HistoryPolicy(history)
        self.depth = int(kwargs.get("depth", 0))
        self.reliability = ReliabilityPolicy(kwargs.get("reliability", ReliabilityPolicy.RELIABLE))
        self.durability = DurabilityPolicy(kwargs.get("durability", DurabilityPolicy.VOLATILE))
        self.liveliness = LivelinessPolicy(kwargs.get("liveliness", LivelinessPolicy.SYSTEM_DEFAULT))

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, QoSProfile):
            return NotImplemented
        return vars(self) == vars(other)

    def __hash__(self) -> int:
        return hash(tuple(sorted(vars(self).items())))

    def __repr__(self) -> str:
        fields = ", ".join(f"{k}={v!r}" for k, v in vars(self).items())
        return f"QoSProfile({fields})"


def to_bus_qos(qos: QoSProfile | int) -> QoS:
    """The bus QoS of an rclpy QoS argument (a profile or a depth)."""
    if isinstance(qos, int):
        return QoS(qos)
    keep_all = qos.history == HistoryPolicy.KEEP_ALL
    return QoS(max(qos.depth, 1),
               reliability=Reliability.BEST_EFFORT if qos.reliability == ReliabilityPolicy.BEST_EFFORT
               else Reliability.RELIABLE,
               durability=Durability.TRANSIENT_LOCAL if qos.durability == DurabilityPolicy.TRANSIENT_LOCAL
               else Durability.VOLATILE,
               history=History.KEEP_ALL if keep_all else History.KEEP_LAST,
               liveliness=Liveliness.MANUAL_BY_TOPIC if qos.liveliness == LivelinessPolicy.MANUAL_BY_TOPIC
               else Liveliness.AUTOMATIC)


#: rmw's presets, as rclpy exports them.
qos_profile_system_default = QoSProfile(history=HistoryPolicy.SYSTEM_DEFAULT, depth=0,
                                        reliability=ReliabilityPolicy.SYSTEM_DEFAULT,
                                        durability=DurabilityPolicy.SYSTEM_DEFAULT)
qos_profile_sensor_data = QoSProfile(depth=5, reliability=ReliabilityPolicy.BEST_EFFORT)
qos_profile_services_default = QoSProfile(depth=10)
qos_profile_parameters = QoSProfile(depth=1000)
qos_profile_parameter_events = QoSProfile(depth=1000)
qos_profile_action_status_default = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL)


class QoSPresetProfiles:
    """rclpy's preset names (``QoSPresetProfiles.SENSOR_DATA.value``)."""

    class _Preset:
        def __init__(self, value: QoSProfile) -> None:
            self.value = value

    SYSTEM_DEFAULT = _Preset(qos_profile_system_default)
    SENSOR_DATA = _Preset(qos_profile_sensor_data)
    SERVICES_DEFAULT = _Preset(qos_profile_services_default)
    PARAMETERS = _Preset(qos_profile_parameters)
    PARAMETER_EVENTS = _Preset(qos_profile_parameter_events)
    ACTION_STATUS_DEFAULT = _Preset(qos_profile_action_status_default)
