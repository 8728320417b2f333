"""Following the master: a node whose master went away registers again once it is back.

rospy registers once (it keeps trying only while the master is not up yet at start:
"Unable to immediately register with master node [...]: master may not be running yet. Will
keep trying."), and neither it nor roscpp registers again with a master that restarted:
their nodes vanish from the graph, and no new peer finds them, until they are restarted.
Here a node asks its master every :data:`PERIOD_S` whether it knows the node (lookupNode).
A master that does not answer is one warning line (and quiet until it answers again); a
master that answers but no longer knows the node gets every publication, subscription and
parameter subscription again, and the subscriptions connect to the publishers it names (a
warning line when the master came back before its loss was seen, else an info line). TCPROS
connections are peer to peer: messages keep flowing between connected nodes meanwhile.
"""

from __future__ import annotations

import logging
import threading
from typing import TYPE_CHECKING

from robotmodel.errors import MasterError
from robotmodel.ros1._master import MasterClient

if TYPE_CHECKING:
    from robotmodel.ros1._node import Ros1Node

__all__ = ["PERIOD_S", "MasterKeepalive"]

_log = logging.getLogger("robotmodel.ros1")

#: Seconds between two questions to the master.
PERIOD_S = 1.0


class MasterKeepalive:
    """A thread registering ``node`` again with a master that restarted (see the module docstring)."""

    def __init__(self, node: Ros1Node) -> None:
        self._node = node
        self._master = MasterClient(node.master_uri, node.name, timeout=5.0)
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._run, name="ros1-keepalive", daemon=True)
        self._thread.start()

    def _known(self) -> bool:
        try:
            return self._master.lookup_node(self._node.name) == self._node.uri
        except MasterError as exc:
            if exc.code is None:
                raise
            return False  # "unknown node": a master that restarted (or forgot us with rosnode cleanup)

    def _run(self) -> None:
        down = False
        while not self._stop.wait(PERIOD_S):
            node = self._node
            try:
                if self._known():
                    down = False
                    continue
                if node.is_shutdown or self._stop.is_set():
                    return
                count = node.reregister()
            except MasterError as exc:
                if not down:
                    _log.warning("%s: lost the master (%s); registering again once it is back", node.name, exc)
                down = True
                continue
            if count:
                # one line per outage: the loss when it was seen, else the restart found on its return
                (_log.info if down else _log.warning)("%s: master %s restarted: registered %d topics again",
                                                      node.name, node.master_uri, count)
            down = False

    def close(self) -> None:
        """Stop asking (does not wait for a call in flight: the thread is a daemon)."""
        self._stop.set()
