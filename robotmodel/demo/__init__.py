"""``robotmodel demo``: the whole pipeline on the bundled diffbot, every part a process on a private bus.

:func:`run_demo` starts and stops everything (one :class:`robotmodel.process.Supervisor`):
the recorder (MCAP), a static map → odom transform, robot_state_publisher and
joint_state_publisher on the diffbot (from xacro), the odometry example (``robot_controller``
and ``sensor_simulator``, whose wheel angles reach joint_state_publisher through
``--source-list /wheel_states``), a live ``tf2_echo map base_footprint``, ``view_frames``,
and the viewer following the robot, with a screenshot of it taken by headless Chromium when
one is installed. After the run, one offline question is answered from the recording with
``tf2-echo --bag``. Each child runs on the installed package, whatever the current directory.
"""

from __future__ import annotations

from robotmodel.demo._run import MAP_TO_ODOM, ROBOT, TOPICS, VIEWER_CAMERA, Demo, private_bus_env

__all__ = ["MAP_TO_ODOM", "ROBOT", "TOPICS", "VIEWER_CAMERA", "Demo", "private_bus_env", "run_demo"]


def run_demo(*, duration: float = 35.0, output: str | None = None, browser: bool = True,
             time_scale: float = 1.0) -> int:
    """Start everything, run for ``duration`` s (or until SIGINT/SIGTERM), stop everything, report; the exit code.

    Files go to ``output`` (None: ``./robotmodel-demo-<time>``; an existing folder must be
    empty). ``browser`` opens the viewer's page; ``time_scale`` runs the odometry example
    that many times faster than real time. Installs signal handlers (main thread only).
    """
    return Demo(duration=duration, output=output, browser=browser, time_scale=time_scale).run()
