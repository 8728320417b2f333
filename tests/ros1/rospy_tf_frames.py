"""A real rospy /tf and /tf_static reader for tests/ros1, run with Debian's /usr/bin/python3.

    rospy_tf_frames.py [--all]

Prints ``ready`` once subscribed, then for each transform the first time its (topic,
publisher, parent, child) is seen: ``TOPIC CALLERID PARENT CHILD SECS.NSECS`` (frame ids
exactly as on the wire, the stamp as rospy decodes it). ``--all``: every transform of every
message, with the wall time it arrived as a sixth field. Then it spins until killed.
"""

from __future__ import annotations

import sys
import threading
import time

import rospy
from tf2_msgs.msg import TFMessage

_seen: set[tuple[str, str, str, str]] = set()
_lock = threading.Lock()


def _printer(topic: str, every: bool):  # type: ignore[no-untyped-def]
    def on_message(msg: TFMessage) -> None:
        arrived = time.time()
        callerid = msg._connection_header["callerid"]
        for t in msg.transforms:
            key = (topic, callerid, t.header.frame_id, t.child_frame_id)
            with _lock:
                if key in _seen and not every:
                    continue
                _seen.add(key)
                extra = f" {arrived:.6f}" if every else ""
                sys.stdout.write(" ".join(key) + f" {t.header.stamp.secs}.{t.header.stamp.nsecs:09d}{extra}\n")
                sys.stdout.flush()

    return on_message


def main() -> int:
    rospy.init_node("rospy_tf_frames", anonymous=True)
    for topic in ("/tf", "/tf_static"):
        rospy.Subscriber(topic, TFMessage, _printer(topic, "--all" in sys.argv[1:]))
    print("ready", flush=True)
    rospy.spin()
    return 0


if __name__ == "__main__":
    sys.exit(main())
