from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, EmitEvent, IncludeLaunchDescription, RegisterEventHandler
from launch.conditions import IfCondition, UnlessCondition
from launch.event_handlers import OnProcessExit
from launch.events import Shutdown
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    ld = LaunchDescription()
    ld.add_action(DeclareLaunchArgument('urdf_package', description='Package holding the robot description'))
    ld.add_action(DeclareLaunchArgument('urdf_package_path',
                                        description='Path of the description inside that package'))
    ld.add_action(DeclareLaunchArgument(
        'rviz_config', default_value=PathJoinSubstitution([FindPackageShare('urdf_launch'), 'config', 'urdf.rviz']),
        description='Absolute path to the rviz config file'))
    ld.add_action(DeclareLaunchArgument('jsp_gui', default_value='true', choices=['true', 'false'],
                                        description='Flag to enable joint_state_publisher_gui'))
    ld.add_action(IncludeLaunchDescription(
        PathJoinSubstitution([FindPackageShare('urdf_launch'), 'launch', 'description.launch.py']),
        launch_arguments={'urdf_package': LaunchConfiguration('urdf_package'),
                          'urdf_package_path': LaunchConfiguration('urdf_package_path')}.items()))
    ld.add_action(Node(package='joint_state_publisher', executable='joint_state_publisher',
                       condition=UnlessCondition(LaunchConfiguration('jsp_gui'))))
    ld.add_action(Node(package='joint_state_publisher_gui', executable='joint_state_publisher_gui',
                       condition=IfCondition(LaunchConfiguration('jsp_gui'))))
    rviz = Node(package='rviz2', executable='rviz2', output='screen',
                arguments=['-d', LaunchConfiguration('rviz_config')])
    ld.add_action(rviz)
    ld.add_action(RegisterEventHandler(OnProcessExit(target_action=rviz, on_exit=[EmitEvent(event=Shutdown())])))
    return ld
