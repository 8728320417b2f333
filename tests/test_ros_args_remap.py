"""Remap rules and parameter overrides, checked against rcl's documented examples and rules.

The remap cases are those of rcl's own tests (test_remap.cpp, test_arguments.cpp) and of the
ROS 2 remapping design article; the value typing follows rcl_yaml_param_parser's rules
(strtoll base 0, strtod, its bool spellings, quoted = string).
"""

from __future__ import annotations

import math
import re
from pathlib import Path

import pytest

from robotmodel.bus import BusError, Node, RemapRule, parse_rules, remap_topic
from robotmodel.rcl import (
    RosArgsError,
    node_params,
    param_rule_entry,
    param_type_name,
    params_for_node,
    take_ros_args,
    typed_param,
)


def remap(rules: list[str], name: str, node: str = "NodeName", ns: str = "/") -> str:
    return remap_topic(parse_rules(rules), name, node, ns)


# -- matching (rcl's test_remap.cpp) -----------------------------------------------------------------
def test_global_topic_rule_matches_only_its_name():
    assert remap(["/bar/foo:=/foo/bar"], "/bar/foo") == "/foo/bar"
    assert remap(["/bar/foo:=/foo/bar"], "/foo/bar") == "/foo/bar"


def test_relative_rule_and_replacement_expand_under_the_node_namespace():
    assert remap(["foo:=bar"], "/ns/foo", ns="/ns") == "/ns/bar"
    # The match is the expanded name: 'foo' in /ns is /ns/foo, never /foo.
    assert remap(["foo:=bar"], "/foo", ns="/ns") == "/foo"
    # An absolute match against a relative replacement: the replacement lands in the namespace.
    assert remap(["/foo/bar:=fiz/buz"], "/foo/bar", ns="/ns") == "/ns/fiz/buz"


def test_private_names_expand_under_the_node():
    assert remap(["~/foo:=~/bar"], "/ns/talker/foo", node="talker", ns="/ns") == "/ns/talker/bar"
    assert remap(["~/foo:=bar"], "/ns/talker/foo", node="talker", ns="/ns") == "/ns/bar"


def test_node_prefix_limits_a_rule_to_that_node():
    rules = ["Node1:/foo:=/foo/bar", "Node2:/foo:=/this_one", "Node3:/foo:=/bar/foo"]
    assert [remap(rules, "/foo", node=n) for n in ("Node1", "Node2", "Node3", "Node4")] == [
        "/foo/bar", "/this_one", "/bar/foo", "/foo"]


def test_first_matching_rule_wins_and_other_kinds_are_skipped():
    rules = ["__ns:=/namespace", "__node:=remap_name", "/foobar:=/foo/bar", "/foobar:=/second"]
    assert remap(rules, "/foobar") == "/foo/bar"


def test_url_schemes():
    assert remap(["rostopic://foo:=bar"], "/ns/foo", ns="/ns") == "/ns/bar"
    # A service-only rule leaves topics alone (there are no services here).
    assert remap(["rosservice://foo:=bar"], "/ns/foo", ns="/ns") == "/ns/foo"


def test_rules_rcl_accepts():
    for text in ["__node:=node_name", "old_name:__node:=node_name", "__ns:=/foo/bar", "__ns:=/", "_:=kq",
                 "nodename:__ns:=/foobar", "foo:=bar", "~/foo:=~/bar", "/foo/bar:=bar", "foo:=/bar",
                 "/foo123:=/bar123", "node:/foo123:=/bar123", "rostopic:=/foo/bar", "rosservice:=baz",
                 "rostopic://rostopic:=rosservice", "rostopic:///rosservice:=rostopic", "rostopic:///foo/bar:=baz"]:
        RemapRule.parse(text)
    # 'rostopic' without '://' is an ordinary name, not a scheme.
    assert remap(["rostopic:=/foo/bar"], "/rostopic") == "/foo/bar"


