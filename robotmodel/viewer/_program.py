"""``robotmodel view`` and ``joint-state-publisher-gui`` as programs: a :class:`ViewOptions` in, an exit code out.

- :func:`run_view`: with ``static_html``/``screenshot``, write those files (all or none) and
  return; else serve the page (:func:`robotmodel.viewer.serve_live`) until SIGINT/SIGTERM.
- :func:`run_joint_state_publisher_gui`: the page with publishing on, joint_state_publisher's
  ROS parameters applied (``zeros.JOINT`` as the sliders' start).
"""

from __future__ import annotations

import sys
from collections.abc import Mapping
from pathlib import Path
from typing import TYPE_CHECKING, Any

from robotmodel.errors import RobotModelError, RosArgsError
from robotmodel.kinematics import parse_joint_words
from robotmodel.viewer._options import ViewOptions, build_viewer, camera_spec, frames_spec, size_spec

if TYPE_CHECKING:
    from robotmodel.model import RobotDescription

__all__ = ["run_joint_state_publisher_gui", "run_view"]


def _load(options: ViewOptions) -> RobotDescription | None:
    from robotmodel.model import load_source

    if options.file is None:
        return None
    return load_source(options.file, options.mappings, package_paths=options.package_path,
                       untrusted=options.untrusted)[0]


def run_view(options: ViewOptions) -> int:
    """Build the viewer, then write files or serve until SIGINT/SIGTERM; returns the exit code."""
    from robotmodel.viewer._live import serve_live

    initial = parse_joint_words(list(options.joint))
    if options.track and not options.tf:
        raise RobotModelError("--track needs --tf (the frame's pose comes from /tf)")
    if options.camera is not None:
        camera_spec(options.camera)  # a bad value fails before the robot is loaded
    # With --tf, --frames picks the /tf frames drawn (rviz's TF display), not the robot's links.
    frames = "none" if options.tf else frames_spec(options.frames)
    if options.static_html or options.screenshot:
        if options.file is None:
            raise RobotModelError("--static-html and --screenshot need FILE")
        size = size_spec(options.size)
        desc = _load(options)
        assert desc is not None
        return _write_files(options, desc, initial, frames, size)
    return serve_live(options, _load(options), initial, frames)


def run_joint_state_publisher_gui(options: ViewOptions) -> int:
    """Serve the page with publishing on, joint_state_publisher's parameters applied; returns the exit code.

    The node is ``joint_state_publisher_gui`` unless renamed, as ROS's. On ROS 1 the parameters
    are read from the parameter server once the node is up, as ROS 1's reads them there.
    """
    from dataclasses import replace

    from robotmodel.publishers import jsp_settings
    from robotmodel.rcl import RosArgs, logger_name, node_params, ros1_wire, ros_log
    from robotmodel.viewer._live import serve_live

    name = options.node_name or "joint_state_publisher_gui"
    options = replace(options, node_name=name)
    ros = options.ros or RosArgs()
    initial = parse_joint_words(list(options.joint))
    if ros1_wire():
        from robotmodel.publishers._ros1params import private_params, ros1_jsp_settings

        def from_server(node: Any) -> dict[str, Any]:
            settings = ros1_jsp_settings(private_params(node, ros, options.namespace, name))
            initial.update(settings.pop("zeros"))  # before the page is built: the sliders start there
            return settings

        try:
            return serve_live(options, _load(options), initial, frames_spec(options.frames), publish=True,
                              jsp_options=from_server)
        except RosArgsError as exc:
            print(f"robotmodel joint-state-publisher-gui: error: {exc}", file=sys.stderr)
            return 2
    try:
        # joint_state_publisher_gui runs joint_state_publisher inside: the same parameters.
        settings = jsp_settings(node_params(ros, options.namespace, name),
                                lambda text: ros_log("WARN", logger_name(options.namespace, name), text))
    except RosArgsError as exc:
        print(f"robotmodel joint-state-publisher-gui: error: {exc}", file=sys.stderr)
        return 2
    initial.update(settings.pop("zeros"))  # zeros.JOINT wins over --joint, as a parameter over its flag
    return serve_live(options, _load(options), initial, frames_spec(options.frames), publish=True,
                      jsp_options=settings)


def _write_files(options: ViewOptions, desc: RobotDescription, initial: Mapping[str, float], frames: Any,
                 size: tuple[int, int]) -> int:
    from robotmodel._atomic import write_atomic, write_bytes_atomic
    from robotmodel.viewer._screenshot import screenshot_html

    viewer = build_viewer(options, desc, initial, frames, serve=False)
    html = viewer.static_html()
    png = screenshot_html(html, width=size[0], height=size[1]) if options.screenshot else None
    written = []
    try:
        if options.static_html:
            write_atomic(options.static_html, html)
            written.append(options.static_html)
        if png is not None and options.screenshot:
            write_bytes_atomic(options.screenshot, png)
            written.append(options.screenshot)
    except OSError as exc:
        for path in written:  # all or nothing
            Path(path).unlink(missing_ok=True)
        raise RobotModelError(f"cannot write {exc.filename or 'the output'}: {exc.strerror or exc}") from None
    for path in written:
        print(f"wrote {path}", file=sys.stderr)
    return 0
