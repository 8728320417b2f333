"""The real ROS 2 side of the parameter-services case: Jazzy's rclpy AsyncParameterClient, on Fast DDS.

``python rclpy_param_setter.py NODE VALUE_FILE`` waits for NODE's parameter services, prints
``ready``, then sets NODE's ``robot_description`` to VALUE_FILE's text, spinning up to 2 s
for the answer, and watches /robot_description (reliable, transient local, as RSP publishes
it); it sets again, as a user retries ``ros2 param set``, until /robot_description carries the
new text (at most 10 times). It prints ``answered True|False`` (whether any answer came) and
``description changed after N sets`` (or ``description unchanged``). It imports only rclpy
and std_msgs, so it runs in the interpreter ``ROBOTMODEL_RCLPY_PYTHON`` names.
"""

import sys
from pathlib import Path

import rclpy
from rclpy.node import Node
from rclpy.parameter import Parameter
from rclpy.parameter_client import AsyncParameterClient
from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy
from std_msgs.msg import String


def main(remote: str, value_file: str) -> None:
    text = Path(value_file).read_text()
    rclpy.init()
    node = Node("rclpy_param_setter")
    seen = []
    latched = QoSProfile(depth=1, reliability=ReliabilityPolicy.RELIABLE, durability=DurabilityPolicy.TRANSIENT_LOCAL)
    node.create_subscription(String, "/robot_description", lambda m: seen.append(m.data), latched)
    client = AsyncParameterClient(node, remote)
    if not client.wait_for_services(timeout_sec=60.0):
        print("no services", flush=True)
        return
    print("ready", flush=True)
    answered = False
    for attempt in range(1, 11):
        future = client.set_parameters([Parameter("robot_description", value=text)])
        rclpy.spin_until_future_complete(node, future, timeout_sec=2.0)
        answered = answered or future.done()
        if seen and seen[-1] == text:
            print("answered", answered, flush=True)
            print("description changed after", attempt, "sets", flush=True)
            break
    else:
        print("answered", answered, flush=True)
        print("description unchanged", flush=True)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main(*sys.argv[1:3])
