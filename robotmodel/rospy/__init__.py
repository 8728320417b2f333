"""rospy on robotmodel's bus: ``from robotmodel import rospy`` in place of ``import rospy``.

On the ROS 1 wire (``ROS_VERSION=1`` and ``ROS_MASTER_URI`` set, as in a sourced ROS 1
shell) the node is a real ROS 1 node: registered with the master, TCPROS to rospy and
roscpp peers, parameters on the parameter server. On the zenoh, DDS and in-process wires
the same calls work between robotmodel processes and ROS 2 peers (parameters node-local).

What is here: :func:`init_node` (``anonymous=``, ``argv=`` with ``__name:=``, ``__ns:=``,
``_param:=value`` and ``from:=to``), :class:`Publisher` (``latch``, ``queue_size``,
``publish(*args, **kwargs)``), :class:`Subscriber` (``callback_args``), :class:`Rate`,
:class:`Time`/:class:`Duration`/:func:`get_rostime`/:func:`get_time`, :func:`sleep`,
:func:`spin`, :func:`is_shutdown`, :func:`on_shutdown`, :func:`signal_shutdown`,
``loginfo``/``logwarn``/``logerr``/``logfatal``/``logdebug`` with ``_throttle`` and ``_once``
(rospy's line format and streams), :class:`Timer`, :func:`wait_for_message`,
``get_param``/``set_param``/``has_param``/``search_param``/``delete_param``,
:class:`ROSException`, :class:`ROSInterruptException`, :class:`ROSInitException`,
:class:`ROSTimeMovedBackwardsException`.

Time follows ``/clock`` when ``/use_sim_time`` is true at init_node (on wires without a
parameter server: ``_use_sim_time:=true``). Log lines go to the console in rospy's format
(``ROSCONSOLE_FORMAT`` followed) and to ``/rosout``: ``rosgraph_msgs/Log`` on ROS 1,
``rcl_interfaces/msg/Log`` elsewhere.

Porting notes (what differs from rospy):

- Publishers and Subscribers need :func:`init_node` first (rospy lets them be made before).
- On the wall clock ``sleep`` returns early at shutdown (rospy's sleeps on) and raises
  nothing, as rospy's; services are not here yet.
- Messages come from :mod:`robotmodel.msgs` (``from robotmodel.msgs.geometry_msgs import
  TransformStamped``); their stamps are ROS 2's ``sec``/``nanosec``, and rospy's Time and
  Duration carry those names too, so ``t.header.stamp = rospy.Time.now()`` works.
"""

from __future__ import annotations

from robotmodel.errors import (
    ROSException,
    ROSInitException,
    ROSInterruptException,
    ROSTimeMovedBackwardsException,
)
from robotmodel.rospy._core import (
    Rate,
    get_name,
    get_namespace,
    get_node,
    init_node,
    is_shutdown,
    myargv,
    on_shutdown,
    resolve_name,
    signal_shutdown,
    sleep,
    spin,
)
from robotmodel.rospy._log import (
    DEBUG,
    ERROR,
    FATAL,
    INFO,
    WARN,
    logdebug,
    logdebug_once,
    logdebug_throttle,
    logerr,
    logerr_once,
    logerr_throttle,
    logfatal,
    logfatal_once,
    logfatal_throttle,
    loginfo,
    loginfo_once,
    loginfo_throttle,
    logwarn,
    logwarn_once,
    logwarn_throttle,
)
from robotmodel.rospy._params import (
    delete_param,
    get_param,
    get_param_names,
    has_param,
    search_param,
    set_param,
)
from robotmodel.rospy._time import Duration, Time, get_rostime, get_time
from robotmodel.rospy._topics import Publisher, Subscriber
from robotmodel.rospy._wait import Timer, TimerEvent, wait_for_message

get_caller_id = get_name

__all__ = [
    "DEBUG",
    "ERROR",
    "FATAL",
    "INFO",
    "WARN",
    "Duration",
    "Publisher",
    "ROSException",
    "ROSInitException",
    "ROSInterruptException",
    "ROSTimeMovedBackwardsException",
    "Rate",
    "Subscriber",
    "Time",
    "Timer",
    "TimerEvent",
    "delete_param",
    "get_caller_id",
    "get_name",
    "get_namespace",
    "get_node",
    "get_param",
    "get_param_names",
    "get_rostime",
    "get_time",
    "has_param",
    "init_node",
    "is_shutdown",
    "logdebug",
    "logdebug_once",
    "logdebug_throttle",
    "logerr",
    "logerr_once",
    "logerr_throttle",
    "logfatal",
    "logfatal_once",
    "logfatal_throttle",
    "loginfo",
    "loginfo_once",
    "loginfo_throttle",
    "logwarn",
    "logwarn_once",
    "logwarn_throttle",
    "myargv",
    "on_shutdown",
    "resolve_name",
    "search_param",
    "set_param",
    "signal_shutdown",
    "sleep",
    "spin",
    "wait_for_message",
]
