"""ROS 2 arguments for every node: ``--ros-args ... [--]`` blocks, read as rcl reads them.

- ``-r``/``--remap`` rules, rcl's syntax and semantics (see :mod:`robotmodel.bus._remap`):
  ``__ns:=/ns`` (fully qualified) and ``__node:=name`` (or ``__name:=``) move and rename the
  node; ``from:=to`` remaps a topic, matched on its fully expanded name (relative names under
  the node's namespace, ``~/x`` under the node), the replacement expanded the same way, e.g.
  ``-r joint_states:=/arm/joint_states`` or ``-r /tf:=/r1/tf``. A ``node:`` prefix limits a
  rule to that node; the first matching rule wins. Topic rules go to the command's
  :class:`robotmodel.bus.Node` (``remappings=``), so /tf, /tf_static, joint_states and
  robot_description all follow them. A malformed rule stops the command with rcl's text.
- ``-p``/``--param [node:]name:=value`` and ``--params-file FILE``: parameter overrides, typed
  and merged as rcl and rclcpp do (:mod:`robotmodel.rcl._params`: within one node pattern
  the value given last wins). robot-state-publisher and joint-state-publisher map them onto
  their settings (the parameter wins over the same setting's ``--flag``, as ``__ns`` wins
  over ``--namespace``); other commands say which overrides they ignore.
- ``--log-level [logger:=]LEVEL`` sets the console's levels (a node command's own lines and
  a stand-in rclpy node's loggers), as rcl does: the default level, or one logger's.
- ``--enclave``, ``--log-config-file``, ``--log-file-name`` and rcl's
  ``--enable-*``/``--disable-*`` flags are accepted and have no effect here. Any other word
  inside a block is refused, as rclcpp refuses unknown ROS arguments.
- ``--namespace NS``: the namespace a node is created with in code (rclpy's
  ``Node(namespace=...)``): ``r1`` means ``/r1``. An ``__ns`` remap overrides it, as in ROS.

Relative topic names then land under the namespace (``joint_states`` → ``/r1/joint_states``);
absolute ones such as ``/tf`` do not, unless a remap rule says so.
"""

from __future__ import annotations

from collections.abc import Collection, Mapping, Sequence
from dataclasses import dataclass, replace
from typing import Any

from robotmodel.errors import RosArgsError

__all__ = [
    "RosArgs",
    "apply_log_levels",
    "logger_name",
    "node_namespace",
    "node_params",
    "remove_ros_args",
    "split_node_words",
    "split_ros_words",
    "take_node_args",
    "take_ros_args",
    "warn_ignored_params",
]

# rcl flags whose value is the next word (so that value is never read as a flag).
_VALUE_FLAGS = frozenset({"-p", "--param", "--params-file", "-e", "--enclave", "--log-level",
                          "--log-config-file", "--log-file-name"})
_REMAP_FLAGS = ("-r", "--remap")
_PARAM_FLAGS = ("-p", "--param")
_SWITCHES = frozenset(f"--{on}-{what}-logs" for on in ("enable", "disable") for what in ("rosout", "stdout",
                                                                                          "external-lib"))
_SEVERITIES = frozenset({"UNSET", "DEBUG", "INFO", "WARN", "WARNING", "ERROR", "FATAL"})


@dataclass(frozen=True)
class RosArgs:
    """What the ``--ros-args`` blocks set for this process's node (None: not set)."""

    namespace: str | None = None
    node_name: str | None = None
    #: Topic remap rules (``[node:]from:=to``), in command-line order, for ``Node(remappings=...)``.
    remaps: tuple[str, ...] = ()
    #: Parameter overrides (node pattern, name, value), in command-line order; see ``_ros_params``.
    params: tuple[tuple[str, str, Any], ...] = ()
    #: ``--log-level [logger:=]LEVEL`` in command-line order ("" names the default level).
    log_levels: tuple[tuple[str, str], ...] = ()


