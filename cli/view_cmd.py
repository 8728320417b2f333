"""``robotmodel view``: the robot in the browser (meshcat), with joint sliders, frames and live modes."""

from __future__ import annotations

import argparse
import math
import os
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

from robotmodel.cli._common import add_mapping_arguments, joint_values
from robotmodel.cli._node_args import add_node_arguments

from robotmodel.errors import RobotModelError


def add_viewer_arguments(parser: argparse.ArgumentParser, *, live_flags: bool = True) -> None:
    """The arguments ``view`` and ``joint-state-publisher-gui`` share."""
    add_mapping_arguments(parser)
    parser.add_argument("file", metavar="FILE", nargs="?",
                        help="a .urdf or .xacro file ('-' reads stdin; default: the robot_description topic)")
    parser.add_argument("--package-path", action="append", default=[], metavar="DIR",
                        help="search DIR first for ROS packages ($(find pkg), package://); repeatable")
    parser.add_argument("--untrusted", action="store_true",
                        help="refuse $(env), $(optenv) and reads outside the input's package roots")
    parser.add_argument("--port", type=int, default=None,
                        help="serve on this port of 127.0.0.1 (default: 7000, or the next free one)")
    parser.add_argument("--open", action="store_true", help="open the page in the default web browser")
    parser.add_argument("--collisions", action="store_true", help="show collision geometry too")
    parser.add_argument("--frames", default=None, metavar="all|none|LINK,...",
                        help="draw these links' frames as named axes (default: none); with --tf, these "
                             "frames from /tf (default: all)")
    parser.add_argument("--camera", metavar="X,Y,Z[:TX,TY,TZ]",
                        help="put the camera at X,Y,Z looking at TX,TY,TZ (default 0,0,0): metres in the "
                             "scene's frame (the fixed frame), Z up; write --camera=-1,... when X is negative")
    parser.add_argument("--joint", action="append", default=[], metavar="NAME=VALUE",
                        help="initial joint value (radians or metres); repeatable")
    parser.add_argument("--no-cache", action="store_true", help="convert meshes again, ignoring the disk cache")
    parser.add_argument("--connect", action="append", default=[], metavar="ENDPOINT",
                        help="zenoh endpoint to connect to (e.g. tcp/192.168.1.10:7447); repeatable")
    if live_flags:
        parser.add_argument("--follow", action="store_true",
                            help="draw the robot from /joint_states on the bus")
        parser.add_argument("--tf", action="store_true", help="draw the frames on /tf and /tf_static")
        parser.add_argument("--fixed-frame", metavar="FRAME",
                            help="the frame --tf draws from, as rviz's Fixed Frame (default: the robot's root)")
        parser.add_argument("--track", metavar="FRAME",
                            help="with --tf: the camera follows FRAME, keeping its offset (and any orbit or "
                                 "zoom done in the page)")
        parser.add_argument("--publish", action="store_true", help="publish the sliders' values on /joint_states")
    add_node_arguments(parser, "robotmodel_view")


def register(sub: Any) -> None:
    """Add the ``view`` subcommand."""
    parser: argparse.ArgumentParser = sub.add_parser(
        "view", help="show the robot in the browser, with joint sliders (meshcat)",
        description="Serve a page on 127.0.0.1 showing the robot's visuals (meshes included), one slider "
        "per movable joint (as joint_state_publisher_gui), and frames as named axes. With --static-html or "
        "--screenshot it writes the file and exits instead. Runs until Ctrl-C.",
    )
    add_viewer_arguments(parser)
    parser.add_argument("--static-html", metavar="OUT.html",
                        help="write one self-contained page of the robot (offline-viewable) and exit")
    parser.add_argument("--screenshot", metavar="OUT.png",
                        help="render the robot with headless Chromium to a PNG and exit")
    parser.add_argument("--size", default="1280x800", metavar="WxH", help="screenshot size (default 1280x800)")
    parser.set_defaults(func=run)


def frames_spec(text: str | None) -> str | list[str]:
    """``all``, ``none`` (also when not given) or a comma-separated list of links."""
    if text is None:
        return "none"
    if text in ("all", "none"):
        return text
    return [name.strip() for name in text.split(",") if name.strip()]


