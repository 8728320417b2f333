"""static_transform_publisher's command line against tf2_ros's (Jazzy) parser, as read in its source.

Expected rotations come from pytransform3d (extrinsic x-y-z: R = Rz(yaw)·Ry(pitch)·Rx(roll)),
not from our own code.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
import pytransform3d.rotations as pr

from robotmodel.errors import StaticArgsError
from robotmodel.tf_ros._static_args import (
    DEPRECATION_WARNING,
    USAGE,
    parse_static_args,
    startup_message,
    validation_errors,
)


def ref_quat(roll: float, pitch: float, yaw: float) -> np.ndarray:
    R = pr.matrix_from_euler([roll, pitch, yaw], 0, 1, 2, True)  # extrinsic x, y, z
    w, x, y, z = pr.quaternion_from_matrix(R)
    q = np.array([x, y, z, w])
    return q if q[3] >= 0 else -q


def parse(*words: str) -> tuple[object, list[str]]:
    warnings: list[str] = []
    spec = parse_static_args(list(words), warnings.append)
    return spec, warnings


def same_rotation(q, ref) -> None:
    q = np.asarray(q)
    assert np.allclose(q, ref, atol=1e-12) or np.allclose(q, -ref, atol=1e-12)


def test_new_style_flags_with_rpy():
    spec, warnings = parse("--x", "1", "--y", "2", "--z", "3", "--yaw", "0.5", "--pitch", "0.1", "--roll", "-1.0",
                           "--frame-id", "foo", "--child-frame-id", "bar")
    assert warnings == []
    assert spec.translation == (1.0, 2.0, 3.0)
    same_rotation(spec.rotation, ref_quat(-1.0, 0.1, 0.5))
    assert (spec.frame_id, spec.child_frame_id, spec.period_ms) == ("foo", "bar", None)


def test_flags_default_identity_and_quaternion_kept_as_given():
    spec, _ = parse("--frame-id", "a", "--child-frame-id", "b")
    assert spec.translation == (0.0, 0.0, 0.0) and spec.rotation == (0.0, 0.0, 0.0, 1.0)
    spec, _ = parse("--qz", "1", "--qw", "0", "--frame-id", "a", "--child-frame-id", "b")
    assert spec.rotation == (0.0, 0.0, 1.0, 0.0)


def test_old_style_eight_words_is_yaw_pitch_roll_and_warns():
    spec, warnings = parse("1", "2", "3", "0.5", "0.1", "-1.0", "foo", "bar")
    assert warnings == [DEPRECATION_WARNING]
    assert DEPRECATION_WARNING == "Old-style arguments are deprecated; see --help for new-style arguments"
    same_rotation(spec.rotation, ref_quat(-1.0, 0.1, 0.5))
    # The check value from ros2/geometry2 #443: (-0.475, -0.076, 0.240, 0.843).
    assert [round(v, 3) for v in spec.rotation] == [-0.475, -0.076, 0.240, 0.843]
    assert (spec.frame_id, spec.child_frame_id, spec.period_ms) == ("foo", "bar", None)


def test_old_style_nine_words_is_quaternion():
    spec, warnings = parse("1", "2", "3", "0", "0", "0.7071067811865476", "0.7071067811865476", "a", "b")
    assert warnings == [DEPRECATION_WARNING]
    assert spec.rotation == (0.0, 0.0, 0.7071067811865476, 0.7071067811865476)
    assert (spec.frame_id, spec.child_frame_id, spec.period_ms) == ("a", "b", None)


def test_ros1_forms_with_period():
    spec, warnings = parse("1", "2", "3", "0.5", "0.1", "-1.0", "foo", "bar", "100")
    assert warnings == []
    same_rotation(spec.rotation, ref_quat(-1.0, 0.1, 0.5))
    assert (spec.frame_id, spec.child_frame_id, spec.period_ms) == ("foo", "bar", 100.0)
    spec, warnings = parse("1", "2", "3", "0", "0", "0", "1", "foo", "bar", "50")
    assert warnings == []
    assert spec.rotation == (0.0, 0.0, 0.0, 1.0)
    assert (spec.frame_id, spec.child_frame_id, spec.period_ms) == ("foo", "bar", 50.0)


def test_numbers_read_like_stod():
    spec, _ = parse("--x", "1.5abc", "--y", " -2e1", "--z", "0x10", "--frame-id", "a", "--child-frame-id", "b")
    assert spec.translation == (1.5, -20.0, 16.0)
    spec, _ = parse("--x", "nan", "--frame-id", "a", "--child-frame-id", "b")
    assert math.isnan(spec.translation[0])


@pytest.mark.parametrize(("words", "message"), [
    # tf2_ros counts the program name, so its "Not enough arguments to parse" never shows.
    ((), "Frame id must not be empty"),
    (("--frame-id", "a", "--x"), "Not enough arguments for --x"),
    (("--x", "abc", "--frame-id", "a", "--child-frame-id", "b"), "Failed to parse --x argument as float"),
    (("--qx", "0", "--roll", "1", "--frame-id", "a", "--child-frame-id", "b"),
     "Cannot specify both quaternion and Euler rotations"),
    (("--x", "1", "1", "2", "3", "0", "0", "0", "a", "b"),
     "Cannot specify both new-style (flags) and old-style (arguments)"),
    (("1", "2", "3"), "Extra unparsed arguments on command-line"),
    (("--child-frame-id", "b"), "Frame id must not be empty"),
    (("--frame-id", "a"), "Child frame id must not be empty"),
    (("1", "2", "q", "0", "0", "0", "a", "b"), "Failed to parse z argument as float"),
    (("1", "2", "3", "0", "zz", "0", "a", "b"), "Failed to parse pitch argument as float"),
])
def test_errors_have_ros2_texts(words, message):
    with pytest.raises(StaticArgsError) as info:
        parse_static_args(list(words), lambda _text: None)
    assert str(info.value) == message


def test_old_style_warning_is_logged_before_the_mixing_error():
    warnings: list[str] = []
    with pytest.raises(StaticArgsError):
        parse_static_args(["--frame-id", "a", "1", "2", "3", "0", "0", "0", "a", "b"], warnings.append)
    assert warnings == [DEPRECATION_WARNING]


def test_help_wins_over_everything_else():
    spec, _ = parse("--x", "1", "-h")
    assert spec.help
    assert USAGE.startswith("usage: static_transform_publisher [--x X] [--y Y] [--z Z] [--qx QX] [--qy QY] "
                            "[--qz QZ] [--qw QW] [--roll ROLL] [--pitch PITCH] [--yaw YAW] --frame-id FRAME_ID "
                            "--child-frame-id CHILD_FRAME_ID\n")


def spec_of(*words: str):
    return parse_static_args(list(words), lambda _t: None)


def test_validation_same_frames():
    assert validation_errors(spec_of("--frame-id", "a", "--child-frame-id", "a"), "n") == [
        "cannot publish static transform from 'a' to 'a', exiting"]


def test_validation_nan_and_quaternions():
    nan = spec_of("--x", "nan", "--frame-id", "a", "--child-frame-id", "b")
    assert validation_errors(nan, "auth") == [
        'TF_NAN_INPUT: Ignoring transform for child_frame_id "b" from authority "auth" because of a nan value '
        "in the transform (nan 0.000000 0.000000) (0.000000 0.000000 0.000000 1.000000)"]
    denorm = spec_of("--qz", "1", "--qw", "1", "--frame-id", "a", "--child-frame-id", "b")
    assert validation_errors(denorm, "auth") == [
        'TF_DENORMALIZED_QUATERNION: Ignoring transform for child_frame_id "b" from authority "auth" because of '
        "an invalid quaternion in the transform (0.000000 0.000000 1.000000 1.000000)"]
    zero = spec_of("--qw", "0", "--frame-id", "a", "--child-frame-id", "b")
    errors = validation_errors(zero, "auth")
    assert [e.split(":")[0] for e in errors] == ["TF_NAN_INPUT", "TF_DENORMALIZED_QUATERNION"]
    # Inside tf2's tolerance on |q|^2 - 1 (0.01): accepted.
    assert validation_errors(spec_of("--qw", "1.004", "--frame-id", "a", "--child-frame-id", "b"), "x") == []


def test_startup_message():
    spec = spec_of("--x", "1", "--y", "2", "--z", "3", "--frame-id", "foo", "--child-frame-id", "bar")
    assert startup_message(spec) == (
        "Spinning until stopped - publishing transform\n"
        "translation: ('1.000000', '2.000000', '3.000000')\n"
        "rotation: ('0.000000', '0.000000', '0.000000', '1.000000')\n"
        "from 'foo' to 'bar'")
