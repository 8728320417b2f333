"""``ros2 topic echo`` as a program: a topic's messages as YAML (or CSV) until stopped.

Each message is printed as rosidl_runtime_py's ``message_to_yaml`` writes it, followed by
``---`` (``--csv``: one line of ``message_to_csv``). The type comes from the graph unless
given; the QoS follows the publishers' (reliable / transient local only when all of them
are) unless a ``--qos-*`` option names it. ``--filter EXPR`` prints only the messages (or
``--field`` values) for which the Python expression on ``m`` is true; ``-i`` prints the
message info (source and receive stamps, sequence numbers) before each, as rclpy's.
"""

from __future__ import annotations

import threading
import time
from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

from robotmodel.topic._convert import message_to_csv, message_to_yaml
from robotmodel.topic._hz import compile_filter
from robotmodel.topic._tools import DEFAULT_SPIN_TIME, _discover, _echo_qos

if TYPE_CHECKING:
    from robotmodel.bus import QoS
    from robotmodel.rcl import RosArgs

__all__ = ["DEFAULT_TRUNCATE_LENGTH", "EchoFormat", "run_topic_echo"]

DEFAULT_TRUNCATE_LENGTH = 128


class EchoFormat:
    """How echo prints: ``field`` (``a.b``), truncation, ``no_arr``/``no_str``, flow style, CSV, message info."""

    def __init__(self, *, field: str | None = None, full_length: bool = False,
                 truncate_length: int = DEFAULT_TRUNCATE_LENGTH, no_arr: bool = False, no_str: bool = False,
                 flow_style: bool = False, csv: bool = False, include_message_info: bool = False) -> None:
        from robotmodel.errors import BusError

        self.fields: list[str] | None = None
        if field is not None:
            self.fields = [f for f in field.split(".") if f]
            if not self.fields:
                raise BusError(f"Invalid field value '{field}'")
        self.limit = None if full_length else truncate_length
        self.no_arr, self.no_str, self.flow_style, self.csv = no_arr, no_str, flow_style, csv
        self.info = include_message_info

    def select(self, msg: Any) -> Any:
        """The ``--field`` value of a message; BusError in ros2's words when the message has no such field."""
        from robotmodel.errors import BusError

        sub = msg
        for name in self.fields or ():
            if not hasattr(sub, name):
                raise BusError(f"Invalid field '{'.'.join(self.fields or [])}': "
                               f"'{type(sub).__name__}' object has no attribute '{name}'")
            sub = getattr(sub, name)
        return sub

    def text(self, value: Any, info: dict[str, int] | None) -> str:
        """What echo prints for one message (or field value), its trailing newline included."""
        import yaml

        if self.csv:
            line = message_to_csv(value, self.limit, no_arr=self.no_arr, no_str=self.no_str)
            return (f"{','.join(str(v) for v in info.values())},{line}" if info is not None else line) + "\n"
        head = yaml.dump(info) + "---\n" if info is not None else ""
        return head + message_to_yaml(value, self.limit, self.flow_style, no_arr=self.no_arr,
                                      no_str=self.no_str) + "---\n"


def run_topic_echo(topic_name: str, message_type: str | None = None, *, form: EchoFormat | None = None,
                   raw: bool = False, once: bool = False, count: int | None = None, timeout: float | None = None,
                   filter_expr: str | None = None, qos: QoS | None = None, qos_profile: QoS | None = None,
                   connect: Sequence[str] = (), spin_time: float = DEFAULT_SPIN_TIME, namespace: str = "/",
                   ros: RosArgs | None = None) -> int:
    """``ros2 topic echo``: print each message until SIGINT/SIGTERM, ``once``, ``count`` or ``timeout``; the exit code.

    ``count``: rostopic's ``-n``, that many messages printed. ``qos``: the QoS the ``--qos-*``
    overrides name (else ``qos_profile``, the preset, adjusted to the publishers); a relative
    ``topic_name`` resolves under ``namespace``.
    """
    from robotmodel.bus import Node, codec_for
    from robotmodel.errors import BusError
    from robotmodel.rcl import RosArgs, warn_ignored_params
    from robotmodel.signals import stop_on_signals

    ros = ros or RosArgs()
    form = form or EchoFormat()
    check = compile_filter(filter_expr) if filter_expr else None
    stop = stop_on_signals()
    lock = threading.Lock()
    problems: list[str] = []
    received, printed = [0], [0]
    name = ros.node_name or "_robotmodel_topic_echo"
    warn_ignored_params(ros, namespace, name)
    with Node(name, namespace, connect=list(connect), remappings=ros.remaps) as node:
        topic = node.resolve_topic_name(topic_name)
        typename = message_type
        # Discovery first, type given or not: the QoS follows the publishers, and a new session's
        # graph does not show them yet, so an echo of a latched topic would subscribe volatile
        # and miss the one latched message.
        found = dict(_discover(node, spin_time))
        if typename is None:
            if topic not in found:
                print(f"WARNING: topic [{topic_name}] does not appear to be published yet", flush=True)
                raise BusError("Could not determine the type for the passed topic")
            if len(found[topic]) > 1:
                raise BusError(f"Cannot echo topic '{topic_name}', as it contains more than one type: "
                               f"[{', '.join(found[topic])}]")
            typename = found[topic][0]
        chosen = qos if qos is not None else _echo_qos(node, topic, qos_profile, say=True)

        def on_sample(sample: Any) -> None:
            if stop.is_set():
                return
            with lock:
                received[0] += 1  # the reader's count of samples, filtered out or not (rmw's reception number)
                reception = received[0]
            payload = sample.payload if codec is None else codec.decode(sample.payload)
            try:
                value = payload if raw else form.select(payload)
                if check is not None and not eval(check, {}, {"m": value}):  # the user's own Python, as ros2
                    return
            except Exception as exc:  # a missing field or the user's expression failing ends echo, named
                problems.append(str(exc) if isinstance(exc, BusError) else
                                f"--filter {filter_expr!r} failed on a message of {topic}: {type(exc).__name__}: {exc}")
                stop.set()
                return
            with lock:
                info = _info(sample, reception) if form.info else None
                if raw:
                    head = "---Got new message, message info:---\n" + str(info) + "\n---Message data:---\n" \
                        if info is not None else ""
                    print(f"{head}{value!r}" if head else value, end="\n---\n", flush=True)
                else:
                    print(form.text(value, info), end="", flush=True)
                printed[0] += 1
                if once or (count is not None and printed[0] >= count):
                    stop.set()

        try:
            codec = None if raw else codec_for(typename, node.context.encoding)
            node.create_subscription(typename, topic, on_sample, chosen, raw=True)
        except BusError as exc:
            if "unknown message type" in str(exc):
                raise BusError("The passed message type is invalid") from None
            raise
        stop.wait(timeout)
    if problems:
        raise BusError(problems[0])
    return 0


def _info(sample: Any, reception: int) -> dict[str, int]:
    """Rclpy's MessageInfo for a sample: its source and receive stamps and the two sequence numbers."""
    return {"source_timestamp": sample.info.source_timestamp_ns, "received_timestamp": time.time_ns(),
            "publication_sequence_number": sample.info.sequence_number, "reception_sequence_number": reception}
