from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import Command, LaunchConfiguration, PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.parameter_descriptions import ParameterValue
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    ld = LaunchDescription()
    ld.add_action(DeclareLaunchArgument('urdf_package', description='Package holding the robot description'))
    ld.add_action(DeclareLaunchArgument('urdf_package_path',
                                        description='Path of the description inside that package'))
    urdf = PathJoinSubstitution([FindPackageShare(LaunchConfiguration('urdf_package')),
                                 LaunchConfiguration('urdf_package_path')])
    description = ParameterValue(Command(['xacro ', urdf]), value_type=str)
    ld.add_action(Node(package='robot_state_publisher', executable='robot_state_publisher',
                       parameters=[{'robot_description': description}]))
    return ld
