"""The backend seam holds: nothing above it imports a wire, and the wires are chosen by name only."""

from __future__ import annotations

import ast
import subprocess
import sys
from pathlib import Path

import pytest

import robotmodel
from robotmodel.bus import BACKENDS, BusError, Context, open_backend

ROOT = Path(robotmodel.__file__).resolve().parent
BUS = ROOT / "bus"
# Modules below the seam: the wires and what only they use (_book: the bookkeeping they share).
WIRE_MODULES = {"_inprocess", "_zenoh", "_zenoh_names", "_zenoh_session", "_attachment", "_config", "_router", "_ros1", "_ros1_graph",
                "_dds", "_dds_types", "_dds_qos", "_dds_raw", "_dds_graph", "_dds_service", "_zenoh_service", "_book"}
# The bus's own modules above the seam (the package's __init__ re-exports zenoh's name helpers
# for users of the wire format, and is not counted).
ABOVE = ["_backend", "_node", "_graph", "_codec", "_ros1codec", "_ros1clock", "_ros1remaps", "_names", "_qos", "_remap",
         "_domain", "_warn", "_select", "_service", "_srv"]


def _imports(path: Path) -> set[str]:
    names: set[str] = set()
    for node in ast.walk(ast.parse(path.read_text(), str(path))):
        if isinstance(node, ast.ImportFrom) and node.module:
            names.add(node.module)
        elif isinstance(node, ast.Import):
            names.update(alias.name for alias in node.names)
    return names


def _wire_imports(path: Path) -> list[str]:
    return sorted(m for m in _imports(path)
                  if m.startswith("robotmodel.bus.") and m.split(".")[2] in WIRE_MODULES)


@pytest.mark.parametrize("module", ABOVE)
def test_the_layer_above_the_seam_imports_no_wire(module: str) -> None:
    assert _wire_imports(BUS / f"{module}.py") == []


def test_the_library_outside_the_bus_reaches_no_wire() -> None:
    offenders = {str(p.relative_to(ROOT)): found for p in ROOT.rglob("*.py")
                 if BUS not in p.parents and (found := _wire_imports(p))}
    assert offenders == {}


def test_every_bus_module_is_placed_above_or_below_the_seam() -> None:
    modules = {p.stem for p in BUS.glob("_*.py")} - {"__init__"}
    assert modules == set(ABOVE) | WIRE_MODULES


def test_wires_are_opened_by_name() -> None:
    assert set(BACKENDS) >= {"inprocess", "zenoh", "ros1"}
    with pytest.raises(BusError, match="unknown bus backend 'carrier_pigeon'"):
        open_backend("carrier_pigeon", 0)
    with Context(backend="inprocess", domain_id=3) as ctx:
        assert (ctx.backend.name, ctx.encoding, ctx.domain_id) == ("inprocess", "cdr", 3)
        with Context(backend=ctx.backend) as shared:
            assert shared.domain_id == 3


def test_importing_the_bus_loads_no_wire() -> None:
    code = ("import sys, robotmodel.bus; "
            "print(sorted(m for m in sys.modules if m == 'zenoh' or m.startswith('robotmodel.bus._zenoh_session')"
            " or m == 'robotmodel.bus._inprocess'))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.strip() == "[]"


@pytest.mark.parametrize("module", sorted(WIRE_MODULES))
def test_a_wire_imports_nothing_of_the_node_layer(module: str) -> None:
    node_layer = {"_node", "_graph", "_codec", "_remap", "_domain"}
    found = sorted(m for m in _imports(BUS / f"{module}.py")
                   if m.startswith("robotmodel.bus.") and m.split(".")[2] in node_layer)
    assert found == []
