"""What each launched node is told on its command line: remaps, name, namespace, parameters.

Expected command lines are written from the launch systems' documented rules: roslaunch
(a <remap> applies to the nodes after it in its scope and in files included after it; the
node resolves the rules against its namespace and keeps the last per name) and launch_ros
(``-r __node``, ``-r __ns``, parameters in the file's order, <set_remap> rules before the
node's own <remap> rules).
"""

from __future__ import annotations

from pathlib import Path

import pytest

from robotmodel.errors import LaunchError
from robotmodel.launch import build_plan, load_launch_file


def ros_args(path: Path, root: Path, tmp_path: Path, **args: str) -> dict[str, tuple[str, ...]]:
    """Each process's words after ``--ros-args`` (empty when it has none)."""
    plan = build_plan(load_launch_file(path, args, [root]), tmp_path, package_paths=[root], browser=False)
    out = {}
    for spec in plan.processes:
        words = spec.argv
        out[spec.name] = words[words.index("--ros-args") + 1:] if "--ros-args" in words else ()
    return out


def test_ros1_remaps_follow_roslaunch_scopes(pkg, tmp_path):
    pkg.launch("parts/inner.launch", """
        <launch>
          <node pkg="tf2_ros" type="static_transform_publisher" name="inner_before" args="0 0 0 0 0 0 a b"/>
          <remap from="inner_topic" to="only_inside"/>
          <node pkg="tf2_ros" type="static_transform_publisher" name="inner_after" args="0 0 0 0 0 0 a b"/>
        </launch>
    """)
    path = pkg.launch("scopes.launch", """
        <launch>
          <param name="robot_description" textfile="$(find probe_description)/urdf/probe.urdf.xacro"/>
          <node pkg="joint_state_publisher" type="joint_state_publisher" name="before"/>
          <remap from="joint_states" to="/arm/joint_states"/>
          <group ns="g">
            <remap from="tf" to="tf_g"/>
            <node pkg="robot_state_publisher" type="robot_state_publisher" name="in_group">
              <remap from="joint_states" to="mine"/>
            </node>
          </group>
          <node pkg="robot_state_publisher" type="robot_state_publisher" name="after_group"/>
          <include file="$(dirname)/parts/inner.launch"/>
          <node pkg="tf2_ros" type="static_transform_publisher" name="after_include" args="0 0 0 0 0 0 a b"/>
        </launch>
    """)
    assert ros_args(path, pkg.root, tmp_path) == {
        # A <remap> acts on the nodes after it only.
        "/before": ("-r", "__node:=before"),
        # The node's own rule replaces the scope's for the same 'from'; the group's rule is the group's.
        "/g/in_group": ("-r", "__node:=in_group", "-r", "__ns:=/g", "-r", "tf:=tf_g", "-r", "joint_states:=mine"),
        "/after_group": ("-r", "__node:=after_group", "-r", "joint_states:=/arm/joint_states"),
        # An included file inherits the includer's rules; its own stay inside it.
        "/inner_before": ("-r", "__node:=inner_before", "-r", "joint_states:=/arm/joint_states"),
        "/inner_after": ("-r", "__node:=inner_after", "-r", "joint_states:=/arm/joint_states",
                         "-r", "inner_topic:=only_inside"),
        "/after_include": ("-r", "__node:=after_include", "-r", "joint_states:=/arm/joint_states"),
    }


def test_ros1_last_rule_per_resolved_name_and_private_names(pkg, tmp_path):
    # roscpp keys its rules by the resolved 'from', so the later of two spellings of /ns/js wins;
    # handed to rcl (first match wins), only that one may remain.
    path = pkg.launch("names.launch", """
        <launch>
          <group ns="ns">
            <remap from="js" to="first"/>
            <node pkg="tf2_ros" type="static_transform_publisher" name="s" args="0 0 0 0 0 0 a b">
              <remap from="/ns/js" to="second"/>
              <remap from="~private" to="/elsewhere//x/"/>
              <remap from="other" to="kept"/>
            </node>
          </group>
        </launch>
    """)
    assert ros_args(path, pkg.root, tmp_path)["/ns/s"] == (
        "-r", "__node:=s", "-r", "__ns:=/ns", "-r", "/ns/js:=second", "-r", "~/private:=/elsewhere/x",
        "-r", "other:=kept")


@pytest.mark.parametrize(("attrs", "text"), [
    ('from="" to="b"', "remap from/to attributes cannot be empty"),
    ('from="1bad" to="b"', r"remap from \[1bad\] is not a valid ROS name"),
    ('from="a" to="b c"', r"remap to \[b c\] is not a valid ROS name"),
])
def test_ros1_bad_remap_is_refused_with_file_and_line(pkg, tmp_path, attrs, text):
    path = pkg.launch("bad.launch", f"""
        <launch>

          <remap {attrs}/>
        </launch>
    """)
    with pytest.raises(LaunchError, match=rf"bad\.launch:3: {text}$"):
        load_launch_file(path, {}, [pkg.root])


