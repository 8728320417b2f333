"""The ``view`` command's options as values: frames, camera and size texts, and building the Viewer they ask for."""

from __future__ import annotations

import math
import sys
import tempfile
import time
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

from robotmodel.errors import RobotModelError

if TYPE_CHECKING:
    from robotmodel.model import RobotDescription
    from robotmodel.rcl import RosArgs
    from robotmodel.viewer._viewer import Viewer

__all__ = ["ViewOptions", "build_viewer", "camera_spec", "frames_spec", "size_spec"]

#: x, y, z in metres, in the scene's (the fixed frame's) coordinates.
Point = tuple[float, float, float]


@dataclass
class ViewOptions:
    """What ``robotmodel view`` (and ``joint-state-publisher-gui``) is asked for; field names are its options'.

    ``file`` None takes the robot from ``/robot_description``; ``joint`` holds ``NAME=VALUE``
    words; ``ros`` the node's ``--ros-args`` settings (:mod:`robotmodel.rcl`).
    """

    file: str | None = None
    mappings: Mapping[str, str] = field(default_factory=dict)
    package_path: Sequence[str] = ()
    untrusted: bool = False
    port: int | None = None
    open: bool = False
    collisions: bool = False
    frames: str | None = None
    camera: str | None = None
    joint: Sequence[str] = ()
    no_cache: bool = False
    connect: Sequence[str] = ()
    follow: bool = False
    tf: bool = False
    fixed_frame: str | None = None
    track: str | None = None
    publish: bool = False
    namespace: str = "/"
    node_name: str | None = None
    ros: RosArgs | None = None
    static_html: str | None = None
    screenshot: str | None = None
    size: str = "1280x800"


def frames_spec(text: str | None) -> str | list[str]:
    """``all``, ``none`` (also when not given) or a comma-separated list of links."""
    if text is None:
        return "none"
    if text in ("all", "none"):
        return text
    return [name.strip() for name in text.split(",") if name.strip()]


def camera_spec(text: str) -> tuple[Point, Point]:
    """``X,Y,Z`` or ``X,Y,Z:TX,TY,TZ`` to (position, target); the target defaults to the origin."""
    bad = f"--camera expects X,Y,Z or X,Y,Z:TX,TY,TZ (metres), got '{text}'"
    points: list[Point] = []
    for part in text.split(":"):
        try:
            values = [float(v) for v in part.split(",")]
        except ValueError:
            raise RobotModelError(bad) from None
        if len(values) != 3 or not all(math.isfinite(v) for v in values):
            raise RobotModelError(bad)
        points.append((values[0], values[1], values[2]))
    if len(points) == 1:
        points.append((0.0, 0.0, 0.0))
    if len(points) != 2:
        raise RobotModelError(bad)
    if points[0] == points[1]:
        raise RobotModelError(f"--camera {text}: the camera cannot stand on the point it looks at")
    return points[0], points[1]


def size_spec(text: str) -> tuple[int, int]:
    """``WIDTHxHEIGHT`` (pixels) to (width, height)."""
    w, sep, h = text.lower().partition("x")
    try:
        width, height = int(w), int(h)
    except ValueError:
        width = height = 0
    if not sep or width <= 0 or height <= 0:
        raise RobotModelError(f"--size expects WIDTHxHEIGHT, got '{text}'")
    return width, height


class _Progress:
    """A mesh-loading bar on stderr (only on a terminal), and one summary line."""

    def __init__(self) -> None:
        self.tty = sys.stderr.isatty()
        self.start = time.monotonic()
        self.total = 0

    def __call__(self, done: int, total: int, label: str) -> None:
        self.total = total
        if not self.tty or total == 0:
            return
        width = 30
        filled = width * done // total
        sys.stderr.write(f"\rmeshes [{'#' * filled}{'.' * (width - filled)}] {done}/{total} {label[:40]:<40}")
        if done == total:
            sys.stderr.write("\r" + " " * (width + 60) + "\r")
        sys.stderr.flush()


def build_viewer(options: ViewOptions, desc: RobotDescription, initial: Mapping[str, float], frames: Any, *,
                 serve: bool) -> Viewer:
    """A Viewer for ``desc`` with the options (mesh progress on stderr, cache, frames, camera, joints)."""
    from robotmodel.viewer._viewer import Viewer

    progress = _Progress()
    cache = Path(tempfile.mkdtemp(prefix="robotmodel-nocache-")) if options.no_cache else None
    viewer = Viewer(desc, serve=serve, port=options.port, package_paths=options.package_path, cache_dir=cache,
                    progress=progress, collisions=options.collisions, frames=frames)
    if options.camera is not None:
        viewer.set_camera(*camera_spec(options.camera))
    if initial:
        viewer.display(dict(initial))
    scene = viewer.scene
    if progress.total:
        print(f"loaded {scene.meshes_loaded} meshes ({scene.meshes_cached} from the cache) in "
              f"{time.monotonic() - progress.start:.2f} s", file=sys.stderr)
    if cache is not None:
        import shutil

        shutil.rmtree(cache, ignore_errors=True)
    return viewer
