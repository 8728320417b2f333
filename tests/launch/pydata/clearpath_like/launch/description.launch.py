from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction
from launch.substitutions import Command, EnvironmentVariable, FindExecutable, LaunchConfiguration
from launch.substitutions import PathJoinSubstitution
from launch_ros.actions import Node, PushRosNamespace, SetParameter, SetRemap
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    namespace = LaunchConfiguration('namespace')
    use_sim_time = LaunchConfiguration('use_sim_time')
    robot_description_command = LaunchConfiguration('robot_description_command')
    robot_urdf = PathJoinSubstitution([FindPackageShare('clearpath_like'), 'urdf', 'skid_steer.urdf.xacro'])
    arg_namespace = DeclareLaunchArgument('namespace', default_value=EnvironmentVariable('ROBOT_NAMESPACE',
                                                                                         default_value=''),
                                          description='Robot namespace')
    arg_use_sim_time = DeclareLaunchArgument('use_sim_time', choices=['true', 'false'], default_value='false',
                                             description='Use simulation time')
    arg_robot_description_command = DeclareLaunchArgument(
        'robot_description_command', default_value=[PathJoinSubstitution([FindExecutable(name='xacro')]), ' ',
                                                    robot_urdf],
        description='Robot description command.')
    group_action_state_publishers = GroupAction([
        PushRosNamespace(namespace),
        SetParameter('use_sim_time', use_sim_time),
        SetRemap('/tf', 'tf'),
        SetRemap('/tf_static', 'tf_static'),
        Node(package='robot_state_publisher', executable='robot_state_publisher', name='robot_state_publisher',
             output='screen',
             parameters=[{'robot_description': Command(robot_description_command)}]),
        Node(package='joint_state_publisher', executable='joint_state_publisher', name='joint_state_publisher',
             output='screen'),
    ])
    ld = LaunchDescription()
    ld.add_action(arg_namespace)
    ld.add_action(arg_use_sim_time)
    ld.add_action(arg_robot_description_command)
    ld.add_action(group_action_state_publishers)
    return ld
