"""Run examples/rospy_odom_to_tf.py unchanged on a ROS 2 wire and check the transform it broadcasts.

    wire_smoke.py WIRE        (zenoh, dds or inprocess)

The program runs in this process (in a thread, as ``__main__``), its rospy node opened first on
WIRE by the same ``init_node`` call it makes itself (rospy ignores the repeat): on zenoh the
wire comes from RMW_IMPLEMENTATION=rmw_zenoh_cpp, as for any program. A robotmodel bus node
feeds it odometry and a tf2_ros listener on another node reads ``odom`` → ``base_link``;
prints ``wire BACKEND_CLASS``, then ``tf x y qz qw`` when it arrives, then shuts rospy down and prints ``ended True``
once the program's ``rospy.spin()`` has returned.
"""

from __future__ import annotations

import math
import runpy
import sys
import threading
import time
from pathlib import Path

from robotmodel.msgs.nav_msgs.msg import Odometry

from robotmodel import rospy, tf2_ros
from robotmodel.bus import Node

PROGRAM = Path(__file__).resolve().parents[2] / "examples" / "rospy_odom_to_tf.py"


def main() -> int:
    wire = sys.argv[1]
    options = {} if wire == "zenoh" else {"backend": wire}
    rospy.init_node("odom_to_tf", **options)
    node = rospy.get_node()
    assert node is not None
    print("wire", type(node.context.backend).__name__, flush=True)
    feeder = Node("odom_feeder", **options)
    odom_pub = feeder.create_publisher(Odometry, "/odom", 10)
    reader = Node("tf_reader", **options)
    buffer = tf2_ros.Buffer()
    tf2_ros.TransformListener(buffer, reader)
    # The program starts once the peers are made: on DDS, topics made at the same time from two
    # threads once failed in cyclonedds (DDS_RETCODE_ERROR creating a Topic) on a loaded machine.
    program = threading.Thread(target=runpy.run_path, args=(str(PROGRAM),), kwargs={"run_name": "__main__"})
    program.start()
    odom = Odometry()
    odom.header.frame_id = "odom"
    odom.child_frame_id = "base_link"
    odom.pose.pose.position.x, odom.pose.pose.position.y = 1.5, -0.5
    odom.pose.pose.orientation.z, odom.pose.pose.orientation.w = math.sin(0.3), math.cos(0.3)
    deadline = time.monotonic() + 60
    while time.monotonic() < deadline:
        odom.header.stamp = rospy.Time.now()
        odom_pub.publish(odom)
        try:
            t = buffer.lookup_transform("odom", "base_link", rospy.Time(0), rospy.Duration(0.1))
        except tf2_ros.TransformException:
            continue
        p, q = t.transform.translation, t.transform.rotation
        print("tf", p.x, p.y, q.z, q.w, flush=True)
        break
    rospy.signal_shutdown("done")
    program.join(5)
    print("ended", not program.is_alive(), flush=True)
    feeder.close()
    reader.close()
    return 0


if __name__ == "__main__":
    sys.exit(main())