def _check_namespace(namespace: str) -> str:
    from robotmodel.bus._names import validate_namespace
    from robotmodel.errors import BusError

    try:
        return validate_namespace(namespace)
    except BusError as exc:
        raise RosArgsError(str(exc)) from None


def _rule(flag: str, text: str, node_name: str | None, found: dict[str, str], remaps: list[str]) -> None:
    from robotmodel.bus._remap import RemapKind, RemapRule, rule_problem

    where = f"Couldn't parse remap rule: '{flag} {text}'. Error:"
    problem = rule_problem(text)
    if problem:
        raise RosArgsError(f"{where} {problem}")
    rule = RemapRule.parse(text)
    if rule.kind not in (RemapKind.NAMESPACE, RemapKind.NODE_NAME):
        remaps.append(text)  # matched later against the node's final name, as rcl does
        return
    if rule.node is not None and node_name is not None and rule.node != node_name:
        return  # a rule for another node
    if rule.kind is RemapKind.NAMESPACE:
        try:
            value = _check_namespace(rule.replacement)
        except RosArgsError:
            raise RosArgsError(f"{where} Namespace not remapped to a fully qualified name "
                               f"(found: {rule.replacement})") from None
        found.setdefault("namespace", value)
    else:
        found.setdefault("node_name", rule.replacement)


def take_ros_args(words: Sequence[str], node_name: str | None = None) -> tuple[RosArgs, list[str]]:
    """Take the ``--ros-args`` blocks out of ``words``: (what they set, the other words).

    Each block runs to a ``--`` (dropped too) or to the end. ``node_name`` is the node's
    default name, against which ``node:``-prefixed ``__ns``/``__node`` rules are matched
    (None: all apply). Params files are read here, so a bad one stops the command early.
    """
    from robotmodel.rcl._params import param_file_entries, param_rule_entry

    rest: list[str] = []
    found: dict[str, str] = {}
    remaps: list[str] = []
    params: list[tuple[str, str, Any]] = []
    levels: list[tuple[str, str]] = []
    unknown: list[str] = []
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
        elif word in _SWITCHES:
            pass
        elif word in _REMAP_FLAGS or word in _VALUE_FLAGS:
            if i + 1 >= len(words):
                raise RosArgsError(_trailing(word))
            value = words[i + 1]
            if word in _REMAP_FLAGS:
                _rule(word, value, node_name, found, remaps)
            elif word in _PARAM_FLAGS:
                params.append(param_rule_entry(word, value))
            elif word == "--params-file":
                params.extend(param_file_entries(word, value))
            elif word == "--log-level":
                logger, _, level = value.rpartition(":=")
                if level.upper() not in _SEVERITIES:
                    raise RosArgsError(f"Couldn't parse log level: '{word} {value}'. Error: Argument does not use "
                                       "a valid severity level")
                levels.append((logger, level))
            i += 1
        else:
            unknown.append(word)
        i += 1
    if unknown:
        # rclcpp refuses them (UnknownROSArgsError): '__ns:=/r1' without its -r would otherwise do nothing.
        raise RosArgsError("found unknown ROS arguments: '" + "', '".join(unknown) + "'")
    return RosArgs(found.get("namespace"), found.get("node_name"), tuple(remaps), tuple(params),
                   tuple(levels)), rest


def take_node_args(words: Sequence[str], node_name: str | None = None,
                   environ: Mapping[str, str] | None = None) -> tuple[RosArgs, list[str]]:
    """A node command's ROS arguments: ``--ros-args`` blocks, then on the ROS 1 wire ROS 1's forms.

    ROS 1's words (:mod:`robotmodel.rcl._ros1args`) add to what the blocks set (a block's
    ``__ns``/``__node`` wins over them); ``environ`` (default ``os.environ``) picks the wire.
    """
    from robotmodel.rcl._ros1args import ros1_wire, take_ros1_args

    ros, rest = take_ros_args(words, node_name)
    apply_log_levels(ros)
    if not ros1_wire(environ):
        return ros, rest
    ros1, rest = take_ros1_args(rest)
    return replace(ros, namespace=ros.namespace if ros.namespace is not None else ros1.namespace,
                   node_name=ros.node_name if ros.node_name is not None else ros1.node_name,
                   remaps=ros1.remaps + ros.remaps, params=ros1.params + ros.params), rest


