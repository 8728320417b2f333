"""Python launch files read in-process: scoping, parameters, --show-args, errors, and the import hook's bounds."""

from __future__ import annotations

import sys
import textwrap
from pathlib import Path

import pytest

from robotmodel.errors import LaunchError
from robotmodel.launch import build_plan
from robotmodel.launch._pyload import load_python_launch, show_arguments

HEAD = """\
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction, IncludeLaunchDescription, OpaqueFunction, TimerAction
from launch.actions import RegisterEventHandler
from launch.conditions import IfCondition, LaunchConfigurationEquals, UnlessCondition
from launch.event_handlers import OnProcessExit, OnProcessStart
from launch.substitutions import Command, EnvironmentVariable, LaunchConfiguration, PathJoinSubstitution
from launch.substitutions import PythonExpression, TextSubstitution
from launch_ros.actions import Node, PushRosNamespace, SetParameter, SetRemap
from launch_ros.parameter_descriptions import ParameterValue
from launch_ros.substitutions import FindPackageShare
"""


def write(pkg, name: str, body: str) -> Path:
    return pkg.launch(name, HEAD + textwrap.dedent(body))


def test_groups_scope_configurations_namespace_remaps_and_parameters(pkg) -> None:
    path = write(pkg, "scopes.launch.py", """
        def generate_launch_description():
            rsp = lambda **kw: Node(package='robot_state_publisher', executable='robot_state_publisher', **kw)
            return LaunchDescription([
                DeclareLaunchArgument('robot', default_value='r1'),
                SetRemap('/joint_states', '/all/joint_states'),
                GroupAction([
                    PushRosNamespace(LaunchConfiguration('robot')),
                    SetParameter('use_sim_time', True),
                    SetRemap('a', 'b'),
                    DeclareLaunchArgument('inner', default_value='x'),
                    rsp(name='inside', parameters=[{'robot_description': ParameterValue(Command(
                        ['xacro ', PathJoinSubstitution([FindPackageShare('probe_description'), 'urdf',
                                                         'probe.urdf.xacro']), ' prefix:=', LaunchConfiguration('robot'),
                         '_'])), 'zeros': {'j1': 1, 'j2': 2.5}, 'names': ['a', 'b'], 'mixed': [1, 2.5],
                        'flag': PythonExpression(["'", LaunchConfiguration('robot'), "' == 'r1'"])}]),
                ]),
                rsp(name='outside', namespace='/abs', parameters=[{'robot_description': '<robot name="x"/>',
                    'text': LaunchConfiguration('inner', default='gone')}]),
            ])
    """)
    launch = load_python_launch(path, {"robot": "r7"}, [pkg.root])
    inside, outside = launch.nodes
    assert (inside.name, inside.namespace, outside.name, outside.namespace) == ("inside", "/r7", "outside", "/abs")
    assert inside.scope_params == (("use_sim_time", "true"),) and outside.scope_params == ()
    # launch_ros: the scope's rules first (the root's list is shared, so 'a'->'b' outlives the group), then the node's.
    assert inside.remaps == (("/joint_states", "/all/joint_states"), ("a", "b"))
    assert outside.remaps == inside.remaps
    source = inside.params["robot_description"].xacro
    assert source is not None and source.file == pkg.xacro and source.mappings == (("prefix", "r7_"),)
    assert {k: inside.params[k].value for k in ("zeros.j1", "zeros.j2", "names", "mixed", "flag")} == {
        "zeros.j1": "1", "zeros.j2": "2.5", "names": "[a, b]", "mixed": "[1.0, 2.5]", "flag": "false"}
    # A Python string stays text; the group's argument is gone after it.
    assert outside.params["robot_description"].value == '<robot name="x"/>'
    assert outside.params["text"].value == "gone"


