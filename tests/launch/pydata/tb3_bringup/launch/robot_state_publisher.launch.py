import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import Command, LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    TURTLEBOT3_MODEL = os.environ['TURTLEBOT3_MODEL']
    use_sim_time = LaunchConfiguration('use_sim_time', default='false')
    namespace = LaunchConfiguration('namespace', default='')
    frame_prefix = LaunchConfiguration('frame_prefix', default='')
    urdf_file_name = 'turtlebot3_' + TURTLEBOT3_MODEL + '.urdf'
    print('urdf_file_name : {}'.format(urdf_file_name))
    urdf_path = os.path.join(get_package_share_directory('turtlebot3_description'), 'urdf', urdf_file_name)
    robot_description = Command(['xacro ', urdf_path, ' namespace:=', namespace])

    return LaunchDescription([
        DeclareLaunchArgument('use_sim_time', default_value='false',
                              description='Use simulation (Gazebo) clock if true'),
        DeclareLaunchArgument('namespace', default_value='', description='Prefix of the robot frames'),
        Node(package='robot_state_publisher', executable='robot_state_publisher', name='robot_state_publisher',
             output='screen',
             parameters=[{'use_sim_time': use_sim_time, 'publish_frequency': 10.0,
                          'robot_description': robot_description, 'frame_prefix': frame_prefix}]),
        Node(package='joint_state_publisher', executable='joint_state_publisher', name='joint_state_publisher',
             parameters=[{'use_sim_time': use_sim_time}]),
    ])
