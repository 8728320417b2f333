"""Joint states to TF as robot_state_publisher does, then a tf2 lookup through the result.

Run: python examples/robot_state_publisher.py
"""

from __future__ import annotations

import robotmodel.robots

from robotmodel.kinematics import KinematicModel, joint_transforms, static_transforms
from robotmodel.tf import Buffer, Time, make_transform


def main() -> None:
    """Publish the arm's TF for one joint state and look the gripper up in the world frame."""
    model = KinematicModel.load(robotmodel.robots.path("arm.urdf.xacro"))
    buffer = Buffer()
    statics = static_transforms(model)  # /tf_static: fixed joints
    for k in range(len(statics.joints)):
        buffer.set_transform_static(make_transform(statics.parents[k], statics.children[k], statics.translations[k],
                                                   statics.rotations[k]), "robot_state_publisher")
    stamp = Time(seconds=1.0)
    stamp_ns = stamp.nanoseconds
    state = {"arm_base_joint": 0.3, "arm_shoulder_joint": 0.5, "arm_elbow_joint": -0.8,
             "gripper_left_finger_joint": 0.01}
    moving = joint_transforms(model, state)  # /tf: joints in the message, plus their mimics
    for k in range(len(moving.joints)):
        buffer.set_transform(make_transform(moving.parents[k], moving.children[k], moving.translations[k],
                                            moving.rotations[k], stamp_ns), "robot_state_publisher")
    print("published:", ", ".join(moving.joints))
    # Joints absent from the message are not published, exactly as robot_state_publisher: the wrist
    # joints are missing, so the gripper is not connected yet.
    print("gripper reachable:", buffer.can_transform("world", "gripper_palm_link", stamp))
    rest = dict.fromkeys(("arm_wrist_pitch_joint", "arm_wrist_roll_joint", "arm_wrist_yaw_joint"), 0.0)
    more = joint_transforms(model, rest)
    for k in range(len(more.joints)):
        buffer.set_transform(make_transform(more.parents[k], more.children[k], more.translations[k],
                                            more.rotations[k], stamp_ns), "robot_state_publisher")
    t = buffer.lookup_transform("world", "gripper_palm_link", stamp)
    p = t.transform.translation
    print(f"gripper_palm_link in world at t=1 s: [{p.x:.4f}, {p.y:.4f}, {p.z:.4f}]")


if __name__ == "__main__":
    main()
