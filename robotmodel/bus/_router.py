"""A zenoh router (eclipse-zenoh in router mode) as rmw_zenoh's ``rmw_zenohd``, and its life.

Below the seam: it is the zenoh wire's meeting point, nothing a node uses. It listens on
tcp/127.0.0.1:7447 by default (``ROBOTMODEL_ZENOH_PORT`` changes the port); ``listen`` and
``connect`` endpoints and ``ZENOH_ROUTER_CONFIG_URI`` / ``ZENOH_CONFIG_OVERRIDE`` apply as
rmw_zenohd reads them (see :func:`robotmodel.bus._config.router_config`).

Its life is its own, as ros2cli's daemon's: a zenoh session that meets at the loopback port
and finds nobody listening there starts a router detached (:func:`ensure_router`: its own
process session, no terminal, output to a log file beside its claim) and waits for it. The
router outlives the tool that started it, so a ROS 2 node that found it keeps it;
:func:`stop_router` (``robotmodel router --stop``) ends it, and then a real ``rmw_zenohd``
can take the port. Every router of ours, detached or not, holds a lock on its claim file
``router-<port>-<netns>.pid`` in the runtime directory (``$XDG_RUNTIME_DIR/robotmodel``, else
``<tmp>/robotmodel-<uid>``) while it runs: that is how ``--stop`` finds it, and a router that
died leaves no stale claim (the kernel drops the lock).
"""

from __future__ import annotations

import contextlib
import json
import os
import re
import signal
import socket
import subprocess
import sys
import tempfile
import time
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING

from robotmodel.bus._config import rendezvous_port
from robotmodel.errors import BusError

if TYPE_CHECKING:
    import zenoh

__all__ = ["ensure_router", "router_claim", "run_router", "stop_router"]

# A Python start, zenoh's import and a bind: well under a second, but a loaded 2-core machine can stall.
_START_TIMEOUT_S = 20.0
_STOP_TIMEOUT_S = 10.0
_POLL_S = 0.02
_LOG_KEEP = 64 * 1024
# The detached router's whole program; -c rather than -m so no second copy of this module is made.
_DETACHED = "from robotmodel.bus._router import main; raise SystemExit(main())"
# Routers this process started, kept so their exit status is collected (no zombie) once they end.
_started: list[subprocess.Popen[bytes]] = []


def _runtime_dir() -> Path:
    base = os.environ.get("XDG_RUNTIME_DIR", "").strip()
    path = Path(base) / "robotmodel" if base else Path(tempfile.gettempdir()) / f"robotmodel-{os.getuid()}"
    try:
        path.mkdir(mode=0o700, parents=True, exist_ok=True)
        owner = path.stat().st_uid
    except OSError as exc:
        raise BusError(f"cannot make the router's runtime directory {path}: {exc.strerror}") from None
    if owner != os.getuid():
        # A shared temporary directory: another user's folder there is not ours to trust.
        raise BusError(f"the router's runtime directory {path} belongs to another user (set XDG_RUNTIME_DIR)")
    return path


def router_claim(port: int | None = None) -> Path:
    """The claim file of our router on ``port`` (default: the rendezvous port) in this network namespace."""
    try:
        # Two network namespaces each have their own port 7447, and so their own router.
        netns = "-" + "".join(c for c in str(Path("/proc/self/ns/net").readlink()) if c.isdigit())
    except OSError:
        netns = ""
    return _runtime_dir() / f"router-{rendezvous_port() if port is None else port}{netns}.pid"


def _lock(fd: int) -> bool:
    import fcntl

    try:
        fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except OSError:
        return False
    return True


