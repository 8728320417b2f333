"""The node-running commands' namespace arguments: ROS 2's ``--ros-args -r __ns:=/ns`` and ``--namespace NS``."""

from __future__ import annotations

import subprocess
import sys

import pytest
from robotmodel.cli.main import build_parser

from robotmodel.rcl import RosArgs, RosArgsError, logger_name, split_node_words, take_ros_args

NODE_COMMANDS = [
    ["robot-state-publisher", "r.urdf"],
    ["joint-state-publisher"],
    ["joint-state-publisher-gui"],
    ["view", "--follow"],
    ["view-frames"],
    ["topic", "echo", "joint_states"],
]


def parse(*words: str):
    return build_parser().parse_args(list(words))


@pytest.mark.parametrize("command", NODE_COMMANDS, ids=lambda c: c[0])
def test_ros_args_remap_gives_the_namespace(command):
    args = parse(*command, "--ros-args", "-r", "__ns:=/r1")
    assert (args.namespace, args.node_name) == ("/r1", None)


@pytest.mark.parametrize("command", NODE_COMMANDS, ids=lambda c: c[0])
def test_namespace_option_is_made_absolute(command):
    assert parse(*command, "--namespace", "r1").namespace == "/r1"
    assert parse(*command, "--namespace=/a/b").namespace == "/a/b"
    assert parse(*command).namespace == "/"


def test_node_rename_and_first_matching_rule_wins_as_in_rcl():
    args = parse("robot-state-publisher", "r.urdf", "--ros-args", "-r", "__node:=rsp_left",
                 "-r", "__ns:=/left", "-r", "__ns:=/right")
    assert (args.namespace, args.node_name) == ("/left", "rsp_left")
    # ROS 1's __name spelling is accepted by rcl too.
    assert parse("view", "--ros-args", "--remap", "__name:=viewer").node_name == "viewer"


def test_remap_overrides_the_namespace_option():
    # The option is the namespace given in code; a command-line remap wins over it, as in ROS.
    assert parse("joint-state-publisher", "--namespace", "r2", "--ros-args", "-r", "__ns:=/r1").namespace == "/r1"


def test_node_prefixed_rules_apply_to_their_node_only():
    args = parse("joint-state-publisher", "--ros-args", "-r", "robot_state_publisher:__ns:=/no",
                 "-r", "joint_state_publisher:__ns:=/yes")
    assert args.namespace == "/yes"


def test_ros_args_block_ends_at_double_dash_and_leaves_xacro_arguments_alone():
    args = parse("robot-state-publisher", "--ros-args", "-p", "use_sim_time:=true", "-r", "__ns:=/r1",
                 "--log-level", "debug", "--", "r.urdf", "prefix:=r1_", "--frame-prefix", "r1/")
    assert args.file == "r.urdf"
    assert args.mappings == {"prefix": "r1_"}  # neither use_sim_time nor __ns became xacro arguments
    assert (args.namespace, args.frame_prefix) == ("/r1", "r1/")


def test_take_ros_args_directly():
    # A topic rule is kept for the node (it used to be dropped: the tool listened on the wrong topic).
    assert take_ros_args(["a", "--ros-args", "-r", "chatter:=/x", "--", "b"]) == (RosArgs(remaps=("chatter:=/x",)),
                                                                               ["a", "b"])
    assert take_ros_args(["--ros-args", "-r", "__ns:=/q/r"]) == (RosArgs("/q/r"), [])
    with pytest.raises(RosArgsError, match=r"^Couldn't parse trailing --remap flag\. No remap rule found\.$"):
        take_ros_args(["--ros-args", "--remap"])


def test_split_node_words_for_commands_that_parse_their_own():
    words = ["--x", "1", "--namespace", "r1", "--frame-id", "a", "--child-frame-id", "b"]
    assert split_node_words(words) == (["--x", "1", "--frame-id", "a", "--child-frame-id", "b"], "/r1", None)
    rest, ns, name = split_node_words(["map", "odom", "--ros-args", "-r", "__ns:=/r2", "-r", "tf2_echo:__node:=e"],
                                      "tf2_echo")
    assert (rest, ns, name) == (["map", "odom"], "/r2", "e")
    assert split_node_words(["map", "odom"]) == (["map", "odom"], "/", None)


def test_logger_name_as_rcl_forms_it():
    assert logger_name("/", "robot_state_publisher") == "robot_state_publisher"
    assert logger_name("/r1/left", "robot_state_publisher") == "r1.left.robot_state_publisher"


@pytest.mark.parametrize(("words", "message"), [
    (["--namespace", "1bad"], "invalid namespace '/1bad': '1bad' must be letters, digits and '_'"),
    (["--namespace", "r1/"], "invalid namespace '/r1/': must not end with '/'"),
    (["--ros-args", "-r", "__ns:=r1"],
     "Couldn't parse remap rule: '-r __ns:=r1'. Error: Namespace not remapped to a fully qualified name (found: r1)"),
    (["--ros-args", "-r", "__ns:=/a//b"],
     "Couldn't parse remap rule: '-r __ns:=/a//b'. Error: Namespace not remapped to a fully qualified name"),
    (["--ros-args", "-r", "__node:=a-b"],
     "Couldn't parse remap rule: '-r __node:=a-b'. Error: Node name not remapped to invalid name: 'a-b'"),
    (["--ros-args", "-r"], "Couldn't parse trailing -r flag. No remap rule found."),
])
def test_invalid_namespace_is_one_line_error(words, message, tmp_path):
    # The command must fail on its arguments, before reading FILE (which does not exist).
    done = subprocess.run([sys.executable, "-m", "robotmodel.cli.main", "robot-state-publisher",
                           str(tmp_path / "none.urdf"), *words], capture_output=True, text=True, timeout=60,
                          check=False)
    assert done.returncode == 2
    assert done.stdout == ""
    lines = done.stderr.splitlines()
    assert len(lines) == 1, done.stderr
    assert lines[0].startswith(f"robotmodel robot-state-publisher: error: {message}")


@pytest.mark.parametrize("command", [["static-transform-publisher", "--frame-id", "a", "--child-frame-id", "b"],
                                     ["tf2-echo", "a", "b"]], ids=lambda c: c[0])
def test_self_parsing_commands_reject_a_bad_namespace_in_one_line(command):
    done = subprocess.run([sys.executable, "-m", "robotmodel.cli.main", *command, "--namespace", "9"],
                          capture_output=True, text=True, timeout=60, check=False)
    assert done.returncode == 2
    assert done.stderr.splitlines() == [f"robotmodel {command[0]}: error: invalid namespace '/9': '9' must be "
                                        "letters, digits and '_', not starting with a digit"]
