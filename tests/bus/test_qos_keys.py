"""``--qos-*`` short keys against the real rclpy's presets and policy keys (ros2topic's qos_profile_from_short_keys)."""

from __future__ import annotations

import json
import os
import subprocess

import pytest
from rclpyside import MISSING, RCLPY

from robotmodel.bus import Durability, History, QoS, Reliability
from robotmodel.errors import BusError
from robotmodel.topic import qos_from_short_keys

# rclpy's presets and overrides, as ros2topic builds them (ros2topic itself is not in the rclpy venv).
_PROBE = """
import json, rclpy.qos as q
out = {}
for key in q.QoSPresetProfiles.short_keys():
    if key in ('unknown', 'best_available'):
        continue
    p = q.QoSPresetProfiles.get_from_short_key(key)
    out[key] = [int(p.history), p.depth, int(p.reliability), int(p.durability)]
p = q.QoSPresetProfiles.get_from_short_key('parameters')
p.history = q.QoSHistoryPolicy.get_from_short_key('keep_all')
p.reliability = q.QoSReliabilityPolicy.get_from_short_key('best_effort')
p.depth = 7
out['parameters+keep_all+best_effort+7'] = [int(p.history), p.depth, int(p.reliability), int(p.durability)]
print(json.dumps(out))
"""


@pytest.mark.skipif(bool(MISSING), reason=MISSING)
def test_presets_and_overrides_match_rclpy() -> None:
    env = {k: v for k, v in os.environ.items() if not k.startswith(("PYTHON", "VIRTUAL_ENV"))}
    env["RMW_IMPLEMENTATION"] = "rmw_fastrtps_cpp"  # the one this rclpy has
    expected = json.loads(subprocess.run([str(RCLPY), "-c", _PROBE], capture_output=True, text=True, check=True,
                                         timeout=60, env=env).stdout)
    ours = {key: qos_from_short_keys(key) for key in expected if "+" not in key}
    ours["parameters+keep_all+best_effort+7"] = qos_from_short_keys("parameters", history="keep_all",
                                                                    reliability="best_effort", depth=7)
    assert {k: [int(q.history), q.depth, int(q.reliability), int(q.durability)] for k, q in ours.items()} == expected


def test_best_available_is_what_rmw_offers_and_unknown_is_refused() -> None:
    # rmw's best available for a publisher: reliable and transient local (a late joiner gets its samples).
    assert qos_from_short_keys("best_available") == QoS(10, Reliability.RELIABLE, Durability.TRANSIENT_LOCAL,
                                                        History.KEEP_LAST)
    # rclcpp's rule: transient local with depth 0 becomes depth 1.
    assert qos_from_short_keys("system_default", durability="transient_local").depth == 1
    with pytest.raises(BusError, match="--qos-reliability unknown"):
        qos_from_short_keys(reliability="unknown")