def _claim(path: Path) -> int | None:
    """Lock ``path`` and write our pid into it; the open descriptor (kept until exit), or None if held."""
    try:
        fd = os.open(path, os.O_RDWR | os.O_CREAT, 0o600)
    except OSError as exc:
        raise BusError(f"cannot open the router's claim {path}: {exc.strerror}") from None
    # Not at the first refusal: another process may be only probing it (_held) for a moment.
    if not _wait_locked(fd, 0.2):
        os.close(fd)
        return None
    os.ftruncate(fd, 0)
    os.write(fd, f"{os.getpid()}\n".encode())
    return fd


def run_router(listen: Sequence[str] = (), connect: Sequence[str] = ()) -> int:
    """Run the router until SIGINT/SIGTERM; the exit code (0). BusError if it cannot start."""
    import zenoh

    from robotmodel.bus._config import rendezvous_endpoint, router_config
    from robotmodel.signals import stop_on_signals

    stop = stop_on_signals()
    config = router_config(list(listen), list(connect))
    where = ", ".join(listen) or rendezvous_endpoint()
    # Claimed before the bind: of several routers of ours racing for one port only one tries,
    # and `--stop` finds a router that is still starting. A router elsewhere claims nothing.
    claim: int | None = None
    if _serves(config, rendezvous_port()):
        claim_path = router_claim()
        claim = _claim(claim_path)
        if claim is None:
            pid = _read_pid_of(claim_path)
            raise BusError(f"a router of ours already runs for port {rendezvous_port()}"
                           f"{f' (pid {pid})' if pid else ''}; `robotmodel router --stop` ends it")
    try:
        try:
            session = zenoh.open(config)
        except zenoh.ZError as exc:
            raise BusError(f"cannot start the router on {where}: {exc}") from exc
        try:
            # rmw_zenohd's start line.
            print(f"Started Zenoh router with id {session.zid()}.", flush=True)
            stop.wait()
        finally:
            session.close()  # type: ignore[no-untyped-call]
    finally:
        if claim is not None:
            os.close(claim)
    return 0


def _serves(config: zenoh.Config, port: int) -> bool:
    """Whether ``config`` listens on ``port`` (on any address)."""
    endpoints = json.loads(config.get_json("listen/endpoints"))
    if isinstance(endpoints, dict):  # per mode
        endpoints = endpoints.get("router", [])
    return any(re.split(r"[#?]", ep)[0].rsplit(":", 1)[-1] == str(port) for ep in endpoints)


def main() -> int:
    """The detached router's program: :func:`run_router` with one line on failure, as the CLI does."""
    try:
        return run_router()
    except BusError as exc:
        print(f"robotmodel router: {exc}", file=sys.stderr, flush=True)
        return 1


def _listening(port: int) -> bool:
    """Whether anything (ours, rmw_zenohd, another router) accepts on the loopback port."""
    try:
        with socket.create_connection(("127.0.0.1", port), timeout=1.0):
            return True
    except TimeoutError:
        return True  # there, but busy
    except OSError:
        return False


def ensure_router(port: int | None = None) -> None:
    """Start our router detached on the loopback ``port`` unless something listens there; BusError if it cannot.

    Several processes may find the port free at once: each starts one, one binds, the others
    exit, and all of them then find it listening.
    """
    port = rendezvous_port() if port is None else port
    if _listening(port):
        return
    claim = router_claim(port)
    log_path = claim.with_suffix(".log")
    proc = None if _held(claim) else _spawn(port, log_path)
    deadline = time.monotonic() + _START_TIMEOUT_S
    while time.monotonic() < deadline:
        if _listening(port):
            return
        # Ours exited: fine if another of ours holds the claim and is starting, else it failed.
        if proc is not None and proc.poll() is not None and not _held(claim) and not _listening(port):
            lines = log_path.read_text(errors="replace").strip().splitlines()
            raise BusError(f"cannot start a zenoh router on tcp/127.0.0.1:{port}: "
                           f"{lines[-1] if lines else f'it exited with {proc.returncode}'} (log: {log_path})")
        time.sleep(_POLL_S)
    raise BusError(f"no zenoh router listened on tcp/127.0.0.1:{port} within {_START_TIMEOUT_S:g} s "
                   f"(log: {log_path})")


