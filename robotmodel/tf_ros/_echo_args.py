"""tf2_echo's texts: its usage, its rate argument, each printed transform and its failure report.

The transform block is what ROS 2 Jazzy's ``tf2_echo`` writes with ``std::fixed`` and a
precision of 3; the RPY angles are tf2's ``Matrix3x3::getEulerYPR`` (first solution) of
the matrix built from the returned quaternion.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import NamedTuple

from robotmodel.errors import EchoArgsError
from robotmodel.rcl._console import strtod_prefix

__all__ = [
    "HELP_MORE",
    "USAGE",
    "EchoArgs",
    "euler_ypr",
    "failure_text",
    "format_echo",
    "parse_echo_args",
    "waiting_message",
]

USAGE = (
    "Usage: tf2_echo source_frame target_frame [echo_rate]\n\n"
    "This will echo the transform from the coordinate frame of the source_frame\n"
    "to the coordinate frame of the target_frame. \n"
    "Note: This is the transform to get data from target_frame into the source_frame.\n"
    "Default echo rate is 1 if echo_rate is not given.\n"
)

# Largest finite float32: std::stof reports anything beyond it as out of range.
_FLT_MAX = 3.4028234663852886e38


class EchoArgs(NamedTuple):
    """``tf2_echo SOURCE TARGET [RATE]``: prints TARGET's pose in SOURCE every 1/RATE s."""

    source_frame: str
    target_frame: str
    rate_hz: float = 1.0


def parse_echo_args(words: Sequence[str]) -> EchoArgs:
    """Parse the words after the program name as tf2_echo does.

    A wrong word count gives the usage on stdout and exit 1; a rate that is not a number
    gives ``Failed to convert rate argument ...`` on stderr and exit 2 (3 when a number is
    followed by junk, as ``std::stof`` reports it).
    """
    if len(words) == 2:
        return EchoArgs(words[0], words[1])
    if len(words) != 3:
        raise EchoArgsError(USAGE, 1, to_stdout=True)
    text = words[2]
    bad = f"Failed to convert rate argument '{text}' to a floating-point number"
    parsed = strtod_prefix(text)
    if parsed is None or (math.isfinite(parsed[0]) and abs(parsed[0]) > _FLT_MAX):
        raise EchoArgsError(bad, 2)
    if parsed[1] != len(text):
        raise EchoArgsError(bad, 3)
    rate = parsed[0]
    if not rate > 0.0 or math.isinf(rate):
        # rclcpp::Rate refuses these; say so in one line rather than abort.
        raise EchoArgsError("rate must be greater than 0", 1)
    return EchoArgs(words[0], words[1], rate)


def waiting_message(source_frame: str, target_frame: str, reason: str) -> str:
    """The throttled INFO text while the transform is not available yet."""
    return f"Waiting for transform {source_frame} ->  {target_frame}: {reason}"


def euler_ypr(m: Sequence[Sequence[float]]) -> tuple[float, float, float]:
    """tf2's ``Matrix3x3::getEulerYPR`` (solution 1) as (roll, pitch, yaw).

    At gimbal lock tf2 sets yaw to 0 and puts the shared angle into roll.
    """
    if abs(m[2][0]) >= 1:
        delta = math.atan2(m[2][1], m[2][2])
        pitch = math.pi / 2 if m[2][0] < 0 else -math.pi / 2
        return delta, pitch, 0.0
    pitch = -math.asin(m[2][0])
    c = math.cos(pitch)
    roll = math.atan2(m[2][1] / c, m[2][2] / c)
    yaw = math.atan2(m[1][0] / c, m[0][0] / c)
    return roll, pitch, yaw


def _f3(value: float) -> str:
    if math.isnan(value):
        return "-nan" if math.copysign(1.0, value) < 0 else "nan"
    return f"{value:.3f}"


def _cell(value: float) -> str:
    return " " + _f3(value).rjust(6)


def format_echo(sec: int, nanosec: int, translation: Sequence[float], rotation: Sequence[float]) -> str:
    """One printed transform, newline-terminated: At time, Translation, Rotation (3 forms), Matrix."""
    from robotmodel.spatial import quat_to_matrix

    x, y, z = (float(v) for v in translation)
    qx, qy, qz, qw = (float(v) for v in rotation)
    m = quat_to_matrix((qx, qy, qz, qw)).tolist()
    roll, pitch, yaw = euler_ypr(m)
    deg = 180.0 / math.pi
    lines = [
        f"At time {sec}.{nanosec}",
        f"- Translation: [{_f3(x)}, {_f3(y)}, {_f3(z)}]",
        f"- Rotation: in Quaternion [{_f3(qx)}, {_f3(qy)}, {_f3(qz)}, {_f3(qw)}]",
        f"- Rotation: in RPY (radian) [{_f3(roll)}, {_f3(pitch)}, {_f3(yaw)}]",
        f"- Rotation: in RPY (degree) [{_f3(roll * deg)}, {_f3(pitch * deg)}, {_f3(yaw * deg)}]",
        "- Matrix:",
    ]
    for row, t in zip(m, (x, y, z), strict=True):
        lines.append("".join(_cell(v) for v in row) + _cell(t))
    lines.append(_cell(0.0) * 3 + _cell(1.0))
    return "\n".join(lines) + "\n"


def failure_text(now_seconds: float, error: str, frames_as_string: str, fixed: bool) -> str:
    """What tf2_echo prints when a lookup in its loop fails.

    ``fixed`` is whether a transform was printed before: tf2_echo switches its stream to
    fixed notation with 3 decimals on its first success, and the time prints with the
    stream's default format (``%g``, 6 digits) until then.
    """
    when = f"{now_seconds:.3f}" if fixed else _cpp_default_float(now_seconds)
    return (f"Failure at {when}\nException thrown:{error}\nThe current list of frames is:\n"
            f"{frames_as_string}\n")


def _cpp_default_float(value: float) -> str:
    return f"{value:g}"

# Printed after tf2_echo's own usage text on --help: the words robotmodel takes beyond ROS's.
HELP_MORE = """
robotmodel also takes:
  --connect ENDPOINT   zenoh endpoint to connect to (repeatable)
  --namespace NS       the node's namespace (/tf and /tf_static stay global)
  --ros-args ... [--]  ROS 2 arguments: -r /tf:=TOPIC remaps a topic, -r __ns:=/NS and
                       -r __node:=NAME move and rename the node; -p NAME:=VALUE and
                       --params-file FILE are named in a warning (tf2_echo has no parameters)

From a recording instead of the bus (ROS 1 .bag, ROS 2 bag folder, .db3 or .mcap):
  tf2_echo --bag FILE source_frame target_frame [echo_rate] [--time T | --every DT] [--urdf FILE]
  --bag FILE           read TF from this recording
  --time T             the transform at T: seconds since the epoch, or +S for S seconds
                       after the first recorded transform (exit 1 if it cannot be looked up)
  --every DT           the transform every DT seconds of the recording
                       (default 1/echo_rate: once per recorded second)
  --urdf FILE          the robot whose /joint_states give TF when the recording has no /tf
                       (default: the recorded /robot_description)
  --no-progress        no progress bar on stderr
"""
