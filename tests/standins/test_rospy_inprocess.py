"""robotmodel.rospy off ROS 1 (the in-process wire), each case in a fresh process (rospy has one node per process)."""

from __future__ import annotations

import importlib
import os
import re
import subprocess
import sys
import textwrap

import pytest

from robotmodel import rospy


def run(code: str, *argv: str, env: dict[str, str] | None = None) -> subprocess.CompletedProcess[str]:
    full = dict(os.environ)
    for var in ("ROS_VERSION", "ROS_MASTER_URI", "ROS_NAMESPACE"):
        full.pop(var, None)
    full.update(env or {})
    done = subprocess.run([sys.executable, "-c", textwrap.dedent(code), *argv], capture_output=True, text=True,
                          timeout=60, check=False, env=full)
    assert done.returncode == 0, done.stdout + done.stderr
    return done


def test_argv_words_params_and_topics() -> None:
    done = run("""
        from robotmodel import rospy
        from robotmodel.msgs.geometry_msgs import Vector3
        rospy.init_node("talker", anonymous=True, backend="inprocess", domain_id=3)
        print(rospy.get_name().startswith("/ns/talker_"), rospy.get_namespace())
        print(repr(rospy.get_param("~gain")), repr(rospy.get_param("~label")), rospy.myargv()[1:])
        rospy.set_param("/ns/shared", 1)
        print(rospy.search_param("shared"), rospy.search_param("absent"))
        got = []
        rospy.Subscriber("renamed", Vector3, lambda m, tag: got.append((tag, m.x, m.y, m.z)), callback_args="t")
        pub = rospy.Publisher("vec", Vector3, queue_size=5)
        pub.publish(1.0, 2.0, 3.0)
        pub.publish(x=4.0)
        pub.publish(Vector3(5.0, 0.0, 0.0))
        rospy.sleep(0.2)
        print(got)
        rospy.init_node("talker", anonymous=True, backend="zenoh")  # the same call: a no-op, as rospy's
        try:
            rospy.init_node("again")
        except rospy.ROSException as exc:
            print("twice refused", type(exc).__name__, "different arguments" in str(exc))
        """, "plain", "_gain:=0.5", "_label:=hi", "vec:=renamed", env={"ROS_NAMESPACE": "/ns"})
    assert done.stdout.splitlines() == [
        "True /ns/",
        "0.5 'hi' ['plain']",
        "/ns/shared None",
        "[('t', 1.0, 2.0, 3.0), ('t', 4.0, 0.0, 0.0), ('t', 5.0, 0.0, 0.0)]",
        "twice refused ROSException True",
    ]


def test_log_levels_and_streams() -> None:
    done = run("""
        from robotmodel import rospy
        rospy.init_node("n", log_level=rospy.DEBUG, backend="inprocess", domain_id=4)
        rospy.logdebug("d %s", "x"); rospy.loginfo("i"); rospy.logwarn("w"); rospy.logerr("e"); rospy.logfatal("f")
        """)
    assert [line.split("]: ")[1] for line in done.stdout.splitlines()] == ["d x", "i"]
    assert [line.split("] [")[0] for line in done.stderr.splitlines()] == ["[WARN", "[ERROR", "[FATAL"]


def test_sigterm_ends_spin_and_runs_hooks() -> None:
    code = """
        import os, signal, threading
        from robotmodel import rospy
        rospy.init_node("n", backend="inprocess", domain_id=5)
        rospy.on_shutdown(lambda reason: print("hook", reason))
        threading.Timer(0.3, os.kill, (os.getpid(), signal.SIGTERM)).start()
        rospy.spin()
        print("spun", rospy.is_shutdown())
        """
    assert run(code).stdout.splitlines() == [f"hook signal-{15}", "spun True"]


def test_time_and_duration_arithmetic() -> None:
    t = rospy.Time(10, 250_000_000)
    d = rospy.Duration.from_sec(1.5)
    assert (t + d).to_nsec() == 11_750_000_000
    assert (t - rospy.Time(9)).to_sec() == pytest.approx(1.25)
    assert (t - d).secs == 8 and (t - d).nsecs == 750_000_000
    assert (-d).to_nsec() == -1_500_000_000 and (d * 2).to_sec() == 3.0
    assert rospy.Time(0).is_zero() and rospy.Time(1) > rospy.Time(0, 999_999_999)
    assert (t.sec, t.nanosec, t.nanoseconds) == (10, 250_000_000, 10_250_000_000)
    with pytest.raises(TypeError):
        rospy.Time(-1)


def test_rate_keeps_its_period() -> None:
    rate = rospy.Rate(20)
    start = rospy.get_time()
    for _ in range(6):
        rate.sleep()
    assert 0.25 <= rospy.get_time() - start < 1.0


