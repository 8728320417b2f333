"""A process ends cleanly after closing its bus, whichever thread declared its subscriptions."""

from __future__ import annotations

import subprocess
import sys
from typing import Any

# Subscriptions (and the graph's token watch) declared from a daemon thread, as the recorder
# subscribes the topics it discovers; then the node is closed and the interpreter exits at once.
_DECLARE_FROM_A_DAEMON_THREAD = """
import threading
from robotmodel.bus import Node
from robotmodel.msgs import String
node = Node("daemon_declarer")
def declare():
    for k in range(8):
        node.create_subscription(String, f"/topic{k}", lambda m: None, 10)
    node.get_topic_names_and_types()
t = threading.Thread(target=declare, daemon=True)
t.start()
t.join()
node.close()
"""


def test_callbacks_declared_from_a_daemon_thread_do_not_abort_the_exit(bus_env: dict[str, str], new_port: Any) -> None:
    # zenoh runs each callback on a thread that inherits the declaring thread's daemon flag; one
    # left running into the interpreter's finalization aborted the process (SIGABRT, 'FATAL:
    # exception not rethrown'): 5 of 12 runs before the backend waited for them on close.
    # Each alone on a bus of its own, as in the runs that showed it.
    runs = [subprocess.Popen([sys.executable, "-c", _DECLARE_FROM_A_DAEMON_THREAD],
                             env=dict(bus_env, ROBOTMODEL_ZENOH_PORT=str(new_port())),
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True) for _ in range(10)]
    results: list[tuple[int, Any]] = []
    try:
        for run in runs:
            _, err = run.communicate(timeout=120)
            results.append((run.returncode, err[-500:]))
    finally:
        for run in runs:
            run.kill()
            run.wait()
    assert [code for code, _ in results] == [0] * len(runs), results