def test_plan_maps_nodes_and_lists_the_rest_as_skipped(pkg, tmp_path: Path) -> None:
    path = write(pkg, "plan.launch.py", """
        def generate_launch_description():
            gui = LaunchConfiguration('gui')
            desc = {'robot_description': ParameterValue(Command(['xacro ', str(__import__('pathlib').Path(
                __file__).parent.parent / 'urdf' / 'probe.urdf.xacro')]), value_type=str)}
            last = Node(package='robot_state_publisher', executable='robot_state_publisher', parameters=[desc])
            return LaunchDescription([
                DeclareLaunchArgument('gui', default_value='true'),
                RegisterEventHandler(OnProcessExit(target_action=last, on_exit=[
                    Node(package='controller_manager', executable='spawner', arguments=['jsb'])])),
                TimerAction(period=2.0, actions=[Node(package='tf2_ros', executable='static_transform_publisher',
                    arguments=['--frame-id', 'map', '--child-frame-id', 'odom'])]),
                RegisterEventHandler(OnProcessStart(target_action=last, on_start=[
                    Node(package='joint_state_publisher', executable='joint_state_publisher',
                         condition=UnlessCondition(gui))])),
                Node(package='joint_state_publisher_gui', executable='joint_state_publisher_gui',
                     condition=IfCondition(gui)),
                last,
                OpaqueFunction(function=lambda context: [Node(package='my_pkg', executable='driver',
                    name=LaunchConfiguration('gui').perform(context) + '_driver')]),
            ])
    """)
    launch = load_python_launch(path, {"gui": "false"}, [pkg.root])
    plan = build_plan(launch, tmp_path, package_paths=[pkg.root], browser=False)
    # Deferred actions in launch's order: process starts, timers by period, process exits.
    assert [p.kind for p in plan.processes] == ["robot_state_publisher", "joint_state_publisher",
                                                "static_transform_publisher"]
    assert plan.skipped == ["/false_driver (my_pkg/driver): no robotmodel equivalent, not started",
                            "/spawner (controller_manager/spawner): no robotmodel equivalent, not started"]
    assert sum("ordering only" in n for n in plan.notes) == 3


def test_show_args_prints_what_ros2_launch_prints(pkg) -> None:
    path = write(pkg, "args.launch.py", """
        def generate_launch_description():
            return LaunchDescription([
                DeclareLaunchArgument('model', default_value=PathJoinSubstitution([FindPackageShare('probe_description'),
                                                                                  'urdf', 'probe.urdf.xacro']),
                                      description='Absolute path to robot urdf file'),
                DeclareLaunchArgument('gui', default_value='true', choices=['true', 'false']),
                DeclareLaunchArgument('ns', description='Namespace.', condition=IfCondition('true')),
                GroupAction([DeclareLaunchArgument('rate', default_value=[LaunchConfiguration('gui'), '0'])]),
            ])
    """)
    assert show_arguments(path, [pkg.root]) == textwrap.dedent("""\
        Arguments (pass arguments as '<name>:=<value>'):

            'model':
                Absolute path to robot urdf file
                (default: PathJoin('FindPackageShare(pkg='probe_description') + 'urdf' + 'probe.urdf.xacro''))

            'gui':
                One of: ['true', 'false']
                (default: 'true')

            'ns':*
                Namespace.

            'rate':
                no description given
                (default: LaunchConfig('gui') + '0')

        * argument(s) which are only used if specific conditions occur
        """)


@pytest.mark.parametrize(("body", "args", "message"), [
    ("return LaunchDescription([DeclareLaunchArgument('ur_type', description='UR series.')])", {},
     "Included launch description missing required argument 'ur_type' (description: 'UR series.'), given: []"),
    ("return LaunchDescription([DeclareLaunchArgument('gui', default_value='true', choices=['true', 'false'])])",
     {"gui": "yes"}, "Argument \"gui\" provided value \"yes\" is not valid. Valid options are: ['true', 'false']"),
    ("return LaunchDescription([Node(package='p', executable='e', condition=IfCondition('maybe'))])", {},
     "invalid condition expression, expected one of [true, 1, false, 0] but got 'maybe'"),
    ("return LaunchDescription([Node(package='p', executable='e', name=LaunchConfiguration('nope'))])", {},
     "launch configuration 'nope' does not exist"),
    ("raise ValueError('bad robot')", {}, "Caught exception in launch (see debug for traceback): bad robot"),
    ("return LaunchDescription([Node(package='p', executable='e', parameters=[{'d': Command('cat /etc/hosts')}])])",
     {}, "command 'cat /etc/hosts': only xacro commands are run, not 'cat'"),
])
def test_bad_input_is_one_line_naming_the_file(pkg, body: str, args: dict[str, str], message: str) -> None:
    path = write(pkg, "bad.launch.py", f"def generate_launch_description():\n    {body}\n")
    with pytest.raises(LaunchError) as info:
        load_python_launch(path, args, [pkg.root])
    text = str(info.value)
    assert message in text and text.startswith(str(path)) and "\n" not in text


