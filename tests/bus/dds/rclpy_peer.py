"""The real ROS 2 side of the DDS interop tests: rclpy (Jazzy, Fast DDS) in its own interpreter.

``python rclpy_peer.py ROLE [ARGS]`` prints ``ready`` once its node exists, then one line per
event, and ends when stdin closes. It imports only rclpy and ROS message packages, so it runs
in the interpreter ``ROBOTMODEL_RCLPY_PYTHON`` names, not in robotmodel's.

Roles:

- ``talker``: node ``rclpy_talker`` publishes std_msgs/String ``hello N`` on /chatter (QoS 10)
  every 50 ms and subscribes sensor_msgs/JointState on /rclpy_in.
- ``joint_listener``: node ``rclpy_listener`` prints ``got NAMES POSITIONS`` (JSON) per JointState
  on /joint_states.
- ``description_listener``: node ``rclpy_late`` subscribes /robot_description (reliable,
  transient local, depth 1) and prints ``got TEXT`` (JSON).
- ``graph NODE TOPIC``: node ``rclpy_observer`` prints ``nodes [[name, ns], ...]`` once NODE is
  listed, then ``publishers [...]`` with each publisher's node name and QoS on TOPIC.
- ``best_effort_talker``: node ``rclpy_be`` publishes std_msgs/String best effort on /qos_probe.
- ``describer FILE STATE``: node ``rclpy_describer`` publishes FILE's text once as std_msgs/String
  on /robot_description (reliable, transient local, depth 1, as robot_state_publisher does) and
  sensor_msgs/JointState STATE (JSON ``{name: position}``) on /joint_states every 50 ms.
- ``wrong_type_talker TOPIC``: node ``rclpy_wrong`` publishes std_msgs/String on TOPIC every 50 ms.
- ``bad_joints STATE``: node ``rclpy_bad_joints`` publishes on /joint_states every 50 ms a JointState
  with one more name than positions (invalid), then STATE (valid), alternately.
- ``latched_joint_listener``: node ``rclpy_tl_joints`` subscribes sensor_msgs/JointState on
  /joint_states, reliable and transient local, and prints ``event POLICY`` per incompatible publisher.
- ``latched_listener``: node ``rclpy_tl`` subscribes std_msgs/String on /qos_probe, reliable and
  transient local, and prints ``event POLICY`` for each incompatible publisher rclpy reports.
- ``params``: node ``rclpy_params`` declares parameters of several types, prints
  ``params {name: [type, value]}`` (JSON) of every parameter it lists, as its own
  ``get_parameters`` reports them, ``shown {name: text}`` of its array parameters as ros2param
  prints them (the str of the ParameterValue field), ``services [[name, [type, ...]], ...]`` as its own graph lists
  its service servers, and ``set [[name, value], ...]`` after each accepted set.
"""

from __future__ import annotations

import json
import sys
import threading

import rclpy
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy


def say(*parts: str) -> None:
    sys.stdout.write(" ".join(parts) + "\n")
    sys.stdout.flush()


