from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, OpaqueFunction, TimerAction
from launch.conditions import LaunchConfigurationEquals, LaunchConfigurationNotEquals
from launch.substitutions import Command, FindExecutable, LaunchConfiguration, PathJoinSubstitution, PythonExpression
from launch_ros.actions import Node
from launch_ros.parameter_descriptions import ParameterValue
from launch_ros.substitutions import FindPackageShare


def launch_setup(context, *args, **kwargs):
    robot_model = LaunchConfiguration('robot_model')
    robot_name = LaunchConfiguration('robot_name')
    robot_description = ParameterValue(Command([
        FindExecutable(name='xacro'), ' ',
        PathJoinSubstitution([FindPackageShare('example-robot-data'), 'robots', 'so_arm_description', 'urdf',
                              PythonExpression(["'", robot_model, "' + '.urdf'"])]),
    ]), value_type=str)
    rsp = Node(package='robot_state_publisher', executable='robot_state_publisher', namespace=robot_name,
               parameters=[{'robot_description': robot_description}], output={'both': 'log'})
    jsp = Node(package='joint_state_publisher', executable='joint_state_publisher', namespace=robot_name,
               condition=LaunchConfigurationEquals('use_joint_pub', 'true'))
    jsp_gui = Node(package='joint_state_publisher_gui', executable='joint_state_publisher_gui',
                   namespace=robot_name, condition=LaunchConfigurationNotEquals('use_joint_pub', 'true'))
    return [rsp, TimerAction(period=0.5, actions=[jsp, jsp_gui])]


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('robot_model', choices=['so100', 'so101'], description='model type'),
        DeclareLaunchArgument('robot_name', default_value=LaunchConfiguration('robot_model'),
                              description='name of the robot (the namespace)'),
        DeclareLaunchArgument('use_joint_pub', default_value='true', choices=['true', 'false'],
                              description='launches the joint_state_publisher node'),
        OpaqueFunction(function=launch_setup),
    ])
