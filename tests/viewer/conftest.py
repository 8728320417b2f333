"""Fixtures for the viewer tests: the live bus (see tests/livebus.py) and a private mesh cache."""

from __future__ import annotations

import os
from collections.abc import Iterator

import pytest
from livebus import bus

__all__ = ["bus", "private_mesh_cache"]


@pytest.fixture(scope="session", autouse=True)
def private_mesh_cache(tmp_path_factory: pytest.TempPathFactory) -> Iterator[None]:
    """Meshes converted by these tests (in-process and in child processes) stay out of ~/.cache."""
    before = os.environ.get("ROBOTMODEL_CACHE_DIR")
    os.environ["ROBOTMODEL_CACHE_DIR"] = str(tmp_path_factory.mktemp("mesh-cache"))
    try:
        yield
    finally:
        if before is None:
            os.environ.pop("ROBOTMODEL_CACHE_DIR", None)
        else:
            os.environ["ROBOTMODEL_CACHE_DIR"] = before
