"""static_transform_publisher's command line: ROS 2 Jazzy's flags and positional forms, and ROS 1's.

Accepted forms (``words`` excludes the program name):

- ROS 2 flags: ``--x --y --z --qx --qy --qz --qw --roll --pitch --yaw --frame-id
  --child-frame-id`` (each takes one value) and ``-h``/``--help``;
- ROS 2's deprecated positional forms ``x y z yaw pitch roll frame child`` (8 words) and
  ``x y z qx qy qz qw frame child`` (9 words), which log ROS 2's deprecation warning;
- ROS 1 tf's ``x y z yaw pitch roll frame child period_ms`` (9 words whose 7th is not a
  number and whose last is) and ``x y z qx qy qz qw frame child period_ms`` (10 words),
  which republish on ``/tf`` every period, as ROS 1's tool does.

Numbers are read like ``std::stod``: a numeric prefix is accepted (``1.0abc`` is 1.0).
Errors carry ROS 2's texts; the caller prints them after
``error parsing command line arguments:``.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from typing import NamedTuple

from robotmodel.errors import StaticArgsError
from robotmodel.rcl._console import strtod_prefix

__all__ = [
    "DEPRECATION_WARNING",
    "HELP_MORE",
    "USAGE",
    "StaticTransformSpec",
    "parse_static_args",
    "rpy_quaternion",
    "startup_message",
    "validation_errors",
]

DEPRECATION_WARNING = "Old-style arguments are deprecated; see --help for new-style arguments"

USAGE = (
    "usage: static_transform_publisher [--x X] [--y Y] [--z Z] [--qx QX] [--qy QY] "
    "[--qz QZ] [--qw QW] [--roll ROLL] [--pitch PITCH] [--yaw YAW] --frame-id FRAME_ID "
    "--child-frame-id CHILD_FRAME_ID\n\n"
    "A command line utility for manually sending a static transform.\n\nIf no translation or"
    " orientation is provided, the identity transform will be published.\n\nThe translation offsets"
    " are in meters.\n\nThe rotation may be provided with roll, pitch, yaw euler angles in radians,"
    " or as a quaternion.\n\n"
    "required arguments:\n"
    "  --frame-id FRAME_ID parent frame\n"
    "  --child-frame-id CHILD_FRAME_ID child frame id\n\n"
    "optional arguments:\n"
    "  --x X                 x component of translation\n"
    "  --y Y                 y component of translation\n"
    "  --z Z                 z component of translation\n"
    "  --qx QX               x component of quaternion rotation\n"
    "  --qy QY               y component of quaternion rotation\n"
    "  --qz QZ               z component of quaternion rotation\n"
    "  --qw QW               w component of quaternion rotation\n"
    "  --roll ROLL           roll component Euler rotation\n"
    "  --pitch PITCH         pitch component Euler rotation\n"
    "  --yaw YAW             yaw component Euler rotation"
)

# tf2's tolerance on |q|^2 - 1 (QUATERNION_NORMALIZATION_TOLERANCE).
_QUAT_TOLERANCE = 10e-3

_FLOAT_FLAGS = ("--x", "--y", "--z", "--qx", "--qy", "--qz", "--qw", "--roll", "--pitch", "--yaw")
_STRING_FLAGS = ("--frame-id", "--child-frame-id")


class StaticTransformSpec(NamedTuple):
    """What to publish: ``child_frame_id``'s pose in ``frame_id``.

    ``period_ms`` is set for ROS 1 tf's forms (republish on ``/tf`` every period) and None
    otherwise (publish once, latched, on ``/tf_static``). ``help`` asks for the usage text.
    """

    translation: tuple[float, float, float] = (0.0, 0.0, 0.0)
    rotation: tuple[float, float, float, float] = (0.0, 0.0, 0.0, 1.0)
    frame_id: str = ""
    child_frame_id: str = ""
    period_ms: float | None = None
    help: bool = False


def rpy_quaternion(roll: float, pitch: float, yaw: float) -> tuple[float, float, float, float]:
    """tf2's ``Quaternion::setRPY``: R = Rz(yaw)·Ry(pitch)·Rx(roll), as (x, y, z, w)."""
    # Imported here: numpy is only needed once a command actually runs.
    from robotmodel.spatial import rpy_to_quat

    q = rpy_to_quat((roll, pitch, yaw))
    return float(q[0]), float(q[1]), float(q[2]), float(q[3])


