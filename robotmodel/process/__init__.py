"""Child processes started, watched and stopped together: the one supervisor of ``launch`` and ``demo``.

- :class:`Supervisor`: start children (``robotmodel`` commands, Python modules, any argv),
  report their deaths as roslaunch does, stop them in order (SIGINT, SIGTERM, SIGKILL) and
  reap them all; their output shared with this process or logged per child.
- :class:`Child`: one of them, with its logged lines (:meth:`Child.wait_line`).
- :func:`module_argv` / :func:`command_argv`: how a child runs a module of the *installed*
  package whatever the current directory (``python -P``), dies quietly on an early SIGINT,
  and follows its supervisor when it dies (Linux); :func:`spawn` starts one with SIGINT held
  until it can take it. Any process of ours that starts Python children starts them here.

Usage::

    import threading
    from robotmodel.process import Supervisor

    sup = Supervisor()
    sup.command("rsp", "robot-state-publisher", "robot.urdf", required=True)
    try:
        sup.watch(threading.Event())  # until the required child exits
    finally:
        sup.stop_all()
"""

from __future__ import annotations

from robotmodel.process._child import Child, command_argv, module_argv, spawn
from robotmodel.process._supervisor import Supervisor

__all__ = ["Child", "Supervisor", "command_argv", "module_argv", "spawn"]
