"""A rospy program for tests/standins: parameters, names, wait_for_message, Timer, logging, shutdown.

Only the import lines differ between the two runs (see test_rospy_ros1.py).
"""

from robotmodel.msgs.std_msgs.msg import String

from robotmodel import rospy

rospy.init_node("basics")
print("name", rospy.get_name())
print("private", repr(rospy.get_param("~rate")))
print("global", repr(rospy.get_param("/shared", "unset")), repr(rospy.get_param("/absent", "unset")))
rospy.set_param("~written", [1, 2.5, "x"])
print("has", rospy.has_param("~written"), rospy.has_param("~nope"))
print("written", repr(rospy.get_param("~written")))
print("search", rospy.search_param("shared"))
rospy.delete_param("~written")
print("deleted", rospy.has_param("~written"))
try:
    rospy.get_param("~nope")
except KeyError as exc:
    print("KeyError", exc)
print("time", type(rospy.Time.now().secs).__name__, rospy.Time(3, 5).to_nsec(), rospy.Duration(1.5).to_nsec())
try:
    rospy.wait_for_message("silent", String, timeout=0.2)
except rospy.ROSException as exc:
    print("ROSException", exc)
ticks = []
timer = rospy.Timer(rospy.Duration(0.05), ticks.append, oneshot=True)
timer.join(5)
print("timer", len(ticks), ticks[0].last_expected, type(ticks[0].current_real).__name__)
rospy.loginfo("info %d", 1)
rospy.logwarn("warn")
rospy.logerr("err")
rospy.logdebug("debug")
rospy.on_shutdown(lambda: print("hook"))
rospy.signal_shutdown("done")
print("is_shutdown", rospy.is_shutdown())
