"""A description whose xacro fails stops the launch before anything starts, as roslaunch and ros2 launch do.

roslaunch runs a ``<param command="xacro ...">`` while it reads the file and ros2 launch a
``$(command 'xacro ...')`` as the node starts: a xacro error ends the launch with exit 1
and no node running. Here the launch file is read once up front (``--dry-run`` too), and the
error is one line naming the launch file and line, carrying xacro's own error.
"""

from __future__ import annotations

import pytest
from robotmodel.cli.main import main

BROKEN_XACRO = """<robot name="broken" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:include filename="$(find no_such_description)/urdf/parts.xacro"/>
  <link name="base_link"/>
</robot>
"""

LAUNCH = {
    "ros1": ("broken.launch", """
        <launch>
          <param name="robot_description" command="$(find xacro)/xacro $(find probe_description)/urdf/broken.urdf.xacro"/>
          <node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/>
          <node pkg="joint_state_publisher" type="joint_state_publisher" name="jsp"/>
          <node pkg="rviz" type="rviz" name="rviz"/>
        </launch>
    """, "Invalid <param> tag: Cannot load command parameter [robot_description]: command ["),
    "ros2": ("broken.launch.xml", """
        <launch>
          <node pkg="robot_state_publisher" exec="robot_state_publisher">
            <param name="robot_description"
                   value="$(command 'xacro $(find-pkg-share probe_description)/urdf/broken.urdf.xacro')"/>
          </node>
          <node pkg="joint_state_publisher" exec="joint_state_publisher"/>
        </launch>
    """, "executed command failed. Command: xacro "),
}
LINE = {"ros1": 2, "ros2": 3}


def broken(pkg, dialect: str):
    (pkg.dir / "urdf" / "broken.urdf.xacro").write_text(BROKEN_XACRO)
    name, text, words = LAUNCH[dialect]
    return pkg.launch(name, text), words


def xacro_error(pkg, capsys) -> str:
    """What ``robotmodel xacro`` says about the same file: the error the launch must carry."""
    code = main(["xacro", str(pkg.dir / "urdf" / "broken.urdf.xacro"), "--package-path", str(pkg.root)])
    err = capsys.readouterr().err.splitlines()
    assert code != 0 and len(err) == 1, err
    assert "no_such_description" in err[0]
    return err[0].split(": error: ", 1)[1]


@pytest.mark.parametrize("dialect", ["ros1", "ros2"])
def test_dry_run_refuses_a_failing_xacro_in_one_line(pkg, capsys, dialect):
    path, words = broken(pkg, dialect)
    expected = xacro_error(pkg, capsys)
    code = main(["launch", str(path), "--package-path", str(pkg.root), "--dry-run"])
    captured = capsys.readouterr()
    assert code == 1
    assert captured.out == ""  # no plan printed
    [line] = captured.err.splitlines()
    assert line.startswith(f"robotmodel launch: error: {path}:{LINE[dialect]}: {words}"), line
    assert expected in line


@pytest.mark.parametrize("dialect", ["ros1", "ros2"])
def test_run_exits_1_and_starts_nothing(pkg, live, capsys, dialect):
    path, _ = broken(pkg, dialect)
    expected = xacro_error(pkg, capsys)
    proc = live.robotmodel("launch", "--no-browser", "--package-path", str(pkg.root), str(path))
    # Before: the nodes started; the publishers died on the xacro error while the viewer (ROS 1)
    # or joint_state_publisher (ROS 2) waited for a robot_description, and the launch never ended.
    proc.wait_for(lambda: proc.popen.poll() is not None, 60, "launch exits")
    assert proc.stop() == 1
    assert not any("started with pid" in line for line in proc.err + proc.out), proc.err
    assert [line for line in proc.err if line.strip()] == [proc.err[0]]
    assert proc.err[0].startswith(f"robotmodel launch: error: {path}:{LINE[dialect]}: ")
    assert expected in proc.err[0]
