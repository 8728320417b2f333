"""A real rospy tf2_ros listener for tests/ros1, run with Debian's /usr/bin/python3 (not the project's venv).

    tf2_listener.py [--joint-states] TARGET SOURCE [TARGET SOURCE ...]

Prints ``ready`` once its node is up, then for each pair the first transform tf2_ros's
``Buffer.lookup_transform(TARGET, SOURCE, Time(0))`` gives, as ``pose TARGET SOURCE x y z qx qy qz
qw`` (repr floats), and with ``--joint-states`` the first /joint_states message it gets, as
``joints name=value ...``. Then it spins until killed.
"""

from __future__ import annotations

import sys
import threading

import rospy
import tf2_ros
from sensor_msgs.msg import JointState

_out = threading.Lock()


def say(*words: str) -> None:
    """One whole line (rospy's callback thread prints too)."""
    with _out:
        sys.stdout.write(" ".join(words) + "\n")
        sys.stdout.flush()


def main() -> int:
    argv = rospy.myargv()[1:]
    joint_states = "--joint-states" in argv
    names = [a for a in argv if a != "--joint-states"]
    pending = list(zip(names[::2], names[1::2], strict=True))
    rospy.init_node("tf2_listener", anonymous=True)
    buffer = tf2_ros.Buffer()
    tf2_ros.TransformListener(buffer)
    if joint_states:
        seen: list[bool] = []

        def on_joints(msg: JointState) -> None:
            if not seen:
                seen.append(True)
                say("joints", *(f"{n}={p!r}" for n, p in zip(msg.name, msg.position, strict=False)))

        rospy.Subscriber("/joint_states", JointState, on_joints)
    say("ready")
    while pending and not rospy.is_shutdown():
        for target, source in list(pending):
            try:
                t = buffer.lookup_transform(target, source, rospy.Time(0), rospy.Duration(0.1))
            except tf2_ros.TransformException:
                continue
            tr, q = t.transform.translation, t.transform.rotation
            say("pose", target, source, *(repr(v) for v in (tr.x, tr.y, tr.z, q.x, q.y, q.z, q.w)))
            pending.remove((target, source))
    rospy.spin()
    return 0


if __name__ == "__main__":
    sys.exit(main())
