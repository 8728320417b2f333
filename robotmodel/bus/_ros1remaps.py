"""A word for remaps that match nothing: on ROS 1 every ``NAME:=VALUE`` word is a remap.

rospy and roscpp take each such word on a node's command line as a remap and say nothing
when no name of the node matches it, so a word meant for something else (a xacro argument
given to robot_state_publisher, a misspelt topic) is silently lost. A node on the ROS 1
wire with remap rules watches the names it resolves (topics, and parameters looked up
through :meth:`robotmodel.bus.Node.resolve_topic_name`); once it has resolved nothing new
for :data:`QUIET_S` seconds, each rule that matched none of them is one warning line.
"""

from __future__ import annotations

import logging
import threading
import time
from collections.abc import Iterable

from robotmodel.bus._names import resolve_topic
from robotmodel.bus._remap import RemapKind, RemapRule
from robotmodel.errors import BusError

__all__ = ["QUIET_S", "RemapWatch"]

log = logging.getLogger("robotmodel.bus")

#: Seconds without a new name before unmatched rules are named.
QUIET_S = 2.0


class RemapWatch:
    """Names the rules of ``rules`` for ``node_name`` that match no name the node resolved (see the module)."""

    def __init__(self, rules: Iterable[RemapRule], node_name: str, namespace: str) -> None:
        self._node = node_name
        self._pending: dict[str, RemapRule] = {}
        for rule in rules:
            if rule.kind in (RemapKind.NAME, RemapKind.TOPIC) and rule.node in (None, node_name):
                try:
                    self._pending[resolve_topic(rule.match, namespace, node_name)] = rule
                except BusError:
                    continue
        self._lock = threading.Lock()
        self._last = time.monotonic()
        self._stop = threading.Event()
        if self._pending:
            threading.Thread(target=self._run, name="ros1-remaps", daemon=True).start()

    def saw(self, name: str) -> None:
        """The node resolved ``name`` (fully qualified, before remapping)."""
        with self._lock:
            self._pending.pop(name, None)
            self._last = time.monotonic()

    def _run(self) -> None:
        while True:
            with self._lock:
                left = self._last + QUIET_S - time.monotonic()
            if left <= 0:
                break
            if self._stop.wait(left):
                return
        with self._lock:
            unmatched, self._pending = list(self._pending.values()), {}
        for rule in unmatched:
            log.warning("remap '%s' matches no name %s uses (on ROS 1 every NAME:=VALUE word is a remap; "
                        "xacro arguments need the file expanded first)", rule.text or f"{rule.match}:="
                        f"{rule.replacement}", self._node)

    def close(self) -> None:
        """Say nothing more."""
        self._stop.set()