def _number(name: str, word: str) -> float:
    parsed = strtod_prefix(word)
    if parsed is None:
        raise StaticArgsError(f"Failed to parse {name} argument as float")
    return float(parsed[0])


def _is_number(word: str) -> bool:
    parsed = strtod_prefix(word)
    return parsed is not None and parsed[1] == len(word)


def parse_static_args(words: Sequence[str], warn: Callable[[str], None]) -> StaticTransformSpec:
    """Parse the words after the program name; ``warn`` receives ROS 2's deprecation warning.

    Raises :class:`StaticArgsError` with ROS 2's text for any bad command line.
    """
    values: dict[str, float] = {}
    strings: dict[str, str] = {}
    positional: list[str] = []
    want_help = False
    i = 0
    while i < len(words):
        word = words[i]
        if word in ("-h", "--help"):
            want_help = True
        elif word in _FLOAT_FLAGS or word in _STRING_FLAGS:
            if i == len(words) - 1:
                raise StaticArgsError(f"Not enough arguments for {word}")
            i += 1
            if word in _FLOAT_FLAGS:
                values[word] = _number(word, words[i])
            else:
                strings[word] = words[i]
        else:
            positional.append(word)
        i += 1
    if want_help:
        return StaticTransformSpec(help=True)

    saw_quat = any(k in values for k in ("--qx", "--qy", "--qz", "--qw"))
    saw_rpy = any(k in values for k in ("--roll", "--pitch", "--yaw"))
    saw_trans = any(k in values for k in ("--x", "--y", "--z"))
    if saw_rpy and saw_quat:
        raise StaticArgsError("Cannot specify both quaternion and Euler rotations")
    translation = (values.get("--x", 0.0), values.get("--y", 0.0), values.get("--z", 0.0))
    if saw_rpy:
        rotation = rpy_quaternion(values.get("--roll", 0.0), values.get("--pitch", 0.0), values.get("--yaw", 0.0))
    else:
        rotation = (values.get("--qx", 0.0), values.get("--qy", 0.0), values.get("--qz", 0.0),
                    values.get("--qw", 1.0))
    frame_id = strings.get("--frame-id", "")
    child_frame_id = strings.get("--child-frame-id", "")
    period_ms: float | None = None

    count = len(positional)
    ros1_euler = count == 9 and not _is_number(positional[6]) and _is_number(positional[8])
    if count in (8, 9, 10):
        if count != 10 and not ros1_euler:
            warn(DEPRECATION_WARNING)
        if strings or saw_trans or saw_quat:
            raise StaticArgsError("Cannot specify both new-style (flags) and old-style (arguments)")
        translation = (_number("x", positional[0]), _number("y", positional[1]), _number("z", positional[2]))
        if count == 8 or ros1_euler:
            yaw = _number("yaw", positional[3])
            pitch = _number("pitch", positional[4])
            roll = _number("roll", positional[5])
            rotation = rpy_quaternion(roll, pitch, yaw)
            frame_id, child_frame_id = positional[6], positional[7]
        else:
            rotation = (_number("qx", positional[3]), _number("qy", positional[4]),
                        _number("qz", positional[5]), _number("qw", positional[6]))
            frame_id, child_frame_id = positional[7], positional[8]
        if count == 10 or ros1_euler:
            period_ms = _number("period", positional[-1])
            if not period_ms > 0.0:
                raise StaticArgsError("period(milliseconds) must be greater than 0")
    elif count:
        raise StaticArgsError("Extra unparsed arguments on command-line")

    if not frame_id:
        raise StaticArgsError("Frame id must not be empty")
    if not child_frame_id:
        raise StaticArgsError("Child frame id must not be empty")
    return StaticTransformSpec(translation, rotation, frame_id, child_frame_id, period_ms)


