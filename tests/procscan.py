"""Which processes are still running on a given private bus (found by its port in their environment)."""

from __future__ import annotations

import time
from pathlib import Path


def leftovers(port: str) -> list[str]:
    """``pid: command line`` of every process with ``ROBOTMODEL_ZENOH_PORT=<port>`` in its environment.

    Not the zenoh router a tool started detached: it outlives the tools by design, and the
    test's teardown stops it (tests/conftest.py).
    """
    found = []
    needle = f"ROBOTMODEL_ZENOH_PORT={port}".encode()
    for entry in Path("/proc").iterdir():
        if not entry.name.isdigit():
            continue
        try:
            environ = (entry / "environ").read_bytes()
            cmdline = (entry / "cmdline").read_bytes().replace(b"\0", b" ").decode(errors="replace")
        except OSError:
            continue
        if needle in environ.split(b"\0") and "robotmodel.bus._router import main" not in cmdline:
            found.append(f"{entry.name}: {cmdline}")
    return found


def assert_none_left(port: str, timeout: float = 10.0) -> None:
    """Fail unless every process on the bus at ``port`` has exited within ``timeout`` seconds."""
    deadline = time.monotonic() + timeout
    while leftovers(port) and time.monotonic() < deadline:
        time.sleep(0.2)
    left = leftovers(port)
    assert left == [], "\n".join(left)
