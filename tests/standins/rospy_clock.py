"""A rospy program for tests/standins: simulated time from /clock, and its log lines on /rosout.

Run with ``/use_sim_time`` true. It drives /clock itself (from 100 s, 0.1 s per 20 ms), then
waits in simulated time: sleep, Rate, a one-shot Timer, a sleep that /clock breaks by going
back (1 s of wall time after the sleep began); then logs a tick per simulated 0.1 s until shutdown, which ends the Rate's sleep with
ROSInterruptException. Only the import lines differ between its real-rospy and robotmodel runs.
"""

import threading
import time

from robotmodel.msgs.rosgraph_msgs.msg import Clock

from robotmodel import rospy

rospy.init_node("clocked")
print("before any /clock", rospy.get_rostime().to_nsec(), rospy.get_time())
clock = rospy.Publisher("/clock", Clock, queue_size=10)
back = threading.Event()


def drive():
    t = rospy.Time(100)
    after = 0
    while not rospy.is_shutdown():
        if back.is_set():
            after += 1
            if after == 50:
                t = rospy.Time(50)
        clock.publish(t)
        t = t + rospy.Duration(0, 100000000)
        time.sleep(0.02)


threading.Thread(target=drive, daemon=True).start()
rospy.sleep(0)
t0 = rospy.Time.now()
print("started", t0.secs >= 100)
rospy.loginfo("sim time %s", t0.secs >= 100)
rospy.sleep(0.5)
print("slept", (rospy.Time.now() - t0).to_sec() >= 0.5)
rate = rospy.Rate(5)
for _ in range(3):
    rate.sleep()
print("rate", (rospy.Time.now() - t0).to_sec() >= 0.5 + 0.4)
ticks = []
rospy.Timer(rospy.Duration(0.3), ticks.append, oneshot=True).join(30)
print("timer", len(ticks), ticks[0].current_real - ticks[0].current_expected >= rospy.Duration(0))
back.set()
try:
    rospy.sleep(10.0)
    print("not interrupted")
except rospy.ROSTimeMovedBackwardsException as exc:
    print("moved back", exc.time > 0, isinstance(exc, rospy.ROSInterruptException))
rate = rospy.Rate(10)
n = 0
try:
    while not rospy.is_shutdown():
        n += 1
        rospy.loginfo("tick %d", n)
        rospy.logwarn_once("once")
        rate.sleep()
except rospy.ROSInterruptException:
    print("interrupted")
