"""The two commands' argument handling: ROS's texts, one-line errors, no heavy imports at registration."""

from __future__ import annotations

import subprocess
import sys

import pytest
from conftest import BUNDLED

ARM = str(BUNDLED / "arm.urdf.xacro")


def robotmodel(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "robotmodel.cli.main", *args], check=False, capture_output=True,
                          text=True,
                          timeout=120)


@pytest.mark.parametrize("hz", ["1000.5", "-1", "nan"])
def test_publish_frequency_out_of_range_is_rsp_text(hz):
    done = robotmodel("robot-state-publisher", ARM, "--publish-frequency", hz)
    assert done.returncode == 1
    assert done.stdout == ""
    assert done.stderr == "robotmodel robot-state-publisher: error: publish_frequency must be between 0 and 1000\n"


def test_missing_file_is_one_line():
    done = robotmodel("robot_state_publisher", "no/such.urdf")
    assert done.returncode == 1
    assert done.stderr.count("\n") == 1 and "no/such.urdf" in done.stderr


@pytest.mark.parametrize("args", [["--zeros", "arm_base_joint"], ["--zeros", "a=x"], ["--rate", "0"],
                                  ["--rate", "fast"]])
def test_jsp_bad_arguments_are_usage_errors(args):
    done = robotmodel("joint-state-publisher", ARM, *args)
    assert done.returncode == 2
    assert done.stderr.startswith("usage: robotmodel joint-state-publisher")
    assert "Traceback" not in done.stderr


def test_invalid_urdf_for_jsp_is_one_line(tmp_path):
    bad = tmp_path / "bad.urdf"
    bad.write_text('<robot name="r"><link name="a"/><link name="b"/><joint name="j" type="revolute">'
                   '<parent link="a"/><child link="b"/></joint></robot>')
    done = robotmodel("joint_state_publisher", str(bad))
    assert done.returncode == 1
    assert done.stderr.count("\n") == 1 and "[j]" in done.stderr


def test_commands_register_without_pinocchio_or_zenoh():
    code = ("import argparse, sys\n"
            "from robotmodel.cli import jsp_cmd, rsp_cmd\n"
            "from robotmodel.cli._parser import CommandParser\n"
            "sub = argparse.ArgumentParser().add_subparsers(parser_class=CommandParser)\n"
            "rsp_cmd.register(sub); jsp_cmd.register(sub)\n"
            "print(sorted(k for k in ('pinocchio', 'zenoh', 'robotmodel.publishers') if k in sys.modules))")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert done.stdout.strip() == "[]"