def main(argv: list[str]) -> int:
    role, *args = argv
    rclpy.init()
    stop = threading.Event()
    threading.Thread(target=lambda: (sys.stdin.read(), stop.set()), daemon=True).start()
    if role == "talker":
        from sensor_msgs.msg import JointState
        from std_msgs.msg import String

        node = Node("rclpy_talker")
        pub = node.create_publisher(String, "/chatter", 10)
        node.create_subscription(JointState, "/rclpy_in", lambda m: None, 10)
        count = [0]

        def tick() -> None:
            count[0] += 1
            pub.publish(String(data=f"hello {count[0]}"))

        node.create_timer(0.05, tick)
    elif role == "joint_listener":
        from sensor_msgs.msg import JointState

        node = Node("rclpy_listener")
        node.create_subscription(JointState, "/joint_states",
                                 lambda m: say("got", json.dumps([list(m.name), list(m.position)])), 10)
    elif role == "description_listener":
        from std_msgs.msg import String

        node = Node("rclpy_late")
        qos = QoSProfile(depth=1, reliability=ReliabilityPolicy.RELIABLE, durability=DurabilityPolicy.TRANSIENT_LOCAL)
        node.create_subscription(String, "/robot_description", lambda m: say("got", json.dumps(m.data)), qos)
    elif role == "graph":
        wanted, topic = args
        node = Node("rclpy_observer")
        say("ready")
        while not stop.is_set():
            rclpy.spin_once(node, timeout_sec=0.1)
            nodes = node.get_node_names_and_namespaces()
            pubs = node.get_publishers_info_by_topic(topic)
            if any(n == wanted for n, _ in nodes) and pubs:
                say("nodes", json.dumps(sorted([n, ns] for n, ns in nodes)))
                say("publishers", json.dumps([{
                    "node": p.node_name, "namespace": p.node_namespace, "type": p.topic_type,
                    "reliability": p.qos_profile.reliability.name, "durability": p.qos_profile.durability.name,
                    "depth": p.qos_profile.depth} for p in pubs]))
                break
        stop.wait()
        node.destroy_node()
        rclpy.shutdown()
        return 0
    elif role == "best_effort_talker":
        from std_msgs.msg import String

        node = Node("rclpy_be")
        pub = node.create_publisher(String, "/qos_probe",
                                    QoSProfile(depth=10, reliability=ReliabilityPolicy.BEST_EFFORT))
        node.create_timer(0.05, lambda: pub.publish(String(data="be")))
    elif role == "describer":
        from pathlib import Path

        from sensor_msgs.msg import JointState
        from std_msgs.msg import String

        path, state_json = args
        state = json.loads(state_json)
        node = Node("rclpy_describer")
        latched = QoSProfile(depth=1, reliability=ReliabilityPolicy.RELIABLE,
                             durability=DurabilityPolicy.TRANSIENT_LOCAL)
        node.create_publisher(String, "/robot_description", latched).publish(String(data=Path(path).read_text()))
        joints = node.create_publisher(JointState, "/joint_states", 10)

        def send_state() -> None:
            msg = JointState(name=list(state), position=[float(v) for v in state.values()])
            msg.header.stamp = node.get_clock().now().to_msg()
            joints.publish(msg)

        node.create_timer(0.05, send_state)
    elif role == "wrong_type_talker":
        from std_msgs.msg import String

        (topic,) = args
        node = Node("rclpy_wrong")
        wrong = node.create_publisher(String, topic, 10)
        node.create_timer(0.05, lambda: wrong.publish(String(data="not a joint state")))
    elif role == "bad_joints":
        from sensor_msgs.msg import JointState

        state = json.loads(args[0])
        node = Node("rclpy_bad_joints")
        joints = node.create_publisher(JointState, "/joint_states", 10)
        flip = [False]

        def send() -> None:
            flip[0] = not flip[0]
            if flip[0]:
                msg = JointState(name=[*state, "extra_joint"], position=[float(v) for v in state.values()])
            else:
                msg = JointState(name=list(state), position=[float(v) for v in state.values()])
            msg.header.stamp = node.get_clock().now().to_msg()
            joints.publish(msg)

        node.create_timer(0.05, send)
    elif role == "latched_joint_listener":
        from rclpy.event_handler import SubscriptionEventCallbacks
        from sensor_msgs.msg import JointState

        node = Node("rclpy_tl_joints")
        qos = QoSProfile(depth=1, reliability=ReliabilityPolicy.RELIABLE, durability=DurabilityPolicy.TRANSIENT_LOCAL)
        events = SubscriptionEventCallbacks(incompatible_qos=lambda e: say("event", e.last_policy_kind.name))
        node.create_subscription(JointState, "/joint_states", lambda m: say("got", json.dumps(list(m.name))), qos,
                                 event_callbacks=events)
    elif role == "latched_listener":
        from rclpy.event_handler import SubscriptionEventCallbacks
        from std_msgs.msg import String

        node = Node("rclpy_tl")
        qos = QoSProfile(depth=1, reliability=ReliabilityPolicy.RELIABLE, durability=DurabilityPolicy.TRANSIENT_LOCAL)
        events = SubscriptionEventCallbacks(incompatible_qos=lambda e: say("event", e.last_policy_kind.name))
        node.create_subscription(String, "/qos_probe", lambda m: say("got", json.dumps(m.data)), qos,
                                 event_callbacks=events)
    elif role == "params":
        node = Node("rclpy_params")
        for name, value in (("rate", 12.5), ("id", 7), ("enabled", True), ("frame", "base_link"),
                            ("joints", ["shoulder", "elbow"]), ("gains", [0.5, 1.25]), ("ids", [3, 4])):
            node.declare_parameter(name, value)

        def plain(value: object) -> object:
            return value.tolist() if hasattr(value, "tolist") else list(value) if isinstance(value, tuple) else value

        names = node.list_parameters([], 0).names
        say("params", json.dumps({p.name: [p.type_.value, plain(p.value)] for p in node.get_parameters(names)}))
        # Each value as ros2param prints it: the str of the ParameterValue message's field for its type.
        fields = {6: "bool_array_value", 7: "integer_array_value", 8: "double_array_value", 9: "string_array_value"}
        say("shown", json.dumps({p.name: str(getattr(p.get_parameter_value(), fields[p.type_.value]))
                                 for p in node.get_parameters(names) if p.type_.value in fields}))
        say("services", json.dumps(node.get_service_names_and_types_by_node(node.get_name(), node.get_namespace())))
        node.add_post_set_parameters_callback(
            lambda params: say("set", json.dumps([[p.name, plain(p.value)] for p in params])))
    else:
        raise SystemExit(f"unknown role {role}")
    say("ready")
    while not stop.is_set():
        rclpy.spin_once(node, timeout_sec=0.1)
    node.destroy_node()
    rclpy.shutdown()
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
