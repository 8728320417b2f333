"""The examples run as real processes on a private bus (own port and domain); the test process joins it."""

from __future__ import annotations

import sys
from collections.abc import Iterator
from pathlib import Path

import pytest
from conftest import REPO
from livebus import Bus, Proc, joined

EXAMPLES = REPO / "examples"


class ExampleBus(Bus):
    """A :class:`livebus.Bus` that also starts the examples."""

    def example(self, name: str, *args: str) -> Proc:
        """``python examples/NAME ARGS``."""
        return self.start(sys.executable, str(EXAMPLES / name), *args)


@pytest.fixture
def live(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Iterator[ExampleBus]:
    """A fresh bus; the test process joins it too (its env is set); every child is reaped."""
    yield from joined(ExampleBus(tmp_path, "zenoh"), monkeypatch)
