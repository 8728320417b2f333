"""A script holding a TransformListener (or any subscription) ends as Python scripts do.

Python joins its non-daemon threads before it runs atexit handlers; zenoh's callback
threads end only once their session closes, so a script that never closed its node hung
at exit forever after an uncaught exception or Ctrl-C. Each case here is a real process on
its own bus, and must end within 2 s of the exception or the signal.
"""

from __future__ import annotations

import signal
import time

import pytest

_SCRIPT = """
import signal, sys, time
from robotmodel.bus import Node
from robotmodel.msgs import String
from robotmodel.tf import Buffer
from robotmodel.tf_ros import TransformListener
node = Node("script")
if sys.argv[1] == "listener":
    TransformListener(Buffer(), node)
else:
    node.create_subscription(String, "/chatter", lambda m: None, 10)
if sys.argv[2] == "exit-on-sigterm":  # a common pattern: SIGTERM ends the script through SystemExit
    signal.signal(signal.SIGTERM, lambda signum, frame: sys.exit(0))
print("ready", flush=True)
if sys.argv[2] == "raise":
    raise RuntimeError("the script failed")
time.sleep(600)
"""

_DEADLINE_S = 2.0


@pytest.mark.parametrize("holder", ["listener", "subscription"])
@pytest.mark.parametrize("ending", ["uncaught exception", "SIGINT", "SIGTERM", "SIGTERM handled by sys.exit"])
def test_script_ends_within_2_s(bus, holder, ending):
    import sys

    mode = {"uncaught exception": "raise", "SIGTERM handled by sys.exit": "exit-on-sigterm"}.get(ending, "sleep")
    proc = bus.start(sys.executable, "-c", _SCRIPT, holder, mode)
    proc.wait_line("^ready$", timeout=60)
    start = time.monotonic()
    if ending != "uncaught exception":
        proc.popen.send_signal(signal.SIGINT if ending == "SIGINT" else signal.SIGTERM)
    try:
        code = proc.popen.wait(_DEADLINE_S + 8)
    except Exception:
        proc.kill()
        pytest.fail(f"the script did not end after {ending}:\n" + "\n".join(proc.err[-20:]))
    elapsed = time.monotonic() - start
    proc.kill()  # reaps the reader threads
    assert elapsed < _DEADLINE_S, f"ended {elapsed:.1f} s after {ending}"
    expected = {"uncaught exception": 1, "SIGINT": -signal.SIGINT, "SIGTERM": -signal.SIGTERM,
                "SIGTERM handled by sys.exit": 0}[ending]
    assert code == expected, proc.err[-20:]
    if ending == "uncaught exception":
        assert proc.err[-1] == "RuntimeError: the script failed"
    if ending == "SIGINT":
        assert proc.err[-1] == "KeyboardInterrupt"


_WORKER = """
import threading, time
from robotmodel.bus import Node
from robotmodel.msgs import String
node = Node("script")
node.create_subscription(String, "/chatter", lambda m: None, 10)
pub = node.create_publisher(String, "/chatter", 10)
def work():
    time.sleep(0.5)  # still working after the main thread has ended
    pub.publish(String(data="late"))
    print("published", flush=True)
threading.Thread(target=work).start()
print("ready", flush=True)
"""


def test_the_scripts_own_threads_finish_with_the_bus_open(bus):
    """Closing the sessions at exit waits for the script's own threads, as Python's exit does."""
    import sys

    proc = bus.start(sys.executable, "-c", _WORKER)
    proc.wait_line("^ready$", timeout=60)
    try:
        code = proc.popen.wait(_DEADLINE_S + 8)
    except Exception:
        proc.kill()
        pytest.fail("the script did not end:\n" + "\n".join(proc.err[-20:]))
    proc.kill()
    assert code == 0, proc.err[-20:]
    assert proc.out[-1] == "published" and not proc.err, proc.err
