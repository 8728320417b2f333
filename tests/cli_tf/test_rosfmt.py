"""Number parsing checked against the C library's own strtod; log lines; bus-option splitting."""

from __future__ import annotations

import ctypes
import ctypes.util
import math
import re

import pytest

from robotmodel.rcl import log_line, remove_ros_args
from robotmodel.rcl._console import strtod_prefix
from robotmodel.tf_ros._view_frames import default_output_name, result_message
from robotmodel.tf_ros._words import split_connect

_libc = ctypes.CDLL(ctypes.util.find_library("c"))
_libc.strtod.restype = ctypes.c_double
_libc.strtod.argtypes = [ctypes.c_char_p, ctypes.POINTER(ctypes.c_char_p)]


def c_strtod(text: str) -> tuple[float, int] | None:
    buf = ctypes.create_string_buffer(text.encode())
    end = ctypes.c_char_p()
    value = _libc.strtod(buf, ctypes.byref(end))
    used = ctypes.cast(end, ctypes.c_void_p).value - ctypes.addressof(buf)
    return None if used == 0 else (value, used)


@pytest.mark.parametrize("text", [
    "1", "-2.5", "+3.", ".5", "1e3", "1e", "1e+", "2E-2x", "  7", "\t-0", "1.0abc", "0x1A", "0x1.8p3", "0x",
    "inf", "-Infinity", "infin", "nan", "NaN(123)", "nanx", "abc", "", "-", ".", "e5", " +.e1", "12.34.56",
])
def test_strtod_prefix_agrees_with_libc(text):
    ours, theirs = strtod_prefix(text), c_strtod(text)
    if theirs is None:
        assert ours is None
        return
    assert ours is not None and ours[1] == theirs[1]
    assert (math.isnan(ours[0]) and math.isnan(theirs[0])) or ours[0] == theirs[0]


def test_log_line_shape():
    assert log_line("INFO", "tf2_echo", "hi", now_ns=1_716_697_697_040_514_000) == (
        "[INFO] [1716697697.040514000] [tf2_echo]: hi")
    assert log_line("WARN", "", "x", now_ns=5).startswith("[WARN] [0.000000005] []: ")


def test_bus_words():
    assert split_connect(["a", "--connect", "tcp/1.2.3.4:7447", "b", "--connect=tcp/x:1"]) == (
        ["a", "b"], ["tcp/1.2.3.4:7447", "tcp/x:1"])
    assert remove_ros_args(["--x", "1", "--ros-args", "-r", "__ns:=/r", "--", "--y", "2", "--ros-args", "-p", "a:=1"]) == [
        "--x", "1", "--y", "2"]


def test_view_frames_names_and_result():
    assert re.fullmatch(r"frames_\d{4}-\d\d-\d\d_\d\d\.\d\d\.\d\d", default_output_name())
    assert default_output_name(0.0).startswith("frames_19")
    assert result_message("a: \n  parent: 'w'\n") == (
        "Result:tf2_msgs.srv.FrameGraph_Response(frame_yaml=\"a: \\n  parent: 'w'\\n\")")
