"""``python -m robotmodel.demo._shot URL OUT.png``: the demo's screenshot of the live viewer, as a child.

A process of its own, so the browser's start and the page's first complete frame overlap
the demo's run instead of holding it up; the demo reaps it like every other child.
"""

from __future__ import annotations

import os
import signal
import sys
import time
from pathlib import Path
from types import FrameType


def _interrupt(_signum: int, _frame: FrameType | None) -> None:
    raise KeyboardInterrupt


def main(argv: list[str]) -> int:
    """Render URL in headless Chromium and write the PNG (atomically) to OUT."""
    from robotmodel.errors import RobotModelError
    from robotmodel.viewer import screenshot

    # A stop (SIGINT, then SIGTERM) unwinds through the browser's context, so Chromium (in a
    # session of its own) is closed with this process rather than left running.
    for signum in (signal.SIGINT, signal.SIGTERM):
        signal.signal(signum, _interrupt)
    url, out = argv[0], Path(argv[1])
    began = time.monotonic()
    try:
        png = screenshot(url, width=1280, height=800, timeout=90.0)
    except (RobotModelError, OSError, TimeoutError) as exc:  # the browser's own errors included: one line
        print(f"no screenshot: {type(exc).__name__}: {' '.join(str(exc).splitlines())}", flush=True)
        return 1
    except KeyboardInterrupt:
        print("no screenshot: stopped", flush=True)
        return 130
    tmp = out.with_name(f".{out.name}.part")
    tmp.write_bytes(png)
    os.replace(tmp, out)
    print(f"wrote {out} in {time.monotonic() - began:.1f} s", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