@pytest.mark.parametrize(("text", "why"), [
    ("foo", "expected ':='"),
    ("/foo/*:=bar", "Wildcard '*' is not implemented"),
    ("**:=bar", "Wildcard '**' is not implemented"),
    ("foo:=\\1", "Backreferences are not implemented"),
    ("foo:=bar/", "not a valid replacement"),
    ("1foo:=bar", "not a valid name"),
    ("__node:=a-b", "Node name not remapped to invalid name: 'a-b'"),
    ("__ns:=r1", "Namespace not remapped to a fully qualified name (found: r1)"),
])
def test_rules_rcl_refuses(text, why):
    with pytest.raises(BusError, match=re.escape(f"Couldn't parse remap rule: '{text}'. Error: ") + ".*" +
                       re.escape(why)):
        RemapRule.parse(text)


# -- on a Node: every topic it names goes through the rules --------------------------------------------
def test_node_applies_rules_to_publishers_subscriptions_and_itself():
    rules = ["joint_states:=/arm/joint_states", "__node:=rsp2", "rsp2:/tf:=tf", "rsp:/tf_static:=/nope",
             "robot_state_publisher:__ns:=/r1"]
    with Node("robot_state_publisher", backend="inprocess", domain_id=91, remappings=rules) as node:
        # __node renames; the __ns rule is matched on the name the node was created with.
        assert (node.name, node.namespace) == ("rsp2", "/r1")
        assert node.resolve_topic_name("joint_states") == "/arm/joint_states"
        assert node.resolve_topic_name("joint_states", only_expand=True) == "/r1/joint_states"
        assert node.resolve_topic_name("/tf") == "/r1/tf"        # matched on the new name
        assert node.resolve_topic_name("/tf_static") == "/tf_static"  # 'rsp:' names another node
        assert node.create_publisher("std_msgs/msg/String", "/tf", 1).topic_name == "/r1/tf"
        got: list[str] = []
        node.create_subscription("std_msgs/msg/String", "/arm/joint_states", lambda m: got.append(m.data), 10)
        from robotmodel.bus import typestore

        String = typestore().types["std_msgs/msg/String"]
        node.create_publisher(String, "joint_states", 10).publish(String(data="remapped"))
        assert got == ["remapped"]


def test_node_refuses_a_bad_rule():
    with pytest.raises(BusError, match=r"^Couldn't parse remap rule: 'a/\*\*:=b'"):
        Node("n", backend="inprocess", domain_id=92, remappings=["a/**:=b"])


# -- the command line ---------------------------------------------------------------------------------
def test_cli_keeps_topic_rules_in_order_and_settles_ns_and_node():
    ros, rest = take_ros_args(["f.urdf", "--ros-args", "-r", "/joint_states:=/arm/joint_states", "-r",
                               "__ns:=/r1", "--remap", "other:__node:=x", "-r", "rsp:/tf:=/r1/tf", "--", "more"],
                              "rsp")
    assert rest == ["f.urdf", "more"]
    assert (ros.namespace, ros.node_name) == ("/r1", None)
    assert ros.remaps == ("/joint_states:=/arm/joint_states", "rsp:/tf:=/r1/tf")


