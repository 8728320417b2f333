"""robotmodel.rclpy's names are rclpy's: every public name of each stand-in module exists in Jazzy's rclpy.

Checked against the real rclpy (``.venv-rclpy``): each ``robotmodel.rclpy.X`` module's
``__all__`` is looked up in ``rclpy.X``. The only names rclpy lacks are robotmodel's
additions, listed here with why.
"""

from __future__ import annotations

import importlib
import json
import os
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
RCLPY = Path(os.environ.get("ROBOTMODEL_RCLPY_PYTHON", str(ROOT / ".venv-rclpy" / "bin" / "python")))
MODULES = ["", ".node", ".qos", ".time", ".duration", ".clock", ".clock_type", ".executors", ".callback_groups",
           ".parameter", ".parameter_client", ".exceptions", ".logging", ".task", ".context", ".utilities"]
ADDITIONS = {
    ("rclpy", "InitContextManager"),  # what newer rclpy's init() returns (Kilted); Jazzy's returns None
    ("rclpy.qos", "to_bus_qos"),  # an rclpy QoS argument as robotmodel's bus QoS
}
CHECK = """
import importlib, json, sys
missing = []
for mod, name in json.loads(sys.argv[1]):
    if not hasattr(importlib.import_module(mod), name):
        missing.append([mod, name])
print(json.dumps(missing))
"""


def test_every_public_name_is_rclpy_s() -> None:
    if not RCLPY.exists():
        pytest.skip(f"no real rclpy at {RCLPY} (run .ci/rclpy-venv)")
    pairs = [[f"rclpy{suffix}", name] for suffix in MODULES
             for name in importlib.import_module(f"robotmodel.rclpy{suffix}").__all__]
    # The suite's conftest names rmw_zenoh_cpp for whatever names no wire; the real rclpy has only Fast DDS.
    env = {k: v for k, v in os.environ.items() if not k.startswith(("PYTHON", "VIRTUAL_ENV", "RMW_IMPLEMENTATION"))}
    done = subprocess.run([str(RCLPY), "-c", CHECK, json.dumps(pairs)], capture_output=True, text=True,
                          timeout=120, check=True, env=env)
    assert {tuple(p) for p in json.loads(done.stdout)} == ADDITIONS
    assert len(pairs) > 60
