from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.conditions import IfCondition
from launch.substitutions import Command, FindExecutable, LaunchConfiguration, PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.parameter_descriptions import ParameterValue
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    declared_arguments = []
    declared_arguments.append(DeclareLaunchArgument(
        'ur_type', description='Typo/series of used UR robot.',
        choices=['ur3', 'ur3e', 'ur5', 'ur5e', 'ur10', 'ur10e', 'ur16e', 'ur20', 'ur30']))
    declared_arguments.append(DeclareLaunchArgument(
        'safety_limits', default_value='true', description='Enables the safety limits controller if true.'))
    declared_arguments.append(DeclareLaunchArgument(
        'description_package', default_value='ur_description',
        description='Description package with robot URDF/XACRO files.'))
    declared_arguments.append(DeclareLaunchArgument(
        'description_file', default_value='ur.urdf.xacro', description='URDF/XACRO description file with the robot.'))
    declared_arguments.append(DeclareLaunchArgument(
        'tf_prefix', default_value='', description='Prefix of the joint names, useful for multi-robot setup.'))
    declared_arguments.append(DeclareLaunchArgument('gui', default_value='false', description='Start the sliders.'))

    ur_type = LaunchConfiguration('ur_type')
    description_package = LaunchConfiguration('description_package')
    robot_description_content = Command([
        PathJoinSubstitution([FindExecutable(name='xacro')]), ' ',
        PathJoinSubstitution([FindPackageShare(description_package), 'urdf',
                              LaunchConfiguration('description_file')]), ' ',
        'safety_limits:=', LaunchConfiguration('safety_limits'), ' ',
        'name:=', 'ur', ' ',
        'ur_type:=', ur_type, ' ',
        'tf_prefix:=', LaunchConfiguration('tf_prefix'),
    ])
    robot_description = {'robot_description': ParameterValue(robot_description_content, value_type=str)}
    rviz_config_file = PathJoinSubstitution([FindPackageShare(description_package), 'rviz', 'view_robot.rviz'])

    robot_state_publisher_node = Node(package='robot_state_publisher', executable='robot_state_publisher',
                                      output='both', parameters=[robot_description])
    joint_state_publisher_node = Node(package='joint_state_publisher', executable='joint_state_publisher')
    rviz_node = Node(package='rviz2', executable='rviz2', name='rviz2', output='log',
                     arguments=['-d', rviz_config_file],
                     condition=IfCondition(LaunchConfiguration('gui')))
    return LaunchDescription([*declared_arguments, joint_state_publisher_node, robot_state_publisher_node, rviz_node])
