"""The tf2 tutorials (broadcaster, static publisher, listener, turtle follower), in one process.

ROS 2's tutorial code with only the imports changed: a static broadcaster puts the camera
on the robot, a broadcaster publishes two turtles' poses in the world as they move, and a
listener asks where turtle1 is seen from turtle2 and steers turtle2 towards it.
Run: python examples/tf2_tutorial.py
"""

from __future__ import annotations

import math
import threading
import time

from robotmodel.tf import Buffer, Duration, Time, TransformStamped


def pose_message(parent: str, child: str, x: float, y: float, theta: float, stamp: Time) -> TransformStamped:
    """What the tutorial's broadcaster builds from a turtle's pose."""
    t = TransformStamped()
    t.header.stamp = stamp.to_msg()
    t.header.frame_id = parent
    t.child_frame_id = child
    t.transform.translation.x = x
    t.transform.translation.y = y
    t.transform.translation.z = 0.0
    t.transform.rotation.z = math.sin(theta / 2)
    t.transform.rotation.w = math.cos(theta / 2)
    return t


def main() -> None:
    """Run the follower for a few simulated seconds."""
    buffer = Buffer()
    # static_transform_publisher: a camera 0.1 m ahead of and 0.2 m above turtle2's centre.
    buffer.set_transform_static(pose_message("turtle2", "camera_link", 0.1, 0.0, 0.0, Time()), "static")
    buffer.lookup_transform("turtle2", "camera_link", Time())
    turtle1 = [5.0, 5.0, 0.0]
    turtle2 = [1.0, 1.0, 0.0]
    clock = [1_000_000_000]
    done = threading.Event()

    def broadcaster() -> None:
        for _ in range(300):
            clock[0] += 10_000_000
            turtle1[2] += 0.01
            turtle1[0] += 0.02 * math.cos(turtle1[2])
            turtle1[1] += 0.02 * math.sin(turtle1[2])
            stamp = Time(nanoseconds=clock[0])
            for name, (x, y, theta) in (("turtle1", turtle1), ("turtle2", turtle2)):
                buffer.set_transform(pose_message("world", name, x, y, theta, stamp), f"{name}_tf2_broadcaster")
            time.sleep(0.001)
        done.set()

    thread = threading.Thread(target=broadcaster)
    thread.start()
    while not done.is_set():
        # The listener: turtle1 as seen from turtle2, waiting for data as the tutorial does.
        t = buffer.lookup_transform("turtle2", "turtle1", Time(), timeout=Duration(seconds=1.0))
        dx, dy = t.transform.translation.x, t.transform.translation.y
        angular = 4.0 * math.atan2(dy, dx)
        linear = 0.5 * math.sqrt(dx * dx + dy * dy)
        turtle2[2] += angular * 0.01
        turtle2[0] += linear * 0.01 * math.cos(turtle2[2])
        turtle2[1] += linear * 0.01 * math.sin(turtle2[2])
        time.sleep(0.002)
    thread.join()
    final = buffer.lookup_transform("turtle2", "turtle1", Time())
    gap = math.hypot(final.transform.translation.x, final.transform.translation.y)
    print(f"turtle2 followed turtle1; distance now {gap:.2f} m (started at {math.hypot(4, 4):.2f} m)")


if __name__ == "__main__":
    main()
