"""Bad command lines: ROS's texts, non-zero exits, and nothing opened on the bus."""

from __future__ import annotations

import re

import pytest
from robotmodel.cli.main import main

from robotmodel.tf_ros._static_args import USAGE as STATIC_USAGE

LOG = r"^\[(ERROR|WARN|INFO)\] \[\d+\.\d{9}\] \[([^\]]*)\]: (.*)$"


def run(capsys, *argv):
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def log_records(err):
    return [re.match(LOG, line).groups() for line in err.splitlines() if re.match(LOG, line)]


def test_same_frames(capsys):
    code, out, err = run(capsys, "static-transform-publisher", "--frame-id", "a", "--child-frame-id", "a")
    assert code == 1 and out == ""
    [(severity, logger, message)] = log_records(err)
    assert severity == "ERROR" and re.fullmatch(r"static_transform_publisher_[0-9A-Za-z]{16}", logger)
    assert message == "cannot publish static transform from 'a' to 'a', exiting"


@pytest.mark.parametrize(("words", "kinds"), [
    (("--qw", "0"), ["TF_NAN_INPUT", "TF_DENORMALIZED_QUATERNION"]),
    (("--qx", "1", "--qy", "1"), ["TF_DENORMALIZED_QUATERNION"]),
    (("--y", "nan"), ["TF_NAN_INPUT"]),
    # A NaN angle makes a NaN quaternion, which also fails tf2's norm check.
    (("0", "0", "0", "nan", "0", "0", "a", "b"), ["TF_NAN_INPUT", "TF_DENORMALIZED_QUATERNION"]),
])
def test_invalid_transforms_are_refused(capsys, words, kinds):
    if words[0].startswith("--"):
        words = (*words, "--frame-id", "a", "--child-frame-id", "b")
    code, out, err = run(capsys, "static_transform_publisher", *words)
    assert code == 1 and out == ""
    records = [r for r in log_records(err) if r[0] == "ERROR"]
    assert [m.split(":")[0] for _, _, m in records] == kinds
    assert all(f'child_frame_id "b" from authority "{logger}"' in m for _, logger, m in records)


def test_parse_error_logs_and_prints_usage(capsys):
    code, out, err = run(capsys, "static-transform-publisher", "--frame-id", "a")
    assert code == 1
    assert log_records(err) == [("ERROR", "", "error parsing command line arguments: Child frame id must not be empty")]
    assert out == STATIC_USAGE + "\n"


def test_ros1_wrong_count_is_extra_arguments(capsys):
    code, _, err = run(capsys, "static-transform-publisher", "1", "2", "3", "4", "a")
    assert code == 1
    assert log_records(err)[-1][2] == "error parsing command line arguments: Extra unparsed arguments on command-line"


def test_help(capsys):
    code, out, _ = run(capsys, "static-transform-publisher", "--help")
    assert code == 0 and out.startswith(STATIC_USAGE + "\n\n")  # then the forms robotmodel adds


def test_tf2_echo_usage_and_bad_rate(capsys):
    code, out, err = run(capsys, "tf2-echo", "only_one")
    assert code == 1 and out.startswith("Usage: tf2_echo source_frame target_frame [echo_rate]\n") and err == ""
    code, out, err = run(capsys, "tf2_echo", "a", "b", "fast")
    assert (code, out, err) == (2, "", "Failed to convert rate argument 'fast' to a floating-point number\n")
    code, _, _ = run(capsys, "tf2_echo", "a", "b", "2Hz")
    assert code == 3
