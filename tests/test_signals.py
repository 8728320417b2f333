"""robotmodel.signals.stop_on_signals: a signal that lands while the main thread holds the stop event's lock still stops the tool."""

from __future__ import annotations

import subprocess
import sys
import textwrap

# Run in a child: with a handler that sets the event itself, the call below never returns.
_PROBE = textwrap.dedent("""
    import signal
    from robotmodel.signals import stop_on_signals

    stop = stop_on_signals()
    handler = signal.getsignal(signal.SIGTERM)
    # Event.wait(timeout) holds the event's lock between waking and returning; a signal handled
    # in that window runs on the main thread with the lock held. Reproduce that window exactly.
    with stop._cond:
        handler(signal.SIGTERM, None)
    assert stop.wait(10), "the stop event was never set"
    print("stopped")
""")


def test_handler_runs_while_the_main_thread_holds_the_event_lock():
    result = subprocess.run([sys.executable, "-c", _PROBE], capture_output=True, text=True, timeout=30, check=False)
    assert result.returncode == 0, result.stderr
    assert result.stdout.strip() == "stopped"


def test_sigterm_stops_a_waiting_main_thread():
    probe = textwrap.dedent("""
        import os, signal, sys
        from robotmodel.signals import stop_on_signals

        stop = stop_on_signals()
        os.kill(os.getpid(), signal.SIGTERM)
        print("stopped" if stop.wait(10) else "not stopped")
    """)
    result = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, timeout=30, check=False)
    assert result.stdout.strip() == "stopped", result.stderr


def test_signal_landing_on_another_thread_wakes_a_main_thread_waiting_without_timeout():
    # The kernel may deliver a process-directed SIGTERM to any thread that does not block it:
    # in a bus process, usually one of zenoh's. The main thread, asleep in stop.wait() with no
    # timeout, is then never interrupted, so Python's handler never runs unless something
    # else wakes the watcher. Deliver it to a worker thread on purpose.
    probe = textwrap.dedent("""
        import signal, threading
        from robotmodel.signals import stop_on_signals

        stop = stop_on_signals()
        worker = threading.Thread(target=lambda: signal.pthread_kill(threading.get_ident(), signal.SIGTERM))
        threading.Timer(0.2, worker.start).start()
        stop.wait()
        print("stopped")
    """)
    try:
        result = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, timeout=20,
                                check=False)
    except subprocess.TimeoutExpired:
        raise AssertionError("SIGTERM on a worker thread did not stop the waiting main thread") from None
    assert result.returncode == 0, result.stderr
    assert result.stdout.strip() == "stopped"
