from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, IncludeLaunchDescription
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.substitutions import FindPackageShare
from launch_yaml.launch_description_sources import YAMLLaunchDescriptionSource


def generate_launch_description():
    share = FindPackageShare('yaml_include')
    return LaunchDescription([
        DeclareLaunchArgument('model', default_value=PathJoinSubstitution([share, 'urdf', 'diffbot.urdf.xacro'])),
        IncludeLaunchDescription(
            YAMLLaunchDescriptionSource(PathJoinSubstitution([share, 'launch', 'state_publishers.launch.yaml'])),
            launch_arguments=[('model', LaunchConfiguration('model')), ('rate', '25')]),
    ])