#: x, y, z in metres, in the scene's (the fixed frame's) coordinates.
Point = tuple[float, float, float]


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


def _write_bytes_atomic(path: str, data: bytes) -> None:
    target = Path(path)
    target.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(prefix=f".{target.name}.", dir=target.parent)
    try:
        with os.fdopen(fd, "wb") as f:
            f.write(data)
        Path(tmp).chmod(0o644)
        os.replace(tmp, target)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise


def _size(text: str) -> tuple[int, int]:
    w, sep, h = text.lower().partition("x")
    try:
        width, height = int(w), int(h)
    except ValueError:
        width = height = 0
    if not sep or width <= 0 or height <= 0:
        raise RobotModelError(f"--size expects WIDTHxHEIGHT, got '{text}'")
    return width, height


def _load(args: argparse.Namespace) -> Any:
    from robotmodel.cli._common import load_description

    desc, _ = load_description(args)
    return desc


def run(args: argparse.Namespace) -> int:
    """Build the viewer, then write files or serve until Ctrl-C."""
    from robotmodel.cli._live import serve_live

    initial = joint_values(args.joint)
    if getattr(args, "track", None) and not getattr(args, "tf", False):
        raise RobotModelError("--track needs --tf (the frame's pose comes from /tf)")
    if args.camera is not None:
        camera_spec(args.camera)  # a bad value fails before the robot is loaded
    # With --tf, --frames picks the /tf frames drawn (rviz's TF display), not the robot's links.
    frames = "none" if getattr(args, "tf", False) else frames_spec(args.frames)
    static = bool(getattr(args, "static_html", None) or getattr(args, "screenshot", None))
    if static:
        if args.file is None:
            raise RobotModelError("--static-html and --screenshot need FILE")
        size = _size(args.size)
        return _write_files(args, _load(args), initial, frames, size)
    desc = _load(args) if args.file is not None else None
    code: int = serve_live(args, desc, initial, frames)
    return code


def make_viewer(args: argparse.Namespace, desc: Any, initial: dict[str, float], frames: Any, *,
                serve: bool) -> Any:
    """A Viewer for ``desc`` with the command's options (progress bar, cache, frames, joints)."""
    from robotmodel.viewer import Viewer

    progress = _Progress()
    cache = Path(tempfile.mkdtemp(prefix="robotmodel-nocache-")) if args.no_cache else None
    viewer = Viewer(desc, serve=serve, port=args.port, package_paths=args.package_path, cache_dir=cache,
                    progress=progress, collisions=args.collisions, frames=frames)
    if args.camera is not None:
        viewer.set_camera(*camera_spec(args.camera))
    if initial:
        viewer.display(initial)
    scene = viewer.scene
    if progress.total:
        print(f"loaded {scene.meshes_loaded} meshes ({scene.meshes_cached} from the cache) in "
              f"{time.monotonic() - progress.start:.2f} s", file=sys.stderr)
    if cache is not None:
        import shutil

        shutil.rmtree(cache, ignore_errors=True)
    return viewer


def _write_files(args: argparse.Namespace, desc: Any, initial: dict[str, float], frames: Any,
                 size: tuple[int, int]) -> int:
    from robotmodel.cli._common import write_atomic

    from robotmodel.viewer import screenshot_html

    viewer = make_viewer(args, desc, initial, frames, serve=False)
    html = viewer.static_html()
    png = screenshot_html(html, width=size[0], height=size[1]) if args.screenshot else None
    written = []
    try:
        if args.static_html:
            write_atomic(args.static_html, html)
            written.append(args.static_html)
        if png is not None:
            _write_bytes_atomic(args.screenshot, png)
            written.append(args.screenshot)
    except OSError as exc:
        for path in written:  # all or nothing
            Path(path).unlink(missing_ok=True)
        raise RobotModelError(f"cannot write {exc.filename or 'the output'}: {exc.strerror or exc}") from None
    for path in written:
        print(f"wrote {path}", file=sys.stderr)
    return 0
