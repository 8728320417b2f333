"""Live-bus fixture for the publisher tests: a private port and domain for this test and its children."""

from __future__ import annotations

import sys
from collections.abc import Iterator
from pathlib import Path

import pytest
from livebus import Bus, Proc, joined

CHILDREN = Path(__file__).with_name("pub_children.py")


class PublisherBus(Bus):
    """A :class:`livebus.Bus` that also starts this folder's listener children."""

    def listener(self, *args: str) -> Proc:
        """A mode of pub_children.py."""
        return self.start(sys.executable, str(CHILDREN), *args)


@pytest.fixture
def live(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Iterator[PublisherBus]:
    """A fresh bus; the test process joins it too (its env is set); every child is reaped."""
    yield from joined(PublisherBus(tmp_path, "zenoh"), monkeypatch)
