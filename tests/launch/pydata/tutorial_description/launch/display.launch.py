from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, IncludeLaunchDescription
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    ld = LaunchDescription()
    package = FindPackageShare('tutorial_description')
    ld.add_action(DeclareLaunchArgument('gui', default_value='true', choices=['true', 'false'],
                                        description='Flag to enable joint_state_publisher_gui'))
    ld.add_action(DeclareLaunchArgument('rvizconfig', default_value=PathJoinSubstitution([package, 'rviz',
                                                                                          'urdf.rviz']),
                                        description='Absolute path to rviz config file'))
    ld.add_action(DeclareLaunchArgument('model', default_value=PathJoinSubstitution(['urdf', 'arm.urdf.xacro']),
                                        description='Path to robot urdf file relative to urdf_tutorial package'))
    ld.add_action(IncludeLaunchDescription(
        PathJoinSubstitution([FindPackageShare('urdf_launch'), 'launch', 'display.launch.py']),
        launch_arguments={'urdf_package': 'tutorial_description',
                          'urdf_package_path': LaunchConfiguration('model'),
                          'rviz_config': LaunchConfiguration('rvizconfig'),
                          'jsp_gui': LaunchConfiguration('gui')}.items()))
    return ld