def test_standins_exist_only_during_the_run_and_shadow_a_real_launch(pkg, tmp_path: Path,
                                                                     monkeypatch: pytest.MonkeyPatch) -> None:
    # A "real" launch package on sys.path: the run must use the stand-ins, and leave it importable after.
    real = tmp_path / "site"
    (real / "launch").mkdir(parents=True)
    (real / "launch" / "__init__.py").write_text("REAL = True\n")
    monkeypatch.syspath_prepend(str(real))
    path = write(pkg, "probe.launch.py", """
        import launch
        import ament_index_python.packages as aip
        SEEN = (hasattr(launch, 'REAL'), aip.get_package_share_directory('probe_description'))

        def generate_launch_description():
            return LaunchDescription([Node(package='p', executable='e', name='n' + str(SEEN[0]),
                                           arguments=[SEEN[1]])])
    """)
    launch = load_python_launch(path, {}, [pkg.root])
    assert launch.nodes[0].name == "nFalse" and launch.nodes[0].args == str(pkg.dir)
    import launch as after  # the real one again

    assert after.REAL is True
    monkeypatch.delitem(sys.modules, "launch")
    assert "launch_ros" not in sys.modules and "ament_index_python" not in sys.modules


def test_yaml_launch_file_on_its_own_reads_as_its_xml_equivalent(pkg) -> None:
    from robotmodel.launch._pysources import load_yaml_launch

    path = pkg.launch("display.launch.yaml", f"""
        launch:
        - arg:
            name: gui
            default: "false"
        - group:
            children:
            - push-ros-namespace:
                namespace: arm
            - node:
                pkg: robot_state_publisher
                exec: robot_state_publisher
                param:
                - name: robot_description
                  value: $(command 'xacro {pkg.xacro} prefix:=y_')
                - name: zeros
                  param:
                  - name: y_shoulder
                    value: 0.5
                remap:
                - from: joint_states
                  to: /all_states
        - node:
            pkg: joint_state_publisher_gui
            exec: joint_state_publisher_gui
            if: $(var gui)
    """)
    launch = load_yaml_launch(path, {"gui": "true"}, [pkg.root])
    rsp, gui = launch.nodes
    assert (rsp.namespace, gui.namespace, gui.line) == ("/arm", "/", 22)  # the "- node:" line
    assert rsp.params["robot_description"].xacro is not None
    assert rsp.params["robot_description"].xacro.mappings == (("prefix", "y_"),)
    assert rsp.params["zeros.y_shoulder"].value == "0.5"
    assert rsp.remaps == (("joint_states", "/all_states"),)
    assert load_yaml_launch(path, {}, [pkg.root]).nodes[1:] == []


def test_ros2_xml_includes_python_and_yaml_launch_files_in_its_scope(pkg) -> None:
    from robotmodel.launch import load_launch_file

    write(pkg, "rsp.launch.py", """
        def generate_launch_description():
            return LaunchDescription([
                DeclareLaunchArgument('prefix'),
                Node(package='robot_state_publisher', executable='robot_state_publisher', name='rsp_py',
                     parameters=[{'frame_prefix': LaunchConfiguration('prefix')}]),
            ])
    """)
    pkg.launch("jsp.launch.yaml", """
        launch:
        - node:
            pkg: joint_state_publisher
            exec: joint_state_publisher
            name: jsp_yaml
    """)
    top = pkg.launch("top.launch.xml", """
        <launch>
          <set_remap from="joint_states" to="/arm/joint_states"/>
          <group>
            <push-ros-namespace namespace="arm"/>
            <include file="$(dirname)/rsp.launch.py"><arg name="prefix" value="a/"/></include>
            <include file="$(dirname)/jsp.launch.yaml"/>
          </group>
        </launch>
    """)
    rsp, jsp = load_launch_file(top, {}, [pkg.root]).nodes
    assert (rsp.full_name, rsp.params["frame_prefix"].value, jsp.full_name) == ("/arm/rsp_py", "a/", "/arm/jsp_yaml")
    assert rsp.remaps == jsp.remaps == (("joint_states", "/arm/joint_states"),)
    ros1 = pkg.launch("top.launch", '<launch><include file="$(find probe_description)/launch/rsp.launch.py"/></launch>')
    assert load_launch_file(ros1, {}, [pkg.root]).skipped == [
        f"<include> {pkg.dir / 'launch' / 'rsp.launch.py'} ({ros1}:1): roslaunch reads only XML launch files"]


