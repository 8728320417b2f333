"""Run a program as ``__main__`` with an uncaught exception on demand: SIGUSR1 raises RuntimeError in its main thread.

    raise_on_usr1.py PROGRAM [ARGS...]

What a bug in a program's main loop does, at whatever point the loop is (spin, a sleep, a
lookup): tests/standins check that the process then ends, with status 1, within 2 s.
"""

import runpy
import signal
import sys


def _raise(signum, frame):
    raise RuntimeError("injected")


signal.signal(signal.SIGUSR1, _raise)
sys.argv = sys.argv[1:]
runpy.run_path(sys.argv[0], run_name="__main__")
