"""A parameter the command takes as a flag and the same one in a params file: the later one wins.

launch_ros passes a node's inline parameters and params files in the file's order, and rcl
lets the later value of a name replace the earlier one; a flag would lose to any file.
"""

from __future__ import annotations

from robotmodel.launch import build_plan, load_launch_file


def rsp_argv(pkg, tmp_path, body: str) -> tuple[str, ...]:
    (pkg.dir / "rsp.yaml").write_text("/rsp:\n  ros__parameters:\n    publish_frequency: 10.0\n"
                                       "    frame_prefix: from_file/\n", encoding="utf-8")
    path = pkg.launch("order.launch.xml", f"""
        <launch>
          <node pkg="robot_state_publisher" exec="robot_state_publisher" name="rsp">
            <param name="robot_description" value="$(command 'xacro $(find-pkg-share probe_description)/urdf/probe.urdf.xacro')"/>
            {body}
          </node>
        </launch>
    """)
    plan = build_plan(load_launch_file(path, {}, [pkg.root]), tmp_path, package_paths=[pkg.root], browser=False)
    return plan.processes[0].argv


def test_inline_parameter_after_the_params_file_wins(pkg, tmp_path):
    words = rsp_argv(pkg, tmp_path, """
        <param from="$(find-pkg-share probe_description)/rsp.yaml"/>
        <param name="publish_frequency" value="30.0"/>
        <param name="frame_prefix" value="inline/"/>
    """)
    tail = words[words.index("--ros-args") + 1:]
    assert "--publish-frequency" not in words and "--frame-prefix" not in words
    assert tail == ("-r", "__node:=rsp", "--params-file", str(pkg.dir / "rsp.yaml"),
                    "-p", "publish_frequency:=30.0", "-p", "frame_prefix:=inline/")


def test_params_file_after_the_inline_parameter_wins(pkg, tmp_path):
    words = rsp_argv(pkg, tmp_path, """
        <param name="publish_frequency" value="30.0"/>
        <param from="$(find-pkg-share probe_description)/rsp.yaml"/>
    """)
    # The flag sets the default the params file then overrides, as ROS's order has it.
    assert words[words.index("--publish-frequency") + 1] == "30.0"
    assert words[words.index("--ros-args") + 1:] == ("-r", "__node:=rsp", "--params-file", str(pkg.dir / "rsp.yaml"))


def test_joint_state_publisher_rate_and_zeros_after_the_params_file(pkg, tmp_path):
    (pkg.dir / "jsp.yaml").write_text("/**:\n  ros__parameters:\n    rate: 5\n", encoding="utf-8")
    path = pkg.launch("jsp.launch.xml", """
        <launch>
          <node pkg="joint_state_publisher" exec="joint_state_publisher" name="jsp">
            <param name="rate" value="20"/>
            <param from="$(find-pkg-share probe_description)/jsp.yaml"/>
            <param name="zeros"><param name="shoulder" value="0.5"/></param>
          </node>
        </launch>
    """)
    plan = build_plan(load_launch_file(path, {}, [pkg.root]), tmp_path, package_paths=[pkg.root], browser=False)
    words = plan.processes[0].argv
    # rate came first: a flag the file overrides; zeros came after: -p after the file.
    assert words[words.index("--rate") + 1] == "20" and "--zeros" not in words
    assert words[words.index("--ros-args") + 1:] == ("-r", "__node:=jsp", "--params-file", str(pkg.dir / "jsp.yaml"),
                                                     "-p", "zeros.shoulder:=0.5")
