"""view_frames as a program (``robotmodel view-frames``): listen to TF, then draw the frame tree.

As ROS 2 Jazzy's tf2_tools view_frames: listens for ``--wait-time`` seconds (default 5),
logs the frames YAML in its ``Result:`` line, and writes ``frames_<YYYY-MM-DD_HH.MM.SS>.gv``
(local time) or ``NAME.gv`` with ``-o NAME``, then the PDF with graphviz's ``dot`` when it
is installed. It also writes the frames YAML next to them as ``NAME.yaml``.

With ``--bag FILE`` it draws the tree of a recording instead (no listening): every frame
with its newest parent, rates and spans over the whole recording.

ROS time: the legend's ``Recorded at time`` is the node's clock, ``/clock`` under sim time
(``--ros-args -p use_sim_time:=true`` on the ROS 2 wires, ``/use_sim_time`` on ROS 1), so a
tree drawn from ``bag play --clock`` is dated in the recording. The listening window is what
each ROS's view_frames waits: wall seconds on ROS 2 (its ``time.time()`` loop), ROS-time
seconds on ROS 1 (``rospy.sleep``: from the first ``/clock`` on, cut short by a jump back).
Its buffer is cleared on a jump back, as tf2_ros's buffer with the node's clock is.
"""

from __future__ import annotations

import sys
import time
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING

from robotmodel._atomic import write_atomic
from robotmodel.rcl import ros_log
from robotmodel.signals import stop_on_signals

if TYPE_CHECKING:
    import threading

    from robotmodel.rcl import RosArgs
    from robotmodel.time import Clock

__all__ = ["default_output_name", "result_message", "run_view_frames"]

_NODE = "view_frames"


def default_output_name(now: float | None = None) -> str:
    """``frames_<YYYY-MM-DD_HH.MM.SS>`` in local time, view_frames' name without ``-o``."""
    return "frames_" + time.strftime("%Y-%m-%d_%H.%M.%S", time.localtime(now))


def result_message(frames_yaml: str) -> str:
    """The ``Result:`` log text: the FrameGraph service response as rclpy prints it."""
    return f"Result:tf2_msgs.srv.FrameGraph_Response(frame_yaml={frames_yaml!r})"


def _ros1_sleep(clock: Clock, seconds: float, stop: threading.Event) -> None:
    """``rospy.sleep(seconds)`` in ``clock``'s time: from the first /clock on, ended by a jump back or ``stop``."""
    from robotmodel.bus import TopicClock
    from robotmodel.time import Duration

    if not isinstance(clock, TopicClock):
        stop.wait(seconds)
        return
    if not clock.wait_for_valid(stop):
        return
    start = clock.now()
    until = start + Duration(seconds=seconds)
    step = Duration(seconds=0.1)
    while not stop.is_set() and not clock.sleep_until(until, step) and clock.now() >= start:
        pass


def run_view_frames(*, wait_time: float = 5.0, output: str | None = None, connect: Sequence[str] = (),
                    namespace: str = "/", ros: RosArgs | None = None, bag: str | None = None,
                    urdf: str | None = None, progress: bool | None = None) -> int:
    """Run view_frames: listen for ``wait_time`` s (or read ``bag``), then write the .gv (and .pdf, .yaml).

    ``output`` is the base name (default ``frames_<date>``); ``ros`` the node's ``--ros-args``
    settings (name, remaps, ignored parameters); ``urdf`` and ``progress`` apply to ``bag``
    (see :func:`robotmodel.recording.load_recording`). Returns the exit code; listening ends
    early on SIGINT/SIGTERM (installs handlers: main thread only).
    """
    from robotmodel.rcl import RosArgs

    ros = ros or RosArgs()
    if not wait_time >= 0.0:
        print("robotmodel view-frames: error: --wait-time must be >= 0", file=sys.stderr)
        return 2
    from robotmodel.tf import Buffer, write_view_frames

    if bag is not None:
        from robotmodel.recording import load_recording

        loaded = load_recording(bag, robot=urdf, progress=progress)
        buffer: Buffer = loaded.buffer
        now_ns = loaded.end_ns or time.time_ns()
    else:
        stop = stop_on_signals()
        from robotmodel.bus import Node, node_clock
        from robotmodel.rcl import logger_name, node_params, warn_ignored_params
        from robotmodel.tf_ros._jump import clear_on_jump_back
        from robotmodel.tf_ros._listener import TransformListener

        buffer = Buffer()
        node_name = ros.node_name or _NODE
        warn_ignored_params(ros, namespace, node_name, used=("use_sim_time",))
        use_sim_time = node_params(ros, namespace, node_name).get("use_sim_time") is True
        # /tf and /tf_static are absolute: the namespace names the node only, as in ROS.
        with Node(node_name, namespace, connect=list(connect), remappings=ros.remaps) as node, \
                TransformListener(buffer, node):
            # ROS time: /clock with use_sim_time (ROS 1's /use_sim_time, ROS 2's parameter)
            clock = node_clock(node, use_sim_time)
            on_ros1 = node.context.backend.name == "ros1"
            clear_on_jump_back(buffer, clock, logger_name(namespace, node_name), ros1=on_ros1)
            ros_log("INFO", _NODE, f"Listening to tf data for {wait_time} seconds...")
            if on_ros1:
                _ros1_sleep(clock, wait_time, stop)
            else:
                stop.wait(wait_time)
            now_ns = clock.now().nanoseconds
    ros_log("INFO", _NODE, "Generating graph...")
    frames_yaml = buffer.all_frames_as_yaml()
    ros_log("INFO", _NODE, result_message(frames_yaml))
    name = output if output is not None else default_output_name()
    ros_log("INFO", _NODE, f"Exporting graph in {name}.pdf file...")
    _gv, pdf = write_view_frames(buffer, name, now_ns)
    write_atomic(Path(f"{name}.yaml"), frames_yaml if frames_yaml.endswith("\n") or not frames_yaml
                 else frames_yaml + "\n")
    if pdf is None:
        print(f"dot (graphviz) is not installed: {name}.pdf was not created", file=sys.stderr)
    return 0