def validation_errors(spec: StaticTransformSpec, authority: str) -> list[str]:
    """The error lines a transform that tf2 would refuse gets, in tf2's texts; empty when valid.

    Equal frames give the ROS 2 node's own refusal; NaN (or infinite) values and a zero or
    non-unit quaternion give the TF_NAN_INPUT / TF_DENORMALIZED_QUATERNION texts every tf2
    listener would log on receiving them, so nothing is published that listeners drop.
    """
    if spec.frame_id == spec.child_frame_id:
        return [f"cannot publish static transform from '{spec.frame_id}' to '{spec.child_frame_id}', exiting"]
    errors = []
    x, y, z = spec.translation
    qx, qy, qz, qw = spec.rotation
    n2 = qx * qx + qy * qy + qz * qz + qw * qw
    shown = spec.rotation
    if n2 == 0.0:
        # tf2 turns a zero quaternion into NaN through its rotation matrix (2 / |q|^2).
        # The x86 default NaN has its sign bit set, so glibc prints it as -nan.
        shown = (-math.nan, -math.nan, -math.nan, -math.nan)
    rot = " ".join(_c_float(v) for v in shown)
    if not all(math.isfinite(v) for v in (x, y, z, *shown)):
        errors.append(f'TF_NAN_INPUT: Ignoring transform for child_frame_id "{spec.child_frame_id}" from '
                      f'authority "{authority}" because of a nan value in the transform '
                      f"({_c_float(x)} {_c_float(y)} {_c_float(z)}) ({rot})")
    if not abs(n2 - 1.0) < _QUAT_TOLERANCE:
        errors.append(f'TF_DENORMALIZED_QUATERNION: Ignoring transform for child_frame_id "{spec.child_frame_id}" '
                      f'from authority "{authority}" because of an invalid quaternion in the transform ({rot})')
    return errors


def _c_float(value: float) -> str:
    """Printf's ``%f``/``%lf`` (glibc spells NaN ``nan`` or ``-nan`` and infinity ``inf``)."""
    if math.isnan(value):
        return "-nan" if math.copysign(1.0, value) < 0 else "nan"
    if math.isinf(value):
        return "-inf" if value < 0 else "inf"
    return f"{value:f}"


def startup_message(spec: StaticTransformSpec) -> str:
    """ROS 2's INFO text once the transform is out (``Spinning until stopped - ...``)."""
    x, y, z = (_c_float(v) for v in spec.translation)
    qx, qy, qz, qw = (_c_float(v) for v in spec.rotation)
    return (f"Spinning until stopped - publishing transform\ntranslation: ('{x}', '{y}', '{z}')\n"
            f"rotation: ('{qx}', '{qy}', '{qz}', '{qw}')\nfrom '{spec.frame_id}' to '{spec.child_frame_id}'")

# Printed after ROS 2's own usage text on --help: the forms and words robotmodel takes beyond it.
HELP_MORE = """

also accepted:
  x y z yaw pitch roll frame_id child_frame_id
  x y z qx qy qz qw frame_id child_frame_id
                        ROS 2's deprecated positional forms (logged as deprecated)
  x y z yaw pitch roll frame_id child_frame_id period_in_ms
  x y z qx qy qz qw frame_id child_frame_id period_in_ms
                        ROS 1 tf's forms: republish on /tf every period_in_ms,
                        stamped one period ahead
  --connect ENDPOINT    zenoh endpoint to connect to (repeatable)
  --namespace NS        the node's namespace (/tf and /tf_static stay global)
  --ros-args ... [--]   ROS 2 arguments: -r /tf_static:=TOPIC remaps a topic,
                        -r __ns:=/NS and -r __node:=NAME move and rename the node;
                        -p NAME:=VALUE and --params-file FILE are named in a warning"""
