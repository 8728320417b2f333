import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, IncludeLaunchDescription
from launch.conditions import UnlessCondition
from launch.substitutions import LaunchConfiguration, ThisLaunchFileDir
from launch_ros.actions import Node
from launch_xml.launch_description_sources import XMLLaunchDescriptionSource


def generate_launch_description():
    share = get_package_share_directory('xml_include')
    return LaunchDescription([
        DeclareLaunchArgument('prefix', default_value='', description='frame prefix'),
        DeclareLaunchArgument('gui', default_value='false', description='sliders'),
        IncludeLaunchDescription(
            XMLLaunchDescriptionSource([ThisLaunchFileDir(), '/rsp.launch.xml']),
            launch_arguments={'model': os.path.join(share, 'urdf', 'arm.urdf.xacro'),
                              'frame_prefix': LaunchConfiguration('prefix')}.items()),
        Node(package='joint_state_publisher', executable='joint_state_publisher',
             condition=UnlessCondition(LaunchConfiguration('gui'))),
    ])