def test_ros2_set_remap_scopes_and_node_remaps(pkg, tmp_path):
    pkg.launch("inc.launch.xml", """
        <launch>
          <set_remap from="from_include" to="leaks"/>
          <node pkg="tf2_ros" exec="static_transform_publisher" name="in_include" args="0 0 0 0 0 0 a b"/>
        </launch>
    """)
    path = pkg.launch("remaps.launch.xml", """
        <launch>
          <remap from="ignored" to="here"/>
          <group>
            <set_remap from="early" to="inside"/>
            <node pkg="tf2_ros" exec="static_transform_publisher" name="early" args="0 0 0 0 0 0 a b"/>
          </group>
          <set_remap from="joint_states" to="/arm/joint_states"/>
          <group>
            <push-ros-namespace namespace="r2"/>
            <set_remap from="tf" to="tf_r2"/>
            <node pkg="robot_state_publisher" exec="robot_state_publisher" name="rsp">
              <param name="robot_description" value="$(command 'xacro $(dirname)/../urdf/probe.urdf.xacro')"/>
              <remap from="joint_states" to="overridden_by_the_scope"/>
              <remap from="robot_description" to="/desc"/>
            </node>
          </group>
          <include file="$(dirname)/inc.launch.xml"/>
          <node pkg="joint_state_publisher_gui" exec="joint_state_publisher_gui"/>
        </launch>
    """)
    plan = build_plan(load_launch_file(path, {}, [pkg.root]), tmp_path, package_paths=[pkg.root], browser=False)
    assert [n for n in plan.notes if "<remap>" in n] == [f"{path}:2: <remap> outside a <node> ignored "
                                                         "(ROS 2 launch: <set_remap>)"]
    assert ros_args(path, pkg.root, tmp_path) == {
        # A group's first <set_remap> starts a list of its own, which ends with the group.
        "/early": ("-r", "__node:=early", "-r", "early:=inside"),
        # launch_ros: the scope's rules first (rcl takes the first match), then the node's, all verbatim.
        "/r2/rsp": ("-r", "__node:=rsp", "-r", "__ns:=/r2", "-r", "joint_states:=/arm/joint_states",
                    "-r", "tf:=tf_r2", "-r", "joint_states:=overridden_by_the_scope",
                    "-r", "robot_description:=/desc"),
        # Once the scope has rules, a group appends to that same list (launch_ros copies the
        # configurations shallowly), so tf:=tf_r2 outlives its group.
        "/in_include": ("-r", "__node:=in_include", "-r", "joint_states:=/arm/joint_states", "-r", "tf:=tf_r2",
                        "-r", "from_include:=leaks"),
        # An include does not scope: its <set_remap> is still in force after it. Unnamed, the GUI
        # takes joint_state_publisher_gui's own name, the command's default (no __node rule).
        "/joint_state_publisher_gui": ("-r", "joint_states:=/arm/joint_states", "-r", "tf:=tf_r2",
                                       "-r", "from_include:=leaks"),
    }


def test_parameters_not_mapped_to_flags_go_as_ros_parameters(pkg, tmp_path):
    params = pkg.dir / "config" / "jsp.yaml"
    params.parent.mkdir()
    params.write_text("/**:\n  ros__parameters:\n    zeros:\n      shoulder: 0.25\n")
    path = pkg.launch("params.launch.xml", """
        <launch>
          <node pkg="joint_state_publisher" exec="joint_state_publisher" name="jsp"
                args="$(dirname)/../urdf/probe.urdf.xacro">
            <param name="rate" value="5"/>
            <param name="use_mimic_tags" value="false"/>
            <param from="$(dirname)/../config/jsp.yaml"/>
            <param name="delta" value="0.1"/>
          </node>
          <node pkg="joint_state_publisher_gui" exec="joint_state_publisher_gui" name="gui">
            <param name="rate" value="20"/>
            <param name="zeros"><param name="shoulder" value="0.5"/></param>
          </node>
          <node pkg="robot_state_publisher" exec="robot_state_publisher">
            <param name="robot_description" value="$(command 'xacro $(dirname)/../urdf/probe.urdf.xacro')"/>
            <param name="frame_prefix" value=""/>
            <param name="tf_prefix" value=""/>
          </node>
        </launch>
    """)
    got = ros_args(path, pkg.root, tmp_path)
    # rate has its flag; the rest in the file's order, the params file among them.
    assert got["/jsp"] == ("-r", "__node:=jsp", "-p", "use_mimic_tags:=false", "--params-file", str(params),
                           "-p", "delta:=0.1")
    # The GUI has no --rate: joint_state_publisher's parameters reach it as parameters.
    assert got["/gui"] == ("-r", "__node:=gui", "-p", "rate:=20")
    # An empty value as rcl reads the empty string; unnamed: the executable's own name, nothing passed.
    assert got["/robot_state_publisher"] == ("-p", "tf_prefix:=''")