def _spawn(port: int, log_path: Path) -> subprocess.Popen[bytes]:
    env = dict(os.environ, ROBOTMODEL_ZENOH_PORT=str(port))
    # Those configure this process's session; applied to the router they could move it off the port.
    for key in ("ZENOH_SESSION_CONFIG_URI", "ZENOH_CONFIG_OVERRIDE"):
        env.pop(key, None)
    # Appended to, never emptied while small: routers started at once share it, and the
    # winner's start line must stay.
    with contextlib.suppress(FileNotFoundError):
        if log_path.stat().st_size > _LOG_KEEP:
            log_path.unlink()
    with log_path.open("ab") as log_file:
        # Its own session: no terminal, and a Ctrl-C or a process-group kill meant for the tool spares it.
        proc = subprocess.Popen([sys.executable, "-c", _DETACHED], stdin=subprocess.DEVNULL, stdout=log_file,
                                stderr=subprocess.STDOUT, env=env, start_new_session=True, close_fds=True)
    _started.append(proc)
    return proc


def _held(path: Path) -> bool:
    """Whether a router of ours holds the claim ``path`` now."""
    try:
        fd = os.open(path, os.O_RDWR)
    except FileNotFoundError:
        return False
    try:
        return not _lock(fd)
    finally:
        os.close(fd)


def _read_pid_of(path: Path) -> int | None:
    try:
        text = path.read_text().strip()
    except OSError:
        return None
    return int(text) if text.isdigit() else None


def _read_pid(fd: int) -> int | None:
    # The router writes its pid just after it locks: give it a moment.
    end = time.monotonic() + 1.0
    while True:
        text = os.pread(fd, 32, 0).decode(errors="replace").strip()
        if text.isdigit():
            return int(text)
        if time.monotonic() > end:
            return None
        time.sleep(_POLL_S)


def _wait_locked(fd: int, timeout: float) -> bool:
    end = time.monotonic() + timeout
    while not _lock(fd):
        if time.monotonic() > end:
            return False
        time.sleep(_POLL_S)
    return True


def _gone(pid: int) -> bool:
    with contextlib.suppress(ChildProcessError):
        os.waitpid(pid, os.WNOHANG)  # ours: collect it
    try:
        stat = Path(f"/proc/{pid}/stat").read_text()
    except FileNotFoundError:
        return True
    except OSError:
        try:
            os.kill(pid, 0)
        except ProcessLookupError:
            return True
        return False
    return stat.rpartition(")")[2].split()[0] in ("Z", "X")  # a zombie has ended; its parent collects it


def stop_router(port: int | None = None) -> bool:
    """Stop our router on ``port`` (default: the rendezvous port); False if none of ours runs there.

    SIGTERM, as a service manager stops it; SIGKILL if it has not let go of its claim within
    10 s. Returns once its process has ended.
    """
    path = router_claim(port)
    try:
        fd = os.open(path, os.O_RDWR)
    except FileNotFoundError:
        return False
    try:
        if _lock(fd):
            return False
        pid = _read_pid(fd)
        if pid is None:
            raise BusError(f"the router's claim {path} names no process")
        with contextlib.suppress(ProcessLookupError):
            os.kill(pid, signal.SIGTERM)
        if not _wait_locked(fd, _STOP_TIMEOUT_S):
            with contextlib.suppress(ProcessLookupError):
                os.kill(pid, signal.SIGKILL)
            if not _wait_locked(fd, _STOP_TIMEOUT_S):
                raise BusError(f"the router (pid {pid}) did not stop")
    finally:
        os.close(fd)
    end = time.monotonic() + _STOP_TIMEOUT_S
    while not _gone(pid) and time.monotonic() < end:
        time.sleep(_POLL_S)
    for proc in list(_started):
        if proc.poll() is not None:
            _started.remove(proc)
    return True
