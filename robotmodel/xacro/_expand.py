"""Expand xacro documents to URDF text by running the ``xacro`` package in a child process."""

from __future__ import annotations

import json
import logging
import os
import signal
import subprocess
from collections.abc import Mapping, Sequence
from pathlib import Path

from robotmodel.errors import PackageNotFoundError, ResourceError, UntrustedInputError, XacroError
from robotmodel.process import module_argv, spawn
from robotmodel.resources import PathLike, record_package

__all__ = ["DEFAULT_MEMORY_BYTES", "DEFAULT_TIMEOUT_S", "dependencies", "expand", "expand_string"]

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
    verbosity: int = 1,
    root_dir: PathLike | None = None,
) -> str:
    """Expand the xacro (or URDF) file ``source`` into URDF XML text.

    The text is what the ``xacro`` command prints for the same file and ``name:=value``
    ``args``. ``$(find pkg)``, ``find()`` and ``package://`` includes resolve without ROS
    (see :func:`robotmodel.xacro.find_package`). ``untrusted`` refuses ``$(env)``,
    ``$(optenv)`` and reads outside the input's package roots. ``verbosity`` and
    ``root_dir`` mean what xacro's ``--verbosity`` and ``--root-dir`` mean; what xacro
    prints on stderr is logged as warnings of the ``robotmodel.xacro`` logger. Raises
    :class:`XacroError` naming the file.
    """
    return _run(_file_request(source, root_dir), str(source), args, package_paths, untrusted, timeout,
                memory_bytes, verbosity)


def dependencies(
    source: PathLike,
    args: Mapping[str, str] | None = None,
    *,
    package_paths: Sequence[PathLike] = (),
    untrusted: bool = False,
    timeout: float = DEFAULT_TIMEOUT_S,
    memory_bytes: int = DEFAULT_MEMORY_BYTES,
    verbosity: int = 1,
    root_dir: PathLike | None = None,
) -> list[str]:
    """The files ``source`` includes or loads (xacro's ``--deps``), each once, in first-use order.

    Paths are spelled as xacro records them: relative includes joined to the including
    file's folder, ``$(find)`` ones absolute. The document is expanded to find them, so
    its required arguments must be given.
    """
    request = _file_request(source, root_dir)
    request["deps"] = True
    deps = json.loads(_run(request, str(source), args, package_paths, untrusted, timeout, memory_bytes,
                           verbosity))
    return [str(d) for d in deps]


def _file_request(source: PathLike, root_dir: PathLike | None) -> dict[str, object]:
    path = Path(root_dir or ".") / source
    if not path.is_file():
        what = "is a directory" if path.is_dir() else "does not exist"
        raise XacroError(f"{source}: input file {what}")
    return {"path": os.fspath(source), "text": None, "base_dir": None,
            "root_dir": os.fspath(root_dir) if root_dir is not None else None}


def expand_string(
    text: str,
    args: Mapping[str, str] | None = None,
    *,
    base_dir: PathLike | None = None,
    package_paths: Sequence[PathLike] = (),
    untrusted: bool = False,
    timeout: float = DEFAULT_TIMEOUT_S,
    memory_bytes: int = DEFAULT_MEMORY_BYTES,
    verbosity: int = 1,
    name: str | None = None,
) -> str:
    """Expand xacro XML given as text; relative includes resolve against ``base_dir`` (default: cwd).

    With ``name`` the output starts with xacro's banner naming it, as for a file of that name.
    """
    base = os.fspath(base_dir) if base_dir is not None else os.getcwd()
    return _run(
        {"path": None, "text": text, "base_dir": base, "banner": name},
        name or "<string>", args, package_paths, untrusted, timeout, memory_bytes, verbosity,
    )


def _run(
    request: dict[str, object],
    label: str,
    args: Mapping[str, str] | None,
    package_paths: Sequence[PathLike],
    untrusted: bool,
    timeout: float,
    memory_bytes: int,
    verbosity: int,
) -> str:
    request.update(
        verbosity=verbosity,
        args=dict(args or {}),
        package_paths=[os.fspath(p) for p in package_paths],
        untrusted=untrusted,
        memory_bytes=memory_bytes,
        cwd=os.getcwd(),
    )
    # The installed package whatever the cwd (python -P); quiet on Ctrl-C, gone with its parent.
    proc = spawn(module_argv("robotmodel.xacro._worker", orphan_signal=signal.SIGKILL), stdin=subprocess.PIPE,
                 stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        stdout, stderr = (str(out) for out in proc.communicate(json.dumps(request), timeout=timeout))
    except subprocess.TimeoutExpired:
        proc.kill()
        proc.communicate()
        raise XacroError(
            f"{label}: expansion did not finish within {timeout:g} s (runaway macro recursion or expansion?)"
        ) from None
    error = None
    reply: dict[str, object] = {}
    for line in stderr.splitlines():
        if line.startswith('{"packages"'):
            for name, folder, how in json.loads(line)["packages"]:
                record_package(name, Path(folder), how)
        elif line.startswith('{"error"'):
            reply = json.loads(line)
            error = str(reply["error"])
        elif line.strip():
            _log.warning("%s", line)
    if proc.returncode == 0:
        return stdout
    if error is None:
        tail = stderr.strip().splitlines()[-1:] or [f"exit status {proc.returncode}"]
        if proc.returncode == -signal.SIGINT:
            error = "interrupted"
        elif "MemoryError" in stderr or proc.returncode < 0:
            error = f"expansion exceeded the memory limit of {memory_bytes >> 20} MiB"
        else:
            error = tail[0]
    if reply.get("kind") == "UntrustedInputError":
        raise UntrustedInputError(f"{label}: {error}")
    if reply.get("kind") == "PackageNotFoundError":
        searched = reply.get("searched")
        where = list(searched) if isinstance(searched, list) else []
        raise PackageNotFoundError(str(reply["package"]), where)
    if reply.get("kind") == "ResourceError":
        raise ResourceError(f"{label}: {error}")
    raise XacroError(f"{label}: {error}")
