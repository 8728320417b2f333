"""Which processes a launch file starts, with which arguments (ROS 1 and ROS 2 XML, includes, conditions)."""

from __future__ import annotations

from pathlib import Path

import pytest
from robotmodel.cli.main import main

from robotmodel.errors import LaunchError
from robotmodel.launch import build_plan, load_launch_file


def plan_of(path: Path, root: Path, tmp_path: Path, **args: str):
    launch = load_launch_file(path, args, [root])
    return build_plan(launch, tmp_path, package_paths=[root], browser=False)


def argv(plan) -> dict[str, tuple[str, ...]]:
    return {p.name: p.argv for p in plan.processes}


def test_ros1_nested_includes_conditions_and_params(pkg, ros1_top, tmp_path):
    top = ros1_top
    plan = plan_of(top, pkg.root, tmp_path)
    xacro, root = str(pkg.xacro), str(pkg.root)
    assert [p.name for p in plan.processes] == ["/jsp", "/rsp", "/map_odom"]
    assert argv(plan) == {
        # rate comes from $(eval 2 * 5) in top.launch; zeros from a <rosparam> map.
        "/jsp": ("joint-state-publisher", xacro, "prefix:=", "--package-path", root, "--rate", "10",
                 "--zeros", "shoulder=0.5", "--ros-args", "-r", "__node:=jsp"),
        # publish_frequency: $(eval rate * 5) in the middle file, passed two includes down.
        "/rsp": ("robot-state-publisher", xacro, "prefix:=", "--package-path", root, "--publish-frequency", "50",
                 "--ros-args", "-r", "__node:=rsp"),
        "/map_odom": ("static-transform-publisher", "1", "2", "0", "0", "0", "0", "map", "odom", "100",
                      "--ros-args", "-r", "__node:=map_odom"),
    }
    assert plan.skipped == ["/sensors/scan_filter (probe_description/scan_filter.py): no robotmodel equivalent, "
                            "not started"]


def test_ros1_command_line_args_flip_the_conditions(pkg, ros1_top, tmp_path):
    top = ros1_top
    plan = plan_of(top, pkg.root, tmp_path, gui="true", with_static="false", prefix="left_")
    xacro, root = str(pkg.xacro), str(pkg.root)
    assert argv(plan) == {
        "/jsp_gui": ("joint-state-publisher-gui", xacro, "prefix:=left_", "--package-path", root,
                     "--ros-args", "-r", "__node:=jsp_gui"),
        "/rsp": ("robot-state-publisher", xacro, "prefix:=left_", "--package-path", root,
                 "--publish-frequency", "50", "--ros-args", "-r", "__node:=rsp"),
    }
    assert plan.skipped == []


def test_ros2_scopes_namespaces_command_and_nested_params(pkg, ros2_top, tmp_path):
    top = ros2_top
    plan = plan_of(top, pkg.root, tmp_path)
    xacro, root = str(pkg.xacro), str(pkg.root)
    assert argv(plan) == {
        # The pushed namespace goes to each node as launch_ros passes it.
        "/robot1/robot_state_publisher": ("robot-state-publisher", xacro, "prefix:=a_", "--package-path", root,
                                          "--publish-frequency", "50", "--frame-prefix", "x/",
                                          "--ros-args", "-r", "__ns:=/robot1"),
        # No robot_description parameter: ROS 2's joint_state_publisher reads the topic (/robot1's).
        "/robot1/joint_state_publisher": ("joint-state-publisher", "--package-path", root, "--zeros",
                                          "a_shoulder=0.5", "--source-list", "/extra_states",
                                          "--ros-args", "-r", "__ns:=/robot1"),
        # child=odom set by the include's <arg> wins over statics.launch.xml's default, two levels down.
        "/map_odom": ("static-transform-publisher", "--x", "1", "--y", "2", "--frame-id", "map",
                      "--child-frame-id", "odom", "--ros-args", "-r", "__node:=map_odom"),
        # $(var child) is still set after the include (ROS 2 includes do not scope), so rviz2 runs.
        "/rviz2": ("view", "--follow", "--package-path", root),
    }
    assert plan.skipped == ["/teleop (probe_description/teleop.py): no robotmodel equivalent, not started"]
    assert not any("namespace" in n for n in plan.notes)


