"""``robotmodel rostopic pub`` and ``rosparam``/``param`` on the ROS 1 wire, against the real rospy and rosparam."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import yaml
from ros1helpers import Ros1World


def _robotmodel(ros1: Ros1World, *args: str) -> subprocess.CompletedProcess[str]:
    env = dict(ros1.env, ROS_VERSION="1")
    return subprocess.run([sys.executable, "-m", "robotmodel.cli.main", *args], env=env, capture_output=True,
                          text=True, timeout=60, check=False)


def test_rostopic_pub_once_reaches_a_real_rospy_subscriber(ros1: Ros1World) -> None:
    sub = ros1.rospy("sub", "/chatter", "std_msgs/String")
    sub.wait_line("ready")
    done = _robotmodel(ros1, "rostopic", "pub", "--once", "/chatter", "std_msgs/msg/String", "{data: hello rospy}")
    assert done.returncode == 0, done.stderr
    sub.wait_line("got hello rospy")


def test_param_get_set_against_the_real_parameter_server(ros1: Ros1World) -> None:
    ros1.tool("rosparam", "set", "/probe/gain", "2.5")
    ros1.tool("rosparam", "set", "/probe/names", "[a, b]")
    got = _robotmodel(ros1, "rosparam", "get", "/probe/gain")
    assert got.returncode == 0, got.stderr
    assert got.stdout == ros1.tool("rosparam", "get", "/probe/gain")
    tree = _robotmodel(ros1, "rosparam", "get", "/probe")
    assert yaml.safe_load(tree.stdout) == yaml.safe_load(ros1.tool("rosparam", "get", "/probe"))
    put = _robotmodel(ros1, "param", "set", "/probe", "gain", "7")
    assert put.stdout == "Set parameter successful\n", put.stderr
    assert ros1.tool("rosparam", "get", "/probe/gain").strip() == "7"
    assert _robotmodel(ros1, "param", "get", "/probe", "gain").stdout == "Integer value is: 7\n"
    assert _robotmodel(ros1, "rosparam", "set", "/probe/on", "true").returncode == 0
    assert ros1.tool("rosparam", "get", "/probe/on").strip() == "true"
    listed = _robotmodel(ros1, "param", "list", "/probe").stdout.splitlines()
    assert listed == ["/probe:", "  gain", "  names", "  on"]


def test_rosparam_load_delete_describe_against_the_real_rosparam(ros1: Ros1World, tmp_path: Path) -> None:
    params = tmp_path / "params.yaml"
    params.write_text("gain: 2.5\nnested: {a: 1, b: [x, y]}\n---\n_ns: sub\nflag: true\n")
    ros1.tool("rosparam", "load", str(params), "/theirs")
    loaded = _robotmodel(ros1, "rosparam", "load", str(params), "/ours")
    assert (loaded.returncode, loaded.stdout) == (0, ""), loaded.stderr

    def tree(ns: str) -> object:
        return yaml.safe_load(ros1.tool("rosparam", "get", ns))

    assert tree("/ours") == tree("/theirs")
    assert _robotmodel(ros1, "rosparam", "delete", "/ours/nested/a").returncode == 0
    ros1.tool("rosparam", "delete", "/theirs/nested/a")
    assert tree("/ours") == tree("/theirs")
    again = _robotmodel(ros1, "rosparam", "delete", "/ours/nested/a")
    theirs = ros1.tool("rosparam", "delete", "/theirs/nested/a")
    assert again.returncode == 1
    assert again.stderr.split("error: ", 1)[1] == theirs.split("ERROR: ", 1)[1].replace("/theirs", "/ours")
    described = _robotmodel(ros1, "param", "describe", "/ours", "gain", "sub/flag")
    assert described.stdout.splitlines() == ["Parameter name: gain", "  Type: double", "  Constraints:",
                                             "Parameter name: sub/flag", "  Type: boolean", "  Constraints:"]
