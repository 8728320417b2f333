"""A robot description as a file was at a git revision (``robotmodel diff --git REV FILE``).

A plain URDF needs its own text only (``git show REV:path``). A xacro file includes
others (``$(find pkg)/...``, relative paths) that must come from the same revision, so
the repository's tree at REV is exported (``git archive``, mesh files left out: no
expansion reads them) into a temporary folder and the file is loaded from there. The
folder is marked as a repository, so the package search stops at its top as it does for
the working copy; packages outside the repository come from ``--package-path``,
``ROS_PACKAGE_PATH`` and the ament index as usual. Messages name the file as ``REV:path``.
"""

from __future__ import annotations

import io
import os
import shutil
import subprocess
import tarfile
import tempfile
from collections.abc import Mapping, Sequence
from pathlib import Path

from robotmodel.errors import RevisionError, RobotModelError
from robotmodel.model import RobotDescription, load

__all__ = ["load_revision"]

# Never read by xacro: leaving them out keeps the export small in repositories full of meshes.
_MESH_SUFFIXES = ("stl", "dae", "obj", "ply", "glb", "gltf", "3ds", "fbx")


def _git(args: Sequence[str], cwd: Path, what: str, *, quiet: bool = False) -> bytes:
    """Run git; on failure raise RevisionError(``what``), with git's last line of stderr unless ``quiet``."""
    try:
        done = subprocess.run(["git", *args], cwd=cwd, capture_output=True, check=False)
    except FileNotFoundError:
        raise RevisionError(f"{what}: git is not installed") from None
    if done.returncode != 0:
        detail = done.stderr.decode(errors="replace").strip().splitlines()
        raise RevisionError(f"{what}: {detail[-1]}" if detail and not quiet else what)
    return done.stdout


def _locate(path: Path) -> tuple[Path, str]:
    """The repository's top folder and ``path`` relative to it (POSIX), for a file in a work tree."""
    folder = path.parent
    if not folder.is_dir():
        raise RevisionError(f"{path}: no such folder {folder}")
    top = Path(_git(["rev-parse", "--show-toplevel"], folder, f"{path}").decode().strip()).resolve()
    try:
        return top, path.relative_to(top).as_posix()
    except ValueError:
        raise RevisionError(f"{path}: not inside the repository at {top}") from None


def _export(top: Path, commit: str, into: Path) -> None:
    excluded = [f":(exclude,icase,glob)**/*.{suffix}" for suffix in _MESH_SUFFIXES]
    data = _git(["archive", "--format=tar", commit, "--", ".", *excluded], top, f"git archive {commit}")
    try:
        with tarfile.open(fileobj=io.BytesIO(data)) as archive:
            archive.extractall(into, filter=_inside)
    except (tarfile.TarError, OSError) as exc:
        raise RevisionError(f"git archive {commit}: cannot unpack: {exc}") from None


def _inside(member: tarfile.TarInfo, dest: str) -> tarfile.TarInfo | None:
    """The 'data' filter of tarfile, skipping (not failing on) what it refuses: a link out of the tree, a device."""
    try:
        return tarfile.data_filter(member, dest)
    except tarfile.FilterError:
        return None


def load_revision(
    path: str | os.PathLike[str], revision: str, args: Mapping[str, str] | None = None, *,
    package_paths: Sequence[str | os.PathLike[str]] = (), untrusted: bool = False,
) -> tuple[RobotDescription, str]:
    """Load ``path`` (a file in a git work tree) as it is at ``revision``; returns it and its label ``REV:path``.

    See the module documentation for how xacro includes are resolved. Raises
    :class:`~robotmodel.errors.RevisionError` when git cannot give the file (not a
    repository, unknown revision, path absent at that revision), and the loading errors of
    :func:`robotmodel.load` otherwise, their file names written ``REV:path``.
    """
    given = Path(path).absolute()
    # The folder resolved as git reports the top (through symlinks such as /tmp → /private/tmp).
    file = given.parent.resolve() / given.name
    top, relative = _locate(file)
    label = f"{revision}:{relative}"
    commit = _git(["rev-parse", "--verify", "--quiet", "--end-of-options", f"{revision}^{{commit}}"], top,
                  f"{label}: unknown revision '{revision}'", quiet=True).decode().strip()
    kind = _git(["cat-file", "-t", f"{commit}:{relative}"], top, f"{label}: no such file at revision '{revision}'",
                quiet=True)
    if kind.strip() != b"blob":
        raise RevisionError(f"{label}: not a file at revision '{revision}'")
    data = _git(["cat-file", "blob", f"{commit}:{relative}"], top, label)
    tmp = Path(tempfile.mkdtemp(prefix="robotmodel-diff-"))
    tree = tmp / "tree"
    try:
        target = tree / relative
        if b"xacro" in data or b"$(" in data:
            _export(top, commit, tree)
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_bytes(data)
        (tree / ".git").mkdir(exist_ok=True)
        try:
            return load(target, args, package_paths=package_paths, untrusted=untrusted), label
        except RobotModelError as exc:
            if len(exc.args) == 1 and isinstance(exc.args[0], str):
                exc.args = (exc.args[0].replace(f"{tree}{os.sep}", f"{revision}:"),)
            raise
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