def apply_log_levels(ros: RosArgs) -> None:
    """Set the console's levels from ``--log-level`` (as rcl's init does for the process)."""
    from robotmodel.rcl._console import set_log_level

    for logger, level in ros.log_levels:
        set_log_level(logger, level)


def _trailing(flag: str) -> str:
    if flag in _REMAP_FLAGS:
        return f"Couldn't parse trailing {flag} flag. No remap rule found."
    if flag in _PARAM_FLAGS:
        return f"Couldn't parse trailing {flag} flag. No parameter override rule found."
    if flag == "--log-level":
        return f"Couldn't parse trailing log level flag: '{flag}'. No log level provided."
    if flag in ("-e", "--enclave"):
        return f"Couldn't parse trailing {flag} flag. No enclave path provided."
    if flag == "--log-file-name":
        return f"Couldn't parse trailing {flag} flag. No string prefix provided."
    return f"Couldn't parse trailing {flag} flag. No file path provided."


def node_namespace(option: str | None, ros: RosArgs) -> str:
    """The namespace a node gets: an ``__ns`` remap, else ``--namespace`` made absolute, else ``/``."""
    if ros.namespace is not None:
        return ros.namespace
    if option is None:
        return "/"
    return _check_namespace(option)


def split_ros_words(words: Sequence[str], node_name: str | None = None) -> tuple[list[str], str, RosArgs]:
    """For commands parsing their own words: (other words, namespace, the ``--ros-args`` settings).

    Takes the ``--ros-args`` blocks and ``--namespace NS`` / ``--namespace=NS`` out.
    """
    ros, words = take_node_args(words, node_name)
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
    return rest, node_namespace(option, ros), ros


def split_node_words(words: Sequence[str], node_name: str | None = None) -> tuple[list[str], str, str | None]:
    """:func:`split_ros_words` giving the ``__node`` override (or None) instead of all settings."""
    rest, namespace, ros = split_ros_words(words, node_name)
    return rest, namespace, ros.node_name


def node_params(ros: RosArgs, namespace: str, name: str) -> dict[str, Any]:
    """The parameter overrides the node ``namespace``/``name`` gets (matched on its final FQN)."""
    from robotmodel.rcl._params import params_for_node

    found: dict[str, Any] = params_for_node(ros.params, namespace.rstrip("/") + "/" + name)
    return found


def warn_ignored_params(ros: RosArgs, namespace: str, name: str, used: Collection[str] = ()) -> None:
    """For commands with no parameters (but ``used``): one rcutils WARN line per other override the node gets."""
    from robotmodel.rcl._console import ros_log
    from robotmodel.rcl._params import warn_unused_params

    warn_unused_params(node_params(ros, namespace, name), lambda n: n in used,
                lambda text: ros_log("WARN", logger_name(namespace, name), text),
                {"use_sim_time": "there is no /clock here", "qos_overrides": "QoS overrides are not read here"})


def logger_name(namespace: str, node_name: str) -> str:
    """The node's logger name as rcl forms it: namespace tokens and name joined by '.' (``r1.rsp``)."""
    return ".".join([*namespace.strip("/").split("/"), node_name]) if namespace != "/" else node_name


def remove_ros_args(words: Sequence[str]) -> list[str]:
    """The words without ROS's own arguments, as ``rclpy.utilities.remove_ros_args`` leaves them.

    Each ``--ros-args`` block runs to a ``--`` (dropped too) or to the end. The blocks are
    dropped unread; :func:`take_ros_args` reads them (and refuses what rcl refuses).
    """
    rest: list[str] = []
    inside = False
    for word in words:
        if inside:
            inside = word != "--"
        elif word == "--ros-args":
            inside = True
        else:
            rest.append(word)
    return rest
