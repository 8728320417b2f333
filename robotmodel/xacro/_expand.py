"""Expand xacro documents to URDF text by running the ``xacro`` package in a child process."""

from __future__ import annotations

import json
import logging
import os
import subprocess
import sys
from collections.abc import Mapping, Sequence
from pathlib import Path

from robotmodel.errors import PackageNotFoundError, UntrustedInputError, XacroError
from robotmodel.xacro._packages import PathLike

__all__ = ["DEFAULT_MEMORY_BYTES", "DEFAULT_TIMEOUT_S", "expand", "expand_string"]

_log = logging.getLogger("robotmodel.xacro")

#: Wall-clock limit for one expansion; runaway macros stop here.
DEFAULT_TIMEOUT_S = 10.0
#: Address-space limit of the expanding process.
DEFAULT_MEMORY_BYTES = 1 << 30


def expand(
    source: PathLike,
    args: Mapping[str, str] | None = None,
    *,
    package_paths: Sequence[PathLike] = (),
    untrusted: bool = False,
    timeout: float = DEFAULT_TIMEOUT_S,
    memory_bytes: int = DEFAULT_MEMORY_BYTES,
) -> str:
    """Expand the xacro (or URDF) file ``source`` into URDF XML text.

    The text is what the ``xacro`` command prints for the same file and ``name:=value``
    ``args``. ``$(find pkg)``, ``find()`` and ``package://`` includes resolve without ROS
    (see :func:`robotmodel.xacro.find_package`). ``untrusted`` refuses ``$(env)``,
    ``$(optenv)`` and reads outside the input's package roots. Raises
    :class:`XacroError` naming the file.
    """
    path = Path(source)
    if not path.is_file():
        what = "is a directory" if path.is_dir() else "does not exist"
        raise XacroError(f"{path}: input file {what}")
    return _run(
        {"path": os.fspath(source), "text": None, "base_dir": None},
        str(path), args, package_paths, untrusted, timeout, memory_bytes,
    )


def expand_string(
    text: str,
    args: Mapping[str, str] | None = None,
    *,
    base_dir: PathLike | None = None,
    package_paths: Sequence[PathLike] = (),
    untrusted: bool = False,
    timeout: float = DEFAULT_TIMEOUT_S,
    memory_bytes: int = DEFAULT_MEMORY_BYTES,
) -> str:
    """Expand xacro XML given as text; relative includes resolve against ``base_dir`` (default: cwd)."""
    base = os.fspath(base_dir) if base_dir is not None else os.getcwd()
    return _run(
        {"path": None, "text": text, "base_dir": base},
        "<string>", args, package_paths, untrusted, timeout, memory_bytes,
    )


def _run(
    request: dict[str, object],
    label: str,
    args: Mapping[str, str] | None,
    package_paths: Sequence[PathLike],
    untrusted: bool,
    timeout: float,
    memory_bytes: int,
) -> str:
    request.update(
        args=dict(args or {}),
        package_paths=[os.fspath(p) for p in package_paths],
        untrusted=untrusted,
        memory_bytes=memory_bytes,
        cwd=os.getcwd(),
    )
    try:
        proc = subprocess.run(
            [sys.executable, "-m", "robotmodel.xacro._worker"],
            input=json.dumps(request),
            capture_output=True,
            text=True,
            timeout=timeout,
            check=False,
        )
    except subprocess.TimeoutExpired:
        raise XacroError(
            f"{label}: expansion did not finish within {timeout:g} s (runaway macro recursion or expansion?)"
        ) from None
    error = None
    reply: dict[str, object] = {}
    for line in proc.stderr.splitlines():
        if line.startswith('{"error"'):
            reply = json.loads(line)
            error = str(reply["error"])
        elif line.strip():
            _log.warning("%s", line)
    if proc.returncode == 0:
        return proc.stdout
    if error is None:
        tail = proc.stderr.strip().splitlines()[-1:] or [f"exit status {proc.returncode}"]
        if "MemoryError" in proc.stderr or proc.returncode < 0:
            error = f"expansion exceeded the memory limit of {memory_bytes >> 20} MiB"
        else:
            error = tail[0]
    if reply.get("kind") == "UntrustedInputError":
        raise UntrustedInputError(f"{label}: {error}")
    if reply.get("kind") == "PackageNotFoundError":
        searched = reply.get("searched")
        where = list(searched) if isinstance(searched, list) else []
        raise PackageNotFoundError(str(reply["package"]), where)
    raise XacroError(f"{label}: {error}")
