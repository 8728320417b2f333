"""A real rospy peer for tests/ros1, run with Debian's /usr/bin/python3 (not the project's venv).

    rospy_peer.py pub TOPIC TYPE [--latch] [--count N] [--text PREFIX]   publish N messages (0: forever, 10 Hz)
    rospy_peer.py sub TOPIC TYPE [--md5 HEX]                              print each message on one line

TYPE is std_msgs/String or tf2_msgs/TFMessage. Output lines: ``ready``, ``got <payload>``,
``published <n>``, and ``rospy: <text>`` for each rospy.internal warning or error (where rospy
reports a refused connection).
"""

from __future__ import annotations

import argparse
import logging
import sys

import rospy
from geometry_msgs.msg import TransformStamped
from std_msgs.msg import String
from tf2_msgs.msg import TFMessage

TYPES = {"std_msgs/String": String, "tf2_msgs/TFMessage": TFMessage}


class _Echo(logging.Handler):
    def emit(self, record: logging.LogRecord) -> None:
        print("rospy:", record.getMessage().replace("\n", " | "), flush=True)


def _payload(msg: object) -> str:
    if isinstance(msg, String):
        return msg.data
    assert isinstance(msg, TFMessage)
    return ";".join(f"{t.header.frame_id}->{t.child_frame_id}@{t.header.stamp.secs}.{t.header.stamp.nsecs:09d}"
                    f":{t.transform.translation.x:.3f}" for t in msg.transforms)


def _message(cls: type, text: str, i: int) -> object:
    if issubclass(cls, String):
        return cls(data=f"{text} {i}")
    t = TransformStamped()
    t.header.frame_id = "world"
    t.header.stamp = rospy.Time(1700000000, i)
    t.child_frame_id = f"{text}{i}"
    t.transform.translation.x = float(i)
    t.transform.rotation.w = 1.0
    return cls(transforms=[t])


def main() -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument("mode", choices=["pub", "sub"])
    parser.add_argument("topic")
    parser.add_argument("type", choices=sorted(TYPES))
    parser.add_argument("--latch", action="store_true")
    parser.add_argument("--count", type=int, default=0)
    parser.add_argument("--text", default="hello")
    parser.add_argument("--md5", default=None)
    parser.add_argument("--name", default=None)
    args = parser.parse_args(rospy.myargv()[1:])
    cls = TYPES[args.type]
    if args.md5:
        cls = type(cls.__name__, (cls,), {"_md5sum": args.md5})
    rospy.init_node(args.name or f"rospy_{args.mode}", anonymous=args.name is None, disable_signals=False)
    handler = _Echo(logging.WARNING)
    logging.getLogger("rospy.internal").addHandler(handler)
    logging.getLogger("rospy.impl").addHandler(handler)
    if args.mode == "sub":
        rospy.Subscriber(args.topic, cls, lambda m: print("got", _payload(m), flush=True))
        print("ready", flush=True)
        rospy.spin()
        return 0
    pub = rospy.Publisher(args.topic, cls, queue_size=10, latch=args.latch)
    print("ready", flush=True)
    rate = rospy.Rate(10)
    i = 0
    while not rospy.is_shutdown() and (args.count == 0 or i < args.count):
        pub.publish(_message(cls, args.text, i))
        i += 1
        print("published", i, flush=True)
        rate.sleep()
    rospy.spin()
    return 0


if __name__ == "__main__":
    sys.exit(main())