@pytest.mark.parametrize(("words", "text"), [
    (["-r", "a/*:=b"], "Couldn't parse remap rule: '-r a/*:=b'. Error: Wildcard '*' is not implemented"),
    (["-p"], "Couldn't parse trailing -p flag. No parameter override rule found."),
    (["--params-file"], "Couldn't parse trailing --params-file flag. No file path provided."),
    (["-p", "rate"], "Couldn't parse parameter override rule: '-p rate'. Error: expected ':=' between the "
                     "parameter name and its value"),
    (["-p", "rate:="], "Couldn't parse parameter override rule: '-p rate:='. Error: No value at line 1"),
    (["-p", "l:=[1, a]"], "Couldn't parse parameter override rule: '-p l:=[1, a]'. Error: Sequence should be of "
                          "same type. Value type 'string' do not belong at line_num 1"),
    (["--params-file", "/nonexistent/p.yaml"],
     "Couldn't parse params file: '--params-file /nonexistent/p.yaml'. Error: Error opening YAML file"),
    (["__ns:=/r1"], "found unknown ROS arguments: '__ns:=/r1'"),
    (["--log-level", "loud"], "Couldn't parse log level: '--log-level loud'. Error: Argument does not use a "
                              "valid severity level"),
])
def test_cli_errors_are_rcls_one_line_texts(words, text):
    with pytest.raises(RosArgsError) as info:
        take_ros_args(["--ros-args", *words])
    assert str(info.value) == text


def test_cli_accepts_rcls_other_flags():
    ros, rest = take_ros_args(["--ros-args", "--log-level", "rsp:=debug", "--log-level", "WARN", "--enclave", "/e",
                               "--disable-rosout-logs", "--enable-stdout-logs", "--log-file-name", "x"])
    assert rest == [] and ros.params == () and ros.remaps == ()


# -- parameter values: rcl_yaml_param_parser's typing ---------------------------------------------------
@pytest.mark.parametrize(("text", "value", "kind"), [
    ("50", 50, "integer"), ("-7", -7, "integer"), ("0x10", 16, "integer"), ("017", 15, "integer"),
    ("50.0", 50.0, "double"), ("1e3", 1000.0, "double"), (".5", 0.5, "double"), ("08", 8.0, "double"),
    ("true", True, "bool"), ("Yes", True, "bool"), ("off", False, "bool"), ("FALSE", False, "bool"),
    ("r1/", "r1/", "string"), ("'50'", "50", "string"), ('"true"', "true", "string"), ("!!str 5", "5", "string"),
    ("1e999", "1e999", "string"),
    ("[a, b]", ("a", "b"), "string_array"), ("[1, 2]", (1, 2), "integer_array"),
    ("[1.5, 2.0]", (1.5, 2.0), "double_array"), ("[true, no]", (True, False), "bool_array"),
    ("['/a/joint_states']", ("/a/joint_states",), "string_array"),
])
def test_values_are_typed_as_rcl_types_them(text, value, kind):
    node, name, got = param_rule_entry("-p", f"x:={text}")
    assert (node, name, got, param_type_name(got)) == ("/**", "x", value, kind)


def test_inf_and_nan_spellings():
    assert param_rule_entry("-p", "x:=-.inf")[2] == -math.inf
    assert math.isnan(param_rule_entry("-p", "x:=.NaN")[2])  # type: ignore[arg-type]


def test_node_prefixed_override_applies_to_that_node_only():
    entries = [param_rule_entry("-p", "rate:=5"), param_rule_entry("-p", "joint_state_publisher:rate:=7")]
    assert params_for_node(entries, "/joint_state_publisher") == {"rate": 7}
    assert params_for_node(entries, "/other") == {"rate": 5}
    # 'name:' means '/name': a node in a namespace needs its full name or a wildcard.
    assert params_for_node(entries, "/r1/joint_state_publisher") == {"rate": 5}


PARAMS = """\
/**:
  ros__parameters:
    rate: 5
    publish_default_velocities: true
joint_state_publisher:
  ros__parameters:
    zeros:
      hinge: 0.25
      slide: -1
    source_list: ['/a/joint_states', '/b/joint_states']
r1:
  joint_state_publisher:
    ros__parameters:
      rate: 40
"""


def test_params_file_nodes_nesting_and_order(tmp_path: Path):
    f = tmp_path / "p.yaml"
    f.write_text(PARAMS)
    ros, _ = take_ros_args(["--ros-args", "--params-file", str(f)])
    assert node_params(ros, "/", "joint_state_publisher") == {
        "rate": 5, "publish_default_velocities": True, "zeros.hinge": 0.25, "zeros.slide": -1,
        "source_list": ("/a/joint_states", "/b/joint_states")}
    assert node_params(ros, "/r1", "joint_state_publisher") == {"rate": 40, "publish_default_velocities": True}
    assert node_params(ros, "/", "robot_state_publisher") == {"rate": 5, "publish_default_velocities": True}


