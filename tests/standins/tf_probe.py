"""A real rospy tf2_ros listener for tests/standins, run with Debian's /usr/bin/python3.

    tf_probe.py TARGET SOURCE

Prints ``ready`` once its node is up, then for every transform with a new stamp that
``Buffer.lookup_transform(TARGET, SOURCE, Time(0))`` gives: ``pose STAMP_NS x y z qx qy qz qw``.
"""

from __future__ import annotations

import sys

import rospy
import tf2_ros


def main() -> int:
    target, source = rospy.myargv()[1:3]
    rospy.init_node("tf_probe", anonymous=True)
    buffer = tf2_ros.Buffer()
    tf2_ros.TransformListener(buffer)
    print("ready", flush=True)
    last = None
    while not rospy.is_shutdown():
        try:
            t = buffer.lookup_transform(target, source, rospy.Time(0), rospy.Duration(0.1))
        except tf2_ros.TransformException:
            continue
        stamp = t.header.stamp.to_nsec()
        if stamp != last:
            last = stamp
            tr, q = t.transform.translation, t.transform.rotation
            print("pose", stamp, *(repr(v) for v in (tr.x, tr.y, tr.z, q.x, q.y, q.z, q.w)), flush=True)
        rospy.sleep(0.02)
    return 0


if __name__ == "__main__":
    sys.exit(main())
