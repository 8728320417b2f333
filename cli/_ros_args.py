"""A node's namespace and name on the command line, the ROS 2 way, for every node-running command.

- ``--ros-args ... [--]`` blocks, read as rcl reads them: ``-r``/``--remap`` rules
  ``__ns:=/ns`` (fully qualified, as rcl requires) and ``__node:=name`` (or ``__name:=``),
  each optionally limited to one node by a ``node:`` prefix; the first matching rule wins,
  as in rcl. Other ROS arguments (topic remaps, parameters, log levels) are accepted and
  have no effect here, so command lines written for ROS run unchanged.
- ``--namespace NS``: the namespace a node is created with in code (rclpy's
  ``Node(namespace=...)``): ``r1`` means ``/r1``. An ``__ns`` remap overrides it, as in ROS.

Relative topic names then land under the namespace (``joint_states`` → ``/r1/joint_states``);
absolute ones such as ``/tf`` do not.
"""

from __future__ import annotations

import argparse
import re
from collections.abc import Sequence
from dataclasses import dataclass

__all__ = [
    "RosArgs",
    "RosArgsError",
    "add_node_arguments",
    "logger_name",
    "node_namespace",
    "settle",
    "split_node_words",
    "take_ros_args",
]

_TOKEN = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")
# rcl flags whose value is the next word (so that value is never read as a flag).
_VALUE_FLAGS = frozenset({"-p", "--param", "--params-file", "-e", "--enclave", "--log-level",
                          "--log-config-file", "--log-file-name"})
_REMAP_FLAGS = ("-r", "--remap")


class RosArgsError(ValueError):
    """A ROS argument or namespace that rcl (or rclpy) would refuse; the text is one line."""


@dataclass(frozen=True)
class RosArgs:
    """What the ``--ros-args`` blocks set for this process's node (None: not set)."""

    namespace: str | None = None
    node_name: str | None = None


def _check_namespace(namespace: str) -> str:
    from robotmodel.bus._names import validate_namespace
    from robotmodel.errors import BusError

    try:
        return validate_namespace(namespace)
    except BusError as exc:
        raise RosArgsError(str(exc)) from None


def _rule(flag: str, rule: str, node_name: str | None, found: dict[str, str]) -> None:
    where = f"Couldn't parse remap rule: '{flag} {rule}'. Error:"
    lhs, sep, rhs = rule.partition(":=")
    if not sep:
        raise RosArgsError(f"{where} expected ':=' in the rule")
    prefix, colon, name = lhs.rpartition(":")
    if colon and not _TOKEN.fullmatch(prefix):
        raise RosArgsError(f"{where} invalid node name prefix '{prefix}'")
    if colon and node_name is not None and prefix != node_name:
        return  # a rule for another node
    if name == "__ns":
        if not rhs.startswith("/"):
            raise RosArgsError(f"{where} Namespace not remapped to a fully qualified name (found: {rhs})")
        try:
            value = _check_namespace(rhs)
        except RosArgsError:
            raise RosArgsError(f"{where} Namespace not remapped to a fully qualified name (found: {rhs})") from None
        found.setdefault("namespace", value)
    elif name in ("__node", "__name"):
        if not _TOKEN.fullmatch(rhs):
            raise RosArgsError(f"{where} Node name not remapped to invalid name: '{rhs}'")
        found.setdefault("node_name", rhs)


def take_ros_args(words: Sequence[str], node_name: str | None = None) -> tuple[RosArgs, list[str]]:
    """Take the ``--ros-args`` blocks out of ``words``: (what they set, the other words).

    Each block runs to a ``--`` (dropped too) or to the end. ``node_name`` is the node's
    default name, against which ``node:``-prefixed rules are matched (None: all apply).
    """
    rest: list[str] = []
    found: dict[str, str] = {}
    inside = False
    i = 0
    while i < len(words):
        word = words[i]
        if not inside:
            if word == "--ros-args":
                inside = True
            else:
                rest.append(word)
        elif word == "--":
            inside = False
        elif word in _REMAP_FLAGS:
            if i + 1 >= len(words):
                raise RosArgsError(f"Couldn't parse trailing {word} flag. No remap rule found.")
            _rule(word, words[i + 1], node_name, found)
            i += 1
        elif word in _VALUE_FLAGS:
            i += 1
        i += 1
    return RosArgs(found.get("namespace"), found.get("node_name")), rest


def node_namespace(option: str | None, ros: RosArgs) -> str:
    """The namespace a node gets: an ``__ns`` remap, else ``--namespace`` made absolute, else ``/``."""
    if ros.namespace is not None:
        return ros.namespace
    if option is None:
        return "/"
    return _check_namespace(option)


def split_node_words(words: Sequence[str], node_name: str | None = None) -> tuple[list[str], str, str | None]:
    """For commands parsing their own words: (other words, namespace, node name override or None).

    Takes the ``--ros-args`` blocks and ``--namespace NS`` / ``--namespace=NS`` out.
    """
    ros, words = take_ros_args(words, node_name)
    rest: list[str] = []
    option: str | None = None
    i = 0
    while i < len(words):
        word = words[i]
        if word.startswith("--namespace="):
            option = word.split("=", 1)[1]
        elif word == "--namespace":
            if i + 1 >= len(words):
                raise RosArgsError("argument --namespace: expected one argument")
            option = words[i + 1]
            i += 1
        else:
            rest.append(word)
        i += 1
    return rest, node_namespace(option, ros), ros.node_name


def add_node_arguments(parser: argparse.ArgumentParser, node_name: str) -> None:
    """Give a :class:`robotmodel.cli._common.CommandParser` ``--namespace`` and ``--ros-args`` blocks.

    ``node_name`` is the node's default name (``node:``-prefixed rules for others are ignored).
    After parsing, ``args.namespace`` is the node's absolute namespace and ``args.node_name``
    the ``__node`` override (or None); see :func:`settle`.
    """
    parser.takes_ros_args = True  # type: ignore[attr-defined]
    parser.ros_node_name = node_name  # type: ignore[attr-defined]
    parser.add_argument("--namespace", metavar="NS", default=None,
                        help="the node's namespace ('r1' means /r1): relative topics such as joint_states "
                        "and robot_description move under it, /tf and /tf_static do not. ROS 2's "
                        "'--ros-args -r __ns:=/r1' (and -r __node:=NAME) also work, and win")
    parser.epilog = ((parser.epilog or "") + " ROS 2 arguments (--ros-args ... [--]) may follow.").strip()


def settle(parsed: argparse.Namespace, ros: RosArgs) -> None:
    """Replace ``parsed.namespace`` by the node's absolute namespace and set ``parsed.node_name``."""
    parsed.namespace = node_namespace(getattr(parsed, "namespace", None), ros)
    parsed.node_name = ros.node_name


def logger_name(namespace: str, node_name: str) -> str:
    """The node's logger name as rcl forms it: namespace tokens and name joined by '.' (``r1.rsp``)."""
    return ".".join([*namespace.strip("/").split("/"), node_name]) if namespace != "/" else node_name
