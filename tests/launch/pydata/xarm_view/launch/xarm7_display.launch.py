import os

from ament_index_python import get_package_share_directory
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, OpaqueFunction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def get_urdf_content(context, prefix):
    # xarm_ros2 builds the description in Python (its own xacro helper) inside an OpaqueFunction.
    urdf = os.path.join(get_package_share_directory('example-robot-data'), 'robots', 'xarm_description', 'urdf',
                        'xarm7.urdf')
    with open(urdf) as f:
        text = f.read()
    return text


def launch_setup(context, *args, **kwargs):
    prefix = LaunchConfiguration('prefix', default='')
    hw_ns = LaunchConfiguration('hw_ns', default='xarm')
    robot_description = {'robot_description': get_urdf_content(context, prefix.perform(context))}
    robot_state_publisher_node = Node(
        package='robot_state_publisher', executable='robot_state_publisher', output='screen',
        parameters=[robot_description, {'frame_prefix': prefix.perform(context)}],
        remappings=[('/tf', 'tf'), ('/tf_static', 'tf_static')])
    joint_state_publisher_node = Node(
        package='joint_state_publisher', executable='joint_state_publisher', name='joint_state_publisher',
        output='screen', parameters=[{'source_list': ['{}/joint_states'.format(hw_ns.perform(context))]}])
    return [robot_state_publisher_node, joint_state_publisher_node]


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('prefix', default_value='', description='frame prefix'),
        OpaqueFunction(function=launch_setup),
    ])