def test_ros2_group_scopes_let_and_gui_argument(pkg, ros2_top, tmp_path):
    top = ros2_top
    plan = plan_of(top, pkg.root, tmp_path, gui="true", model=str(pkg.xacro))
    names = [p.name for p in plan.processes]
    assert names == ["/robot1/robot_state_publisher", "/robot1/joint_state_publisher_gui", "/map_odom", "/rviz2"]
    leak = pkg.launch("leak.launch.xml", """
        <launch>
          <group><let name="inner" value="1"/></group>
          <node pkg="tf2_ros" exec="static_transform_publisher" args="$(var inner)"/>
        </launch>
    """)
    with pytest.raises(LaunchError, match=r"leak\.launch\.xml:3: launch configuration 'inner' does not exist"):
        load_launch_file(leak, {}, [pkg.root])


def test_textfile_literal_value_and_search_up_the_namespace(pkg, tmp_path):
    urdf = pkg.dir / "urdf" / "plain.urdf"
    urdf.write_text('<robot name="r"><link name="a"/></robot>')
    path = pkg.launch("sensors.launch", f"""
        <launch>
          <param name="robot_description" textfile="$(find probe_description)/urdf/plain.urdf"/>
          <group ns="arm">
            <param name="robot_description" value="&lt;robot name='lit'&gt;&lt;link name='b'/&gt;&lt;/robot&gt;"/>
            <group ns="deeper">
              <node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp_arm"/>
            </group>
          </group>
          <node pkg="tf" type="static_transform_publisher" name="map_odom" args="0 0 0 0 0 0 map odom 100"/>
          <node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/>
          <node pkg="rviz" type="rviz" name="rviz" args="-d $(find probe_description)/x.rviz"/>
          <node pkg="probe_description" type="odom_sim.py" name="odom_sim"/>
          <node pkg="probe_description" type="scan_sim.py" name="scan_sim" env="{urdf}"/>
        </launch>
    """)
    plan = plan_of(path, pkg.root, tmp_path)
    lit = argv(plan)["/arm/deeper/rsp_arm"][1]
    assert Path(lit).read_text() == "<robot name='lit'><link name='b'/></robot>"
    assert argv(plan)["/rsp"] == ("robot-state-publisher", str(urdf), "--package-path", str(pkg.root),
                                  "--ros-args", "-r", "__node:=rsp")
    assert [p.name for p in plan.processes] == ["/arm/deeper/rsp_arm", "/map_odom", "/rsp", "/rviz"]
    assert [s.split(" ")[0] for s in plan.skipped] == ["/odom_sim", "/scan_sim"]


def test_substitutions(pkg, tmp_path, monkeypatch):
    monkeypatch.setenv("PROBE_SET", "from_env")
    monkeypatch.delenv("PROBE_UNSET", raising=False)
    path = pkg.launch("subs.launch", """
        <launch>
          <arg name="a" value="$(env PROBE_SET)"/>
          <arg name="b" value="$(optenv PROBE_UNSET fall back)"/>
          <arg name="c" value="$(eval a == 'from_env' and 3 > 2)"/>
          <arg name="d" value="$(eval arg('b').upper())"/>
          <arg name="e" value="$(dirname)"/>
          <node pkg="tf" type="static_transform_publisher" name="s"
                args="$(arg a) $(arg b) $(arg c) $(arg d) $(arg e) $(anon x) $(anon x)"/>
        </launch>
    """)
    words = argv(plan_of(path, pkg.root, tmp_path))["/s"][1:]
    assert words[-3:] == ("--ros-args", "-r", "__node:=s")
    # args are split on blanks, as the node's argv.
    assert words[:7] == ("from_env", "fall", "back", "True", "FALL", "BACK", str(path.parent))
    assert words[7] == words[8] and words[7].startswith("x_")