def test_the_value_given_last_wins_as_rclcpp_merges_them(tmp_path: Path):
    f = tmp_path / "p.yaml"
    f.write_text(PARAMS)
    after, _ = take_ros_args(["--ros-args", "--params-file", str(f), "-p", "rate:=20", "-p", "zeros.hinge:=0.5"])
    assert node_params(after, "/", "joint_state_publisher")["rate"] == 20
    # rcl updates '/**' in place, and rclcpp applies the file's later 'joint_state_publisher:' table
    # over it: a node's own entry in a file beats an unprefixed -p, wherever the -p stands.
    assert node_params(after, "/", "joint_state_publisher")["zeros.hinge"] == 0.25
    own, _ = take_ros_args(["--ros-args", "--params-file", str(f), "-p", "joint_state_publisher:zeros.hinge:=0.5"])
    assert node_params(own, "/", "joint_state_publisher")["zeros.hinge"] == 0.5
    before, _ = take_ros_args(["--ros-args", "-p", "rate:=20", "--params-file", str(f)])
    assert node_params(before, "/", "joint_state_publisher")["rate"] == 5


@pytest.mark.parametrize(("text", "why"), [
    ("ros__parameters:\n  a: 1\n", "There are no node names before ros__parameters at line 1"),
    ("n:\n  x: 1\n", "Cannot have a value before ros__parameters at line 2"),
    ("n:\n  ros__parameters:\n    l: [1, 2.5]\n", "Sequence should be of same type"),
    ("n: [\n", "Error parsing a event near line"),
])
def test_bad_params_files(tmp_path: Path, text, why):
    f = tmp_path / "p.yaml"
    f.write_text(text)
    with pytest.raises(RosArgsError, match=f"^Couldn't parse params file: '--params-file {f}'. Error: "
                       + why.replace("[", r"\[")):
        take_ros_args(["--ros-args", "--params-file", str(f)])


def test_wrong_type_is_rclcpps_text():
    with pytest.raises(RosArgsError) as info:
        typed_param({"publish_frequency": 50}, "publish_frequency", "double")
    assert str(info.value) == ("parameter 'publish_frequency' has invalid type: Wrong parameter type, parameter "
                               "{publish_frequency} is of type {double}, setting it to {integer} is not allowed.")
    assert typed_param({"rate": 20.5}, "rate", "integer", "double") == 20.5
    assert typed_param({}, "rate", "integer") is None


def test_library_publishers_take_remappings_through_their_node_options():
    from robotmodel.bus import QOS_TF, Context
    from robotmodel.msgs import Header, JointState, TFMessage, stamp
    from robotmodel.publishers import RobotStatePublisher

    urdf = ('<robot name="r"><link name="a"/><link name="b"/><joint name="j" type="continuous">'
            '<parent link="a"/><child link="b"/><axis xyz="0 0 1"/></joint></robot>')
    with Context(backend="inprocess", domain_id=93) as ctx, Node("driver", context=ctx) as driver:
        got: list[TFMessage] = []
        driver.create_subscription(TFMessage, "/r1/tf", got.append, QOS_TF)
        with RobotStatePublisher(urdf, context=ctx, remappings=["joint_states:=/arm/joint_states", "/tf:=/r1/tf"]):
            pub = driver.create_publisher(JointState, "/arm/joint_states", 10)
            pub.publish(JointState(header=Header(stamp=stamp(5_000_000_000)), name=["j"], position=[0.5]))
        assert [(t.header.frame_id, t.child_frame_id) for m in got for t in m.transforms] == [("a", "b")]
