"""The tests here run on the DDS wire: the processes they start speak it (RMW_IMPLEMENTATION)."""

from __future__ import annotations

import pytest


@pytest.fixture
def wire() -> str:
    """The DDS wire, for ``bus_env`` and the processes ``procs`` starts."""
    return "dds"
