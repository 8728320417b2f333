"""ros2cli's ``--qos-*`` options: a preset profile by its short key, then each policy overridden by its own.

As ``ros2topic.api.qos_profile_from_short_keys``: ``--qos-profile`` names one of rclpy's
``QoSPresetProfiles`` (``default``, ``sensor_data``, ``system_default``, ...);
``--qos-history``, ``--qos-reliability``, ``--qos-durability``, ``--qos-liveliness`` and
``--qos-liveliness-lease-duration-seconds`` replace that policy, ``--qos-depth`` the depth (a
depth of 0 or none leaves the preset's, made 1 when the profile is transient local with depth 0).
``best_available`` is what rmw makes of it for a publisher: reliable, transient local,
automatic liveliness. ``unknown`` is refused: no wire can offer it.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TypeVar

from robotmodel.bus import QoS
from robotmodel.bus._qos import DURATION_INFINITE_NS, Durability, History, Liveliness, Reliability
from robotmodel.errors import BusError

__all__ = ["DURABILITY_KEYS", "HISTORY_KEYS", "LIVELINESS_KEYS", "PROFILE_KEYS", "RELIABILITY_KEYS",
           "qos_from_short_keys"]

_D, _R, _H, _L = Durability, Reliability, History, Liveliness
# rclpy's QoSPresetProfiles, as (history, depth, reliability, durability).
_PRESETS: dict[str, tuple[History, int, Reliability, Durability]] = {
    "default": (_H.KEEP_LAST, 10, _R.RELIABLE, _D.VOLATILE),
    "system_default": (_H.SYSTEM_DEFAULT, 0, _R.SYSTEM_DEFAULT, _D.SYSTEM_DEFAULT),
    "sensor_data": (_H.KEEP_LAST, 5, _R.BEST_EFFORT, _D.VOLATILE),
    "services_default": (_H.KEEP_LAST, 10, _R.RELIABLE, _D.VOLATILE),
    "parameters": (_H.KEEP_LAST, 1000, _R.RELIABLE, _D.VOLATILE),
    "parameter_events": (_H.KEEP_LAST, 1000, _R.RELIABLE, _D.VOLATILE),
    "action_status_default": (_H.KEEP_LAST, 1, _R.RELIABLE, _D.TRANSIENT_LOCAL),
    "best_available": (_H.KEEP_LAST, 10, _R.RELIABLE, _D.TRANSIENT_LOCAL),
}
_HISTORY = {"system_default": _H.SYSTEM_DEFAULT, "keep_last": _H.KEEP_LAST, "keep_all": _H.KEEP_ALL}
_RELIABILITY = {"system_default": _R.SYSTEM_DEFAULT, "reliable": _R.RELIABLE, "best_effort": _R.BEST_EFFORT,
                "best_available": _R.RELIABLE}
_DURABILITY = {"system_default": _D.SYSTEM_DEFAULT, "transient_local": _D.TRANSIENT_LOCAL, "volatile": _D.VOLATILE,
               "best_available": _D.TRANSIENT_LOCAL}
_LIVELINESS = {"system_default": _L.SYSTEM_DEFAULT, "automatic": _L.AUTOMATIC, "manual_by_topic": _L.MANUAL_BY_TOPIC,
               "best_available": _L.AUTOMATIC}
#: The short keys rclpy accepts for each option (``unknown`` among them, which is refused here).
PROFILE_KEYS = ("unknown", *_PRESETS)
HISTORY_KEYS = (*_HISTORY, "unknown")
RELIABILITY_KEYS = ("system_default", "reliable", "best_effort", "unknown", "best_available")
DURABILITY_KEYS = ("system_default", "transient_local", "volatile", "unknown", "best_available")
LIVELINESS_KEYS = ("system_default", "automatic", "manual_by_topic", "unknown", "best_available")


_T = TypeVar("_T")


def _pick(table: Mapping[str, _T], key: str, option: str) -> _T:
    try:
        return table[key]
    except KeyError:
        raise BusError(f"--{option} {key}: not a QoS setting a publisher can offer "
                       f"(one of {', '.join(table)})") from None


def qos_from_short_keys(profile: str = "default", *, reliability: str | None = None, durability: str | None = None,
                        depth: int | None = None, history: str | None = None, liveliness: str | None = None,
                        liveliness_lease_duration_s: float | None = None) -> QoS:
    """The QoS ros2cli builds from ``--qos-profile`` and the ``--qos-*`` overrides (see the module docstring)."""
    hist, dep, rel, dur = _pick(_PRESETS, profile, "qos-profile")
    live, lease = _L.SYSTEM_DEFAULT if profile == "system_default" else _L.AUTOMATIC, DURATION_INFINITE_NS
    if history:
        hist = _pick(_HISTORY, history, "qos-history")
    if durability:
        dur = _pick(_DURABILITY, durability, "qos-durability")
    if reliability:
        rel = _pick(_RELIABILITY, reliability, "qos-reliability")
    if liveliness:
        live = _pick(_LIVELINESS, liveliness, "qos-liveliness")
    if liveliness_lease_duration_s and liveliness_lease_duration_s >= 0:
        lease = round(liveliness_lease_duration_s * 1e9)
    if depth and depth >= 0:
        dep = depth
    elif dur == _D.TRANSIENT_LOCAL and dep == 0:
        dep = 1
    return QoS(dep, reliability=rel, durability=dur, history=hist, liveliness=live, liveliness_lease_ns=lease)
