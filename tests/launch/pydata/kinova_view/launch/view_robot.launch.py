from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.conditions import IfCondition, UnlessCondition
from launch.substitutions import Command, FindExecutable, LaunchConfiguration, PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    declared_arguments = [
        DeclareLaunchArgument('description_package', default_value='example-robot-data',
                              description='Description package with robot URDF/xacro files.'),
        DeclareLaunchArgument('description_file', default_value='robots/kinova_description/robots/kinova.urdf',
                              description='URDF/XACRO description file with the robot.'),
        DeclareLaunchArgument('prefix', default_value='',
                              description='Prefix of the joint names, useful for multi-robot setup.'),
        DeclareLaunchArgument('gripper', default_value='', description='Name of the gripper attached to the arm'),
        DeclareLaunchArgument('gui', default_value='false', description='Start joint_state_publisher_gui'),
        DeclareLaunchArgument('launch_rviz', default_value='false', description='Launch RViz?'),
    ]
    robot_description_content = Command([
        PathJoinSubstitution([FindExecutable(name='xacro')]), ' ',
        PathJoinSubstitution([FindPackageShare(LaunchConfiguration('description_package')),
                              LaunchConfiguration('description_file')]),
    ])
    robot_description = {'robot_description': robot_description_content}
    robot_state_publisher_node = Node(
        package='robot_state_publisher', executable='robot_state_publisher', output='both',
        parameters=[robot_description, {'frame_prefix': LaunchConfiguration('prefix')}])
    joint_state_publisher_node = Node(package='joint_state_publisher', executable='joint_state_publisher',
                                      condition=UnlessCondition(LaunchConfiguration('gui')))
    joint_state_publisher_gui_node = Node(package='joint_state_publisher_gui',
                                          executable='joint_state_publisher_gui',
                                          condition=IfCondition(LaunchConfiguration('gui')))
    rviz_node = Node(package='rviz2', executable='rviz2', name='rviz2', output='log',
                     condition=IfCondition(LaunchConfiguration('launch_rviz')))
    return LaunchDescription(declared_arguments + [joint_state_publisher_node, joint_state_publisher_gui_node,
                                                   robot_state_publisher_node, rviz_node])
