"""The ROS executables robotmodel stands in for, by (package, executable), as ``ros2 run``/``rosrun`` name them.

One table serves ``robotmodel run`` (the command a pair runs) and the launcher (which nodes
of a launch file start, :mod:`robotmodel.launch._kinds`).
"""

from __future__ import annotations

from robotmodel.errors import CommandLineError

__all__ = ["JSP", "JSP_GUI", "RSP", "RVIZ", "STANDINS", "STATIC", "standin_command"]

RSP = frozenset({("robot_state_publisher", "robot_state_publisher"), ("robot_state_publisher", "state_publisher")})
JSP = frozenset({("joint_state_publisher", "joint_state_publisher")})
JSP_GUI = frozenset({("joint_state_publisher_gui", "joint_state_publisher_gui")})
STATIC = frozenset({("tf", "static_transform_publisher"), ("tf2_ros", "static_transform_publisher")})
RVIZ = frozenset({("rviz", "rviz"), ("rviz2", "rviz2")})
_ECHO = frozenset({("tf2_ros", "tf2_echo"), ("tf", "tf_echo"), ("tf2_tools", "echo.py")})
_VIEW_FRAMES = frozenset({("tf2_tools", "view_frames"), ("tf2_tools", "view_frames.py"), ("tf", "view_frames")})
_BAG = {("rosbag", verb): ("bag", verb) for verb in ("record", "play", "info")}

#: (package, executable) -> the robotmodel command words that stand in for it.
STANDINS: dict[tuple[str, str], tuple[str, ...]] = {
    **dict.fromkeys(RSP, ("robot-state-publisher",)),
    **dict.fromkeys(JSP, ("joint-state-publisher",)),
    **dict.fromkeys(JSP_GUI, ("joint-state-publisher-gui",)),
    **dict.fromkeys(STATIC, ("static-transform-publisher",)),
    **dict.fromkeys(RVIZ, ("view", "--follow")),
    **dict.fromkeys(_ECHO, ("tf2-echo",)),
    **dict.fromkeys(_VIEW_FRAMES, ("view-frames",)),
    ("xacro", "xacro"): ("xacro",),
    **_BAG,
}


def standin_command(package: str, executable: str) -> tuple[str, ...]:
    """The robotmodel command for ``package executable``; :class:`CommandLineError` naming the pair otherwise."""
    words = STANDINS.get((package, executable))
    if words is not None:
        return words
    executables = sorted(exe for pkg, exe in STANDINS if pkg == package)
    if executables:
        raise CommandLineError(f"No executable found: package '{package}' has no '{executable}' here "
                               f"(robotmodel stands in for: {', '.join(executables)})")
    packages = sorted({pkg for pkg, _ in STANDINS})
    raise CommandLineError(f"Package '{package}' not found (robotmodel stands in for executables of: "
                           f"{', '.join(packages)})")
