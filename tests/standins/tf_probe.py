"""A real rospy tf2_ros listener for tests/standins, run with Debian's /usr/bin/python3 (or as robotmodel's).

    tf_probe.py TARGET SOURCE [SOURCE...]

Prints ``ready`` once its node is up, then for every transform with a new stamp that
``Buffer.lookup_transform(TARGET, SOURCE, Time(0))`` gives: ``pose SOURCE STAMP_NS x y z qx qy qz qw``.
"""

import sys

import rospy
import tf2_ros


def main():
    words = rospy.myargv()
    target, sources = words[1], words[2:]
    rospy.init_node("tf_probe", anonymous=True)
    buffer = tf2_ros.Buffer()
    tf2_ros.TransformListener(buffer)
    print("ready", flush=True)
    last = {}
    while not rospy.is_shutdown():
        for source in sources:
            try:
                t = buffer.lookup_transform(target, source, rospy.Time(0), rospy.Duration(0.05))
            except tf2_ros.TransformException:
                continue
            stamp = t.header.stamp.to_nsec()
            if stamp != last.get(source):
                last[source] = stamp
                tr, q = t.transform.translation, t.transform.rotation
                values = (tr.x, tr.y, tr.z, q.x, q.y, q.z, q.w)
                print("pose", source, stamp, *(repr(v) for v in values), flush=True)
        rospy.sleep(0.02)
    return 0


if __name__ == "__main__":
    sys.exit(main())
