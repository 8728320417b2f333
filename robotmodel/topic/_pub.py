"""``ros2 topic pub``: publish a message given in YAML, once, N times or at a rate.

The YAML is ros2's form (``"{data: hello}"``, nested mappings for nested messages); fields it
does not name keep ROS's defaults, and a name the type does not have is an error naming it,
as ros2's ``set_message_fields`` raises. ``header: auto`` and a Time given as ``now`` are
stamped with the time of each publication, as ros2 topic pub stamps them.
"""

from __future__ import annotations

import functools
import sys
import time
from collections.abc import Callable, Sequence
from typing import TYPE_CHECKING, Any

from robotmodel.errors import BusError

if TYPE_CHECKING:
    from robotmodel.bus import QoS

__all__ = ["message_from_yaml", "run_topic_pub"]

Stamp = Callable[[Any], None]
_HEADER, _TIME = "std_msgs/msg/Header", "builtin_interfaces/msg/Time"
# rostopic pub -1 latches its message for this long before it exits.
_ROS1_LATCH_S = 3.0
# ros2 topic pub checks for matching subscriptions this often (and says so every tenth time).
_WAIT_STEP_S = 0.1


def _kind(desc: Any) -> str:
    return str(getattr(desc[0], "name", desc[0]))


def _fill(typename: str, values: Any, stamps: list[Stamp]) -> Any:
    from robotmodel.msgs._convert import typestore
    from robotmodel.msgs._dynamic import message_class

    msg = message_class(typename)()
    if values is None:
        return msg
    if not isinstance(values, dict):
        raise BusError(f"The YAML for {typename} must be a mapping of its fields, got {values!r}")
    fields = dict(typestore().fielddefs[typename][1])
    for name, value in values.items():
        if name not in fields:
            raise BusError(f"Failed to populate field: '{typename.rsplit('/', 1)[1]}' object has no attribute "
                           f"'{name}'")
        desc = fields[name]
        kind = _kind(desc)
        # rosidl_runtime_py's expand_header_auto / expand_time_now, as ros2 topic pub turns them on.
        if kind == "NAME" and (desc[1], value) in ((_HEADER, "auto"), (_TIME, "now")):
            target, attr = (getattr(msg, name), "stamp") if desc[1] == _HEADER else (msg, name)
            stamps.append(functools.partial(setattr, target, attr))
            continue
        setattr(msg, name, _value(desc, value, name, stamps))
    return msg


def _base(base: str, value: Any, where: str) -> Any:
    """``value`` for a field of ROS type ``base``, or the error rosidl's setters raise (naming the field)."""
    if base in ("string", "wstring"):
        want, ok = "str", isinstance(value, str)
    elif base == "bool":
        want, ok = "bool", isinstance(value, bool)
    elif base.startswith("float"):
        want, ok = "float", isinstance(value, int | float) and not isinstance(value, bool)
        value = float(value) if ok else value
    else:  # the integer types, byte and char
        want, ok = "int", isinstance(value, int) and not isinstance(value, bool)
    if not ok:
        raise BusError(f"Failed to populate field: The '{where}' field must be of type '{want}'")
    return value


def _value(desc: Any, value: Any, where: str, stamps: list[Stamp]) -> Any:
    kind, detail = _kind(desc), desc[1]
    if kind == "NAME":
        return _fill(detail, value, stamps)
    if kind == "BASE":
        return _base(detail[0], value, where)
    if not isinstance(value, list):
        raise BusError(f"Failed to populate field: The '{where}' field must be a sequence")
    return [_value(detail[0], v, where, stamps) for v in value]