def test_ros2_substitutions(pkg, tmp_path):
    path = pkg.launch("subs.launch.xml", """
        <launch>
          <arg name="n" default="3"/>
          <let name="v" value="$(eval '$(var n) * math.pi / 3')"/>
          <let name="w" value="$(eval 'round(sqrt(16))')"/>
          <node pkg="tf2_ros" exec="static_transform_publisher" name="s"
                args="$(var v) $(var w) $(not false) $(and true 1) $(or 0 false) $(equals a a) $(env PROBE_NOPE dflt)
                      '$(find-pkg-share probe_description)'"/>
        </launch>
    """)
    words = argv(plan_of(path, pkg.root, tmp_path))["/s"][1:]
    assert words == ("3.141592653589793", "4", "true", "true", "false", "true", "dflt", str(pkg.dir),
                     "--ros-args", "-r", "__node:=s")


def test_pkg_file_form_and_dry_run_output(pkg, ros1_top, capsys):
    del ros1_top
    code = main(["launch", "probe_description", "top.launch", "--dry-run", "--package-path", str(pkg.root),
                 "gui:=true"])
    out = capsys.readouterr().out.splitlines()
    assert code == 0
    assert out[0] == "skipped: /sensors/scan_filter (probe_description/scan_filter.py): no robotmodel equivalent, " \
                     "not started"
    assert out[1:] == [
        f"/jsp_gui: robotmodel joint-state-publisher-gui {pkg.xacro} prefix:= --package-path {pkg.root} --open "
        "--ros-args -r __node:=jsp_gui",
        f"/rsp: robotmodel robot-state-publisher {pkg.xacro} prefix:= --package-path {pkg.root} "
        "--publish-frequency 50 --ros-args -r __node:=rsp",
        "/map_odom: robotmodel static-transform-publisher 1 2 0 0 0 0 map odom 100 --ros-args -r __node:=map_odom",
    ]


def test_jsp_use_gui_and_ros2_description_argument(pkg, tmp_path):
    path = pkg.launch("jsp.launch", """
        <launch>
          <param name="robot_description" textfile="$(find probe_description)/urdf/probe.urdf.xacro"/>
          <node pkg="joint_state_publisher" type="joint_state_publisher" name="old_gui">
            <param name="use_gui" value="true"/>
            <rosparam param="zeros">{shoulder: -0.25}</rosparam>
          </node>
        </launch>
    """)
    assert argv(plan_of(path, pkg.root, tmp_path)) == {
        "/old_gui": ("joint-state-publisher-gui", str(pkg.xacro), "--package-path", str(pkg.root),
                     "--joint=shoulder=-0.25", "--ros-args", "-r", "__node:=old_gui"),
    }
    path = pkg.launch("jsp.launch.xml", """
        <launch>
          <node pkg="joint_state_publisher" exec="joint_state_publisher" args="$(dirname)/../urdf/probe.urdf.xacro">
            <param name="rate" value="5"/>
          </node>
        </launch>
    """)
    assert argv(plan_of(path, pkg.root, tmp_path)) == {
        "/joint_state_publisher": ("joint-state-publisher", str(pkg.xacro), "--package-path", str(pkg.root),
                                   "--rate", "5"),
    }


def test_a_node_parameter_of_the_wrong_type_names_file_and_line(pkg, tmp_path):
    path = pkg.launch("rate.launch", """
        <launch>
          <node pkg="joint_state_publisher" type="joint_state_publisher" name="jsp">

            <param name="rate" value="fast"/>
          </node>
        </launch>
    """)
    with pytest.raises(LaunchError, match=r"rate\.launch:4: parameter 'rate' of /jsp must be a number, got 'fast'"):
        plan_of(path, pkg.root, tmp_path)


def test_ros1_find_inside_a_command_line_arg_is_resolved(pkg, ros1_top, tmp_path):
    # As urdf_tutorial's ROS 1 instructions: roslaunch ... model:='$(find pkg)/urdf/x.urdf'.
    other = pkg.dir / "urdf" / "other.urdf.xacro"
    other.write_text(pkg.xacro.read_text())
    path = pkg.launch("model.launch", """
        <launch>
          <arg name="model" default="$(find probe_description)/urdf/probe.urdf.xacro"/>
          <param name="robot_description" command="xacro $(arg model)"/>
          <node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/>
        </launch>
    """)
    plan = plan_of(path, pkg.root, tmp_path, model="$(find probe_description)/urdf/other.urdf.xacro")
    assert argv(plan)["/rsp"] == ("robot-state-publisher", str(other), "--package-path", str(pkg.root),
                                  "--ros-args", "-r", "__node:=rsp")