def test_ros2_set_parameter_ros_args_and_a_missing_params_file(pkg, tmp_path):
    path = pkg.launch("global.launch.xml", """
        <launch>
          <group>
            <set_parameter name="scoped" value="1"/>
          </group>
          <set_parameter name="use_sim_time" value="false"/>
          <group>
            <set_parameter name="publish_default_efforts" value="true"/>
            <node pkg="joint_state_publisher" exec="joint_state_publisher" name="jsp" ros_args="--log-level warn"
                  namespace="arm">
              <param from="$(dirname)/missing.yaml"/>
              <param name="delta" value="0.2"/>
            </node>
          </group>
          <node pkg="tf2_ros" exec="static_transform_publisher" args="0 0 0 0 0 0 a b"/>
        </launch>
    """)
    plan = build_plan(load_launch_file(path, {}, [pkg.root]), tmp_path, package_paths=[pkg.root], browser=False)
    # launch_ros warns and starts the node without the file.
    assert f"{path}:10: Parameter file path is not a file: {pkg.dir / 'launch' / 'missing.yaml'}" in plan.notes
    assert ros_args(path, pkg.root, tmp_path) == {
        # ros_args first, then name and namespace, then the scope's values before the node's own.
        "/arm/jsp": ("--log-level", "warn", "-r", "__node:=jsp", "-r", "__ns:=/arm", "-p", "use_sim_time:=false",
                     "-p", "publish_default_efforts:=true", "-p", "delta:=0.2"),
        # The first group's value stayed in it; the second's was added to the scope's list, as
        # launch_ros does it, so it outlives its group.
        "/static_transform_publisher": ("-p", "use_sim_time:=false", "-p", "publish_default_efforts:=true"),
    }


def test_ros1_rosparam_file_in_a_node(pkg, tmp_path):
    (pkg.dir / "config").mkdir()
    (pkg.dir / "config" / "zeros.yaml").write_text("zeros:\n  shoulder: $(arg q)\nrate: 7\n")
    path = pkg.launch("file.launch", """
        <launch>
          <arg name="q" default="0.125"/>
          <param name="robot_description" textfile="$(find probe_description)/urdf/probe.urdf.xacro"/>
          <node pkg="joint_state_publisher" type="joint_state_publisher" name="jsp">
            <rosparam command="load" file="$(find probe_description)/config/zeros.yaml" subst_value="true"/>
          </node>
        </launch>
    """)
    plan = build_plan(load_launch_file(path, {}, [pkg.root]), tmp_path, package_paths=[pkg.root], browser=False)
    assert plan.processes[0].argv[-7:] == ("--rate", "7", "--zeros", "shoulder=0.125", "--ros-args", "-r",
                                           "__node:=jsp")
    # Without subst_value the text is taken as written, as roslaunch does: '$(arg q)' stays a string.
    path.write_text(path.read_text().replace(' subst_value="true"', ""))
    with pytest.raises(LaunchError, match=r"parameter 'zeros.shoulder' of /jsp must be a number, got '\$\(arg q\)'"):
        build_plan(load_launch_file(path, {}, [pkg.root]), tmp_path, package_paths=[pkg.root], browser=False)
    path.write_text(path.read_text().replace("zeros.yaml", "nope.yaml"))
    with pytest.raises(LaunchError, match=r"file\.launch:5: <rosparam>: file does not exist \[.*/config/nope\.yaml\]$"):
        load_launch_file(path, {}, [pkg.root])


def test_ros1_remapped_robot_description_is_the_parameter_read(pkg, tmp_path):
    arm = pkg.dir / "urdf" / "arm.urdf"
    arm.write_text('<robot name="arm"><link name="a"/></robot>')
    path = pkg.launch("two.launch", """
        <launch>
          <param name="robot_description" textfile="$(find probe_description)/urdf/probe.urdf.xacro"/>
          <group ns="left">
            <param name="arm_description" textfile="$(find probe_description)/urdf/arm.urdf"/>
            <group ns="deeper">
              <remap from="robot_description" to="arm_description"/>
              <node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/>
            </group>
          </group>
          <node pkg="robot_state_publisher" type="robot_state_publisher" name="plain"/>
        </launch>
    """)
    plan = build_plan(load_launch_file(path, {}, [pkg.root]), tmp_path, package_paths=[pkg.root], browser=False)
    files = {p.name: p.argv[1] for p in plan.processes}
    # roscpp's searchParam takes the remapped name and searches it up from /left/deeper.
    assert files == {"/left/deeper/rsp": str(arm), "/plain": str(pkg.xacro)}


def test_a_remap_inside_an_include_is_noted_not_applied(pkg, tmp_path):
    pkg.launch("inner.launch", """
        <launch>
          <node pkg="tf2_ros" type="static_transform_publisher" name="s" args="0 0 0 0 0 0 a b"/>
        </launch>
    """)
    path = pkg.launch("outer.launch", """
        <launch>
          <include file="$(dirname)/inner.launch">
            <remap from="tf" to="elsewhere"/>
          </include>
        </launch>
    """)
    plan = build_plan(load_launch_file(path, {}, [pkg.root]), tmp_path, package_paths=[pkg.root], browser=False)
    assert plan.notes == [f"{path}:3: <remap> inside <include> ignored"]
    assert plan.processes[0].argv[-3:] == ("--ros-args", "-r", "__node:=s")