def stamp_now() -> Any:
    """The system time now as a builtin_interfaces/Time (what rclpy's clock gives without sim time)."""
    from robotmodel.msgs._dynamic import message_class

    Time = message_class(_TIME)  # noqa: N806 -- the class the messages' own stamps have
    now = time.time_ns()
    return Time(sec=now // 1_000_000_000, nanosec=now % 1_000_000_000)


def message_from_yaml(typename: str, text: str, stamps: list[Stamp] | None = None) -> Any:
    """The message of ``pkg/msg/Name`` whose fields ``text`` (YAML, ros2 topic pub's form) sets.

    As ros2 topic pub, a Header given as ``auto`` and a Time given as ``now`` are stamped with
    the current time: each time it is published when ``stamps`` is given (a setter for each is
    appended to it, to be called with the stamp), else once, now.
    """
    import yaml

    from robotmodel.msgs._convert import typestore

    if typename.count("/") == 1:  # ros2 accepts pkg/Name
        typename = typename.replace("/", "/msg/")
    if typename not in typestore().fielddefs:
        raise BusError("The passed message type is invalid")
    try:
        values = yaml.safe_load(text) if text else None
    except yaml.YAMLError as exc:
        where = getattr(exc, "problem_mark", None)
        at = f" (line {where.line + 1}, column {where.column + 1})" if where is not None else ""
        raise BusError(f"The passed value needs to be a dictionary in YAML format: "
                       f"{getattr(exc, 'problem', None) or exc}{at}") from None
    setters: list[Stamp] = [] if stamps is None else stamps
    msg = _fill(typename, values, setters)
    if stamps is None and setters:
        stamp = stamp_now()
        for setter in setters:
            setter(stamp)
    return msg


def _repr(msg: Any) -> str:
    from dataclasses import fields

    if not hasattr(type(msg), "__msgtype__"):
        return repr(msg)
    pkg, _, name = msg.__msgtype__.split("/")
    inner = ", ".join(f"{f.name}={_repr(getattr(msg, f.name))}" for f in fields(msg))
    return f"{pkg}.msg.{name}({inner})"


def _wait_for_subscriptions(pub: Any, wait: int, max_wait_time: float | None, stop: Any) -> None:
    """ros2's wait: a line each second, a check each 0.1 s; BusError with its text past ``max_wait_time``."""
    waited, checks = 0.0, 0
    while not stop.is_set() and not pub.wait_for_subscriptions(wait, 0.0):
        if checks % 10 == 0:
            print(f"Waiting for at least {wait} matching subscription(s)...", flush=True)
        if max_wait_time is not None and max_wait_time <= waited:
            raise BusError(f"Timed out waiting for subscribers: Expected {wait} subcribers but only got "
                           f"{pub.get_subscription_count()} subscribers")
        checks += 1
        stop.wait(_WAIT_STEP_S)
        waited += _WAIT_STEP_S


def run_topic_pub(topic_name: str, message_type: str, values: str = "", *, rate: float = 1.0, once: bool = False,
                  times: int = 0, wait_matching_subscriptions: int | None = None, keep_alive: float = 0.1,
                  print_nth: int = 1, qos: QoS | None = None, max_wait_time_secs: float | None = None,
                  node_name: str | None = None, stdin: bool = False, connect: Sequence[str] = ()) -> int:
    """``ros2 topic pub``: publish until stopped, ``once`` or ``times`` messages, at ``rate`` Hz; the exit code.

    With ``once`` or ``times`` it first waits for one matching subscription (ros2's
    ``-w`` default then), and stays ``keep_alive`` s after the last message so it gets out.
    ``qos`` is the publisher's (:func:`robotmodel.topic.qos_from_short_keys` reads ros2's
    ``--qos-*``; default ros2's ``default`` profile, which on ROS 1 with ``once``/``times``
    latches, as ``rostopic pub -1``). ``stdin`` reads the YAML from standard input.
    """
    from robotmodel.bus import QOS_DEFAULT, QOS_LATCHED, Node
    from robotmodel.signals import stop_on_signals

    if stdin:
        values = sys.stdin.read()
    stamps: list[Stamp] = []
    msg = message_from_yaml(message_type, values, stamps)
    count = 1 if once else times
    wait = wait_matching_subscriptions if wait_matching_subscriptions is not None else (1 if count else 0)
    if rate <= 0:
        raise BusError(f"rate must be greater than zero, got {rate}")
    if wait == 0 and max_wait_time_secs is not None:
        raise BusError("--max-wait-time-secs option is only effective with --wait-matching-subscriptions, "
                       "--once or --times")
    qos = QOS_DEFAULT if qos is None else qos
    stop = stop_on_signals()
    with Node(node_name or "_robotmodel_topic_pub", connect=list(connect)) as node:
        if count and node.context.encoding == "ros1" and qos == QOS_DEFAULT:
            qos, keep_alive = QOS_LATCHED, max(keep_alive, _ROS1_LATCH_S)
        pub = node.create_publisher(type(msg), topic_name, qos)
        if wait:
            _wait_for_subscriptions(pub, wait, max_wait_time_secs, stop)
        print("publisher: beginning loop", flush=True)
        period_ns = int(1e9 / rate)
        deadline = time.monotonic_ns()
        sent = 0
        while not stop.is_set():
            if stamps:
                stamp = stamp_now()
                for setter in stamps:
                    setter(stamp)
            pub.publish(msg)
            sent += 1
            if print_nth and sent % print_nth == 0:
                print(f"publishing #{sent}: {_repr(msg)}\n", flush=True)
            if count and sent >= count:
                stop.wait(keep_alive)
                break
            # Absolute deadlines: a late wake-up shortens the next wait, so the mean rate holds.
            deadline += period_ns
            stop.wait(max(0.0, (deadline - time.monotonic_ns()) / 1e9))
    return 0