def test_ros2_find_exec_xacro_command(pkg, tmp_path):
    path = pkg.launch("exec.launch.xml", """
        <launch>
          <node pkg="robot_state_publisher" exec="robot_state_publisher">
            <param name="robot_description"
                   value="$(command '$(find-exec xacro) $(find-pkg-share probe_description)/urdf/probe.urdf.xacro')"/>
          </node>
        </launch>
    """)
    assert argv(plan_of(path, pkg.root, tmp_path)) == {
        "/robot_state_publisher": ("robot-state-publisher", str(pkg.xacro), "--package-path", str(pkg.root)),
    }


def test_ros2_command_inside_a_longer_value_is_expanded_in_process(pkg, tmp_path):
    path = pkg.launch("text.launch.xml", """
        <launch>
          <node pkg="robot_state_publisher" exec="robot_state_publisher">
            <param name="robot_description" value=" $(command 'xacro $(dirname)/../urdf/probe.urdf.xacro prefix:=t_')"/>
          </node>
        </launch>
    """)
    written = Path(argv(plan_of(path, pkg.root, tmp_path))["/robot_state_publisher"][1])
    assert written.parent == tmp_path
    import xml.etree.ElementTree as ET

    text = written.read_text()
    assert text.startswith("<?xml")  # the value's leading blank dropped, so the declaration still parses
    links = [e.get("name") for e in ET.fromstring(text.encode()).iter("link")]
    assert links == ["t_base_link", "t_arm", "t_tool"]


def test_ros1_jsp_reads_use_gui_and_rate_from_its_namespace(pkg, tmp_path):
    # The kinetic-era display.launch: <param name="use_gui"> at the top level, not in the node.
    path = pkg.launch("old_display.launch", """
        <launch>
          <arg name="gui" default="true"/>
          <param name="robot_description" command="$(find xacro)/xacro --inorder '$(find probe_description)/urdf/probe.urdf.xacro'"/>
          <param name="use_gui" value="$(arg gui)"/>
          <group ns="other"><param name="rate" value="99"/></group>
          <node name="joint_state_publisher" pkg="joint_state_publisher" type="joint_state_publisher"/>
        </launch>
    """)
    assert argv(plan_of(path, pkg.root, tmp_path)) == {
        # The GUI runs under the name the file gave it.
        "/joint_state_publisher": ("joint-state-publisher-gui", str(pkg.xacro), "--package-path", str(pkg.root),
                                   "--ros-args", "-r", "__node:=joint_state_publisher"),
    }
    assert argv(plan_of(path, pkg.root, tmp_path, gui="false")) == {
        "/joint_state_publisher": ("joint-state-publisher", str(pkg.xacro), "--package-path", str(pkg.root)),
    }


def test_viewer_gets_the_packages_the_launch_file_found(pkg, tmp_path):
    # Started by path with no --package-path, the launcher finds probe_description beside the
    # file; the viewer, which has only /robot_description's text, must be told where it is, or
    # the description's package:// meshes cannot resolve (they were drawn as placeholders).
    top = pkg.launch("display.launch", """
        <launch>
          <param name="robot_description" command="$(find xacro)/xacro $(find probe_description)/urdf/probe.urdf.xacro"/>
          <node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/>
          <node pkg="rviz" type="rviz" name="rviz"/>
        </launch>
    """)
    plan = build_plan(load_launch_file(top, {}), tmp_path, browser=False)
    assert argv(plan)["/rviz"][:4] == ("view", "--follow", "--package-path", str(pkg.dir.resolve()))
    # A path the user gave is not repeated.
    plan = plan_of(top, pkg.dir, tmp_path)
    assert argv(plan)["/rviz"].count("--package-path") == 1