@pytest.mark.parametrize("package", ["builtin_interfaces", "geometry_msgs", "nav_msgs", "rosgraph_msgs",
                                     "sensor_msgs", "std_msgs", "tf2_msgs"])
def test_messages_import_from_a_msg_submodule(package: str) -> None:
    module = importlib.import_module(f"robotmodel.msgs.{package}")
    assert importlib.import_module(f"robotmodel.msgs.{package}.msg") is module
    assert module.msg is module


def test_throttle_once_timer_and_wait_for_message() -> None:
    done = run("""
        import time
        from robotmodel import rospy
        from robotmodel.msgs.std_msgs.msg import String
        rospy.init_node("n", backend="inprocess", domain_id=6)
        def both(i):
            rospy.loginfo_once("once %d", i)
            rospy.loginfo_throttle(0.2, "throttled %d", i)
        both(0)
        both(1)  # at once: neither
        time.sleep(0.3)
        both(3)  # a period later: throttled only
        ticks = []
        timer = rospy.Timer(rospy.Duration(0.05), ticks.append)
        time.sleep(0.4)
        timer.shutdown()
        first, second = ticks[0], ticks[1]
        print(first.last_expected is None, second.last_expected == first.current_expected,
              (second.current_expected - first.current_expected).to_nsec(), 4 <= len(ticks) <= 9)
        pub = rospy.Publisher("chatter", String, queue_size=1)
        rospy.Timer(rospy.Duration(0.2), lambda event: pub.publish("late"), oneshot=True)
        print(rospy.wait_for_message("chatter", String, timeout=5).data)
        try:
            rospy.wait_for_message("silent", String, timeout=0.2)
        except rospy.ROSException as exc:
            print(exc)
        """)
    assert [line.split("]: ", 1)[-1] for line in done.stdout.splitlines()] == [
        "once 0", "throttled 0", "throttled 3",
        "True True 50000000 True",
        "late",
        "timeout exceeded while waiting for message on topic silent",
    ]


def test_rospy_style_tf2_ros_classes_use_the_rospy_node() -> None:
    done = run("""
        from robotmodel import rospy, tf2_ros
        # Before init_node: a node of its own, as robotmodel.tf_ros.
        before = tf2_ros.TransformBroadcaster(backend="inprocess", domain_id=8)
        rospy.init_node("n", backend="inprocess", domain_id=8)
        node = rospy.get_node()
        listener = tf2_ros.TransformListener(tf2_ros.Buffer())
        print(listener.node is node, tf2_ros.TransformBroadcaster().node is node,
              tf2_ros.StaticTransformBroadcaster().node is node, before.node is not node)
        before.close()
        """)
    assert done.stdout.split() == ["True"] * 4


def test_sim_time_from_a_private_parameter_and_rosout_as_ros2_log() -> None:
    """Off ROS 1 (no parameter server): ``_use_sim_time:=true`` follows /clock; log lines are rcl_interfaces/msg/Log."""
    done = run("""
        import threading, time
        from robotmodel import rospy
        from robotmodel.bus import Node
        from robotmodel.msgs.rosgraph_msgs import Clock
        rospy.init_node("simmed", backend="inprocess", domain_id=9)
        print("before", rospy.get_rostime().to_nsec())
        peer = Node("peer", backend="inprocess", domain_id=9)
        logs = []
        peer.create_subscription("rcl_interfaces/msg/Log", "/rosout", logs.append, 10)
        clock = peer.create_publisher(Clock, "/clock", 1)
        def drive(stop=threading.Event()):
            t = 42_000_000_000
            while not rospy.is_shutdown():
                msg = Clock()
                msg.clock.sec, msg.clock.nanosec = divmod(t, 1_000_000_000)
                clock.publish(msg)
                t += 100_000_000
                stop.wait(0.01)
        threading.Thread(target=drive, daemon=True).start()
        rospy.sleep(0)
        start = rospy.Time.now()
        rospy.sleep(1.0)  # ten /clock ticks: about 0.1 s of wall time
        print("after", start.secs >= 42, (rospy.Time.now() - start).to_sec() >= 1.0)
        rospy.logwarn("careful %d", 3)
        deadline = time.monotonic() + 10
        while not logs and time.monotonic() < deadline:
            time.sleep(0.01)
        log = logs[0]
        print(log.level, log.name, log.msg, log.function, log.stamp.sec >= 42)
        rospy.signal_shutdown("done")
        """, "_use_sim_time:=true")
    lines = done.stdout.splitlines()
    assert lines[:3] == ["before 0", "after True True", "30 simmed careful 3 <module> True"]
    assert re.match(r"^\[WARN\] \[\d+\.\d{6}, 4\d\.\d{6}\]: careful 3$", done.stderr.splitlines()[0])