def test_a_static_include_passing_a_required_argument_is_accepted_and_shown(pkg) -> None:
    write(pkg, "inner.launch.py", """
        def generate_launch_description():
            return LaunchDescription([
                DeclareLaunchArgument('robot', description='Which robot.'),
                Node(package='robot_state_publisher', executable='robot_state_publisher',
                     name=LaunchConfiguration('robot')),
            ])
    """)
    outer = write(pkg, "outer.launch.py", """
        import os

        def generate_launch_description():
            inner = os.path.join(os.path.dirname(__file__), 'inner.launch.py')
            return LaunchDescription([IncludeLaunchDescription(inner, launch_arguments={'robot': 'r2'}.items())])
    """)
    # ros2 launch counts the names a statically known nested include passes (launch's best effort).
    assert [n.name for n in load_python_launch(outer, {}, [pkg.root]).nodes] == ["r2"]
    assert "'robot':\n        Which robot." in show_arguments(outer, [pkg.root])


def test_the_dotted_style_of_older_launch_files_works(pkg) -> None:
    path = pkg.launch("dotted.launch.py", """
        import launch
        import launch_ros


        def generate_launch_description():
            return launch.LaunchDescription([
                launch.actions.DeclareLaunchArgument(name='gui', default_value='False'),
                launch_ros.actions.Node(package='joint_state_publisher', executable='joint_state_publisher',
                                        condition=launch.conditions.UnlessCondition(
                                            launch.substitutions.LaunchConfiguration('gui'))),
            ])
    """)
    assert [n.executable for n in load_python_launch(path, {}, [pkg.root]).nodes] == ["joint_state_publisher"]


def test_environment_actions_and_other_event_handlers(pkg, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("RM_TEST_PATH", "/a")
    path = write(pkg, "env.launch.py", """
        from launch.actions import AppendEnvironmentVariable, SetEnvironmentVariable
        from launch.event_handlers import OnShutdown

        def generate_launch_description():
            return LaunchDescription([
                AppendEnvironmentVariable('RM_TEST_PATH', '/b'),
                SetEnvironmentVariable('RM_TEST_NAME', 'r'),
                RegisterEventHandler(OnShutdown(on_shutdown=[])),
                Node(package='p', executable='e', name=EnvironmentVariable('RM_TEST_NAME'),
                     arguments=[EnvironmentVariable('RM_TEST_PATH')]),
            ])
    """)
    launch = load_python_launch(path, {}, [pkg.root])
    assert (launch.nodes[0].name, launch.nodes[0].args) == ("r", "/a:/b")
    assert any("OnShutdown event handler ignored" in n for n in launch.notes)


def test_install_layout_package_runs_by_name_with_dry_run(pkg, tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
                                                         capsys: pytest.CaptureFixture[str]) -> None:
    from robotmodel.launch import run_launch

    # A colcon install prefix: share/<pkg>/ plus the ament index marker; the launch file reaches the
    # source-tree package probe_description through --package-path.
    prefix = tmp_path / "install"
    share = prefix / "share" / "my_robot_bringup"
    (share / "launch").mkdir(parents=True)
    (prefix / "share" / "ament_index" / "resource_index" / "packages").mkdir(parents=True)
    (prefix / "share" / "ament_index" / "resource_index" / "packages" / "my_robot_bringup").write_text("")
    (share / "package.xml").write_text((pkg.dir / "package.xml").read_text().replace("probe_description",
                                                                                     "my_robot_bringup"))
    (share / "launch" / "bringup.launch.py").write_text(HEAD + textwrap.dedent("""
        def generate_launch_description():
            urdf = PathJoinSubstitution([FindPackageShare('probe_description'), 'urdf', 'probe.urdf.xacro'])
            return LaunchDescription([Node(package='robot_state_publisher', executable='robot_state_publisher',
                parameters=[{'robot_description': ParameterValue(Command(['xacro ', urdf]), value_type=str),
                             'publish_frequency': 5.0, 'label': FindPackageShare('my_robot_bringup')}])])
    """))
    monkeypatch.setenv("AMENT_PREFIX_PATH", str(prefix))
    assert run_launch("my_robot_bringup", "bringup.launch.py", {}, package_paths=[str(pkg.root)], dry_run=True) == 0
    out = capsys.readouterr().out.splitlines()
    assert out == [f"/robot_state_publisher: robotmodel robot-state-publisher {pkg.xacro} --package-path {pkg.root} "
                   f"--publish-frequency 5.0 --ros-args -p label:={share}"]
