"""tf2_echo's texts (Jazzy's tf2_echo.cpp, read in its source) and its RPY convention.

The expected block for ``1 2 3 0.5 0.1 -1.0 foo bar`` was worked out by hand from tf2's
formulas (documented in the project's tf2 reference); angles and matrices are checked
against pytransform3d.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
import pytransform3d.rotations as pr
from cli_tf.expected import EXPECTED_STATIC

from robotmodel.errors import EchoArgsError
from robotmodel.tf_ros._echo_args import (
    USAGE,
    EchoArgs,
    euler_ypr,
    failure_text,
    format_echo,
    parse_echo_args,
    waiting_message,
)


def test_static_example_block():
    R = pr.matrix_from_euler([-1.0, 0.1, 0.5], 0, 1, 2, True)
    w, x, y, z = pr.quaternion_from_matrix(R)
    assert format_echo(0, 0, (1.0, 2.0, 3.0), (x, y, z, w)) == EXPECTED_STATIC


def test_at_time_prints_nanoseconds_without_padding():
    text = format_echo(1778343184, 87549310, (0, 0, 0), (0, 0, 0, 1))
    assert text.splitlines()[0] == "At time 1778343184.87549310"


def test_rpy_matches_reference_away_from_gimbal_lock():
    rng = np.random.default_rng(7)
    for _ in range(200):
        roll, yaw = rng.uniform(-math.pi, math.pi, 2)
        pitch = rng.uniform(-1.5, 1.5)
        R = pr.matrix_from_euler([roll, pitch, yaw], 0, 1, 2, True)
        assert np.allclose(euler_ypr(R.tolist()), (roll, pitch, yaw), atol=1e-9)


def test_rpy_at_gimbal_lock_follows_tf2():
    R = pr.matrix_from_euler([0.0, math.pi / 2, 0.3], 0, 1, 2, True)
    R[2, 0] = -1.0  # exactly locked, as tf2 tests |m20| >= 1
    roll, pitch, yaw = euler_ypr(R.tolist())
    assert yaw == 0.0 and pitch == pytest.approx(math.pi / 2)
    # tf2 takes roll from the last row alone here (atan2(m21, m22)), even though at lock
    # that row no longer carries the angle: tf2_echo prints what tf2 computes.
    assert roll == math.atan2(R[2, 1], R[2, 2])


def test_matrix_rows_are_width_6_with_a_leading_space():
    text = format_echo(5, 0, (-10.25, 0.0, 123.456), (0, 0, 0, 1))
    rows = text.splitlines()[-4:]
    assert rows[0] == "  1.000  0.000  0.000 -10.250"
    assert rows[2] == "  0.000  0.000  1.000 123.456"


def test_parse_rate_and_usage():
    assert parse_echo_args(["a", "b"]) == EchoArgs("a", "b", 1.0)
    assert parse_echo_args(["a", "b", "10"]) == EchoArgs("a", "b", 10.0)
    assert parse_echo_args(["a", "b", " 2.5"]).rate_hz == 2.5
    with pytest.raises(EchoArgsError) as info:
        parse_echo_args(["a"])
    assert info.value.code == 1 and info.value.to_stdout and str(info.value) == USAGE
    assert USAGE.splitlines()[0] == "Usage: tf2_echo source_frame target_frame [echo_rate]"
    with pytest.raises(EchoArgsError) as info:
        parse_echo_args(["a", "b", "foo"])
    assert (info.value.code, str(info.value)) == (2, "Failed to convert rate argument 'foo' to a floating-point number")
    with pytest.raises(EchoArgsError) as info:
        parse_echo_args(["a", "b", "1.0foo"])
    assert info.value.code == 3


def test_waiting_and_failure_texts():
    assert waiting_message("foo", "bar", "why") == "Waiting for transform foo ->  bar: why"
    assert failure_text(1716697697.0406, "boom", "Frame b exists with parent a.\n", fixed=True) == (
        "Failure at 1716697697.041\nException thrown:boom\nThe current list of frames is:\n"
        "Frame b exists with parent a.\n\n")
    assert failure_text(1716697697.0405, "boom", "", fixed=False).splitlines()[0] == "Failure at 1.7167e+09"
