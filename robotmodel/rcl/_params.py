"""ROS 2 parameter overrides: ``-p name:=value`` and ``--params-file FILE``, read as rcl reads them.

- Values are YAML, typed by rcl's rules: ``true``/``yes``/``on`` (and their spellings) are
  bool, ``50`` (``0x32``) is integer, ``50.0``/``1e3``/``.inf`` double, anything else or
  anything quoted a string; ``[a, b]`` is an array whose items share one type.
- A params file maps node names (``robot_state_publisher:``, ``/r1/rsp:``, ``/**:``) to
  ``ros__parameters:``; nested keys flatten with dots (``zeros: {j1: 0.5}`` is ``zeros.j1``).
- Every override goes into the table of its node pattern (``-p`` without a ``node:`` prefix
  means ``/**``), a later value replacing an earlier one in place; a node then applies, in
  order of each table's first appearance, the tables whose pattern matches its fully
  qualified name, as rclcpp does. So ``--params-file F -p rate:=20`` gives 20 when F sets
  ``rate`` under ``/**`` or has no ``rate`` after a ``/**`` section, but F's own
  ``joint_state_publisher:`` entry beats a ``-p`` that came before that table appeared
  (``-p joint_state_publisher:rate:=20`` always lands in the node's own table).

Commands then read their settings with :func:`typed_param`, which refuses a wrong type with
rclcpp's text, and :func:`warn_unused_params` names the overrides they have no use for.
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable, Iterable, Mapping
from pathlib import Path
from typing import Any

from robotmodel.errors import RosArgsError

__all__ = [
    "ParamEntry",
    "ParamValue",
    "is_param_name",
    "param_file_entries",
    "param_rule_entry",
    "param_type_name",
    "params_for_node",
    "typed_param",
    "warn_unused_params",
]

ParamValue = bool | int | float | str | tuple[bool, ...] | tuple[int, ...] | tuple[float, ...] | tuple[str, ...]
#: (node pattern, parameter name, value), in command-line order.
ParamEntry = tuple[str, str, ParamValue]

_TOKEN = r"[A-Za-z_][A-Za-z0-9_]*"
_PARAM_NAME = re.compile(rf"^{_TOKEN}(\.{_TOKEN})*$")
_PREFIX = re.compile(rf"^({_TOKEN}):(?!=)")
_TRUE = frozenset(["Y", "y", "yes", "Yes", "YES", "true", "True", "TRUE", "on", "On", "ON"])
_FALSE = frozenset(["N", "n", "no", "No", "NO", "false", "False", "FALSE", "off", "Off", "OFF"])
_INF_NAN = frozenset(f"{s}{w}" for s in ("", "+", "-") for w in (".inf", ".Inf", ".INF")) | {".nan", ".NaN", ".NAN"}
# strtoll with base 0: decimal, 0x hex or leading-0 octal, optional sign, leading blanks.
_INT = re.compile(r"^[ \t\n\v\f\r]*[+-]?(0[xX][0-9a-fA-F]+|0[0-7]*|[1-9][0-9]*)$")
_PARAMS_KEY = "ros__parameters"


def _scalar(text: str, quoted: bool, tagged_str: bool) -> bool | int | float | str:
    if quoted or tagged_str:
        return text
    if text in _TRUE:
        return True
    if text in _FALSE:
        return False
    if _INT.match(text):
        value = int(text.strip(), 0) if not re.match(r"^\s*[+-]?0[0-7]+$", text) else int(text.strip(), 8)
        if -(2**63) <= value < 2**63:
            return value
    if text in _INF_NAN:
        return float(text.lstrip("+").replace(".", "").lower())
    if text.strip() and "_" not in text:
        try:
            number = float.fromhex(text) if re.match(r"^\s*[+-]?0[xX]", text) else float(text)
        except ValueError:
            pass
        else:
            if not math.isinf(number) or re.search(r"inf", text, re.IGNORECASE):
                return number
    return text


def param_type_name(value: ParamValue) -> str:
    """Rclcpp's name of a value's parameter type (``double``, ``string_array``, ...)."""
    kinds = {bool: "bool", int: "integer", float: "double", str: "string"}
    if isinstance(value, tuple):
        return f"{kinds[type(value[0])]}_array" if value else "string_array"
    return kinds[type(value)]


class _Events:
    """PyYAML's (libyaml's) event stream, walked as rcl's parser walks it."""

    def __init__(self, text: str) -> None:
        import yaml

        try:
            self.items = list(yaml.parse(text))
        except yaml.YAMLError as exc:
            mark = getattr(exc, "problem_mark", None)
            line = mark.line + 1 if mark is not None else 1
            raise ValueError(f"Error parsing a event near line {line}") from None
        self.pos = 0

    def peek(self) -> Any:
        return self.items[self.pos]

    def take(self) -> Any:
        self.pos += 1
        return self.items[self.pos - 1]

    def skip_to_content(self) -> bool:
        import yaml

        while isinstance(self.peek(), (yaml.StreamStartEvent, yaml.DocumentStartEvent)):
            self.take()
        return not isinstance(self.peek(), (yaml.DocumentEndEvent, yaml.StreamEndEvent))

    def value(self) -> ParamValue:
        import yaml

        event = self.take()
        line = event.start_mark.line + 1
        if isinstance(event, yaml.AliasEvent) or getattr(event, "anchor", None):
            raise ValueError(f"Will not support aliasing at line {line}")
        if isinstance(event, yaml.ScalarEvent):
            return self._scalar(event)
        if isinstance(event, yaml.SequenceStartEvent):
            items: list[bool | int | float | str] = []
            while not isinstance(self.peek(), yaml.SequenceEndEvent):
                item = self.take()
                if not isinstance(item, yaml.ScalarEvent):
                    raise ValueError(f"Sequences can only hold scalars, at line {item.start_mark.line + 1}")
                value = self._scalar(item)
                if items and type(value) is not type(items[0]):
                    raise ValueError(f"Sequence should be of same type. Value type '{param_type_name(value)}' do not "
                                     f"belong at line_num {item.start_mark.line + 1}")
                items.append(value)
            self.take()
            return tuple(items)  # type: ignore[return-value]
        raise ValueError(f"a parameter value must be a scalar or a sequence, at line {line}")

    @staticmethod
    def _scalar(event: Any) -> bool | int | float | str:
        quoted = event.style in ("'", '"')
        if not quoted and not event.value and event.tag is None:
            raise ValueError(f"No value at line {event.start_mark.line + 1}")
        return _scalar(event.value, quoted, event.tag in ("tag:yaml.org,2002:str", "!!str"))


def is_param_name(name: str) -> bool:
    """Whether rcl accepts ``name`` as a parameter name (tokens joined by dots: ``zeros.j1``)."""
    return _PARAM_NAME.fullmatch(name) is not None


def _node_and_name(flag: str, rule: str) -> tuple[str, str, str]:
    where = f"Couldn't parse parameter override rule: '{flag} {rule}'. Error:"
    node = "/**"
    prefix = _PREFIX.match(rule)
    rest = rule
    if prefix:
        node, rest = prefix.group(1), rule[prefix.end():]
    name, sep, text = rest.partition(":=")
    if not sep:
        raise RosArgsError(f"{where} expected ':=' between the parameter name and its value")
    if not _PARAM_NAME.fullmatch(name):
        wild = "Wildcard '**' is not implemented" if "**" in name else (
            "Wildcard '*' is not implemented" if "*" in name else f"invalid parameter name '{name}'")
        raise RosArgsError(f"{where} {wild}")
    return node, name, text


def param_rule_entry(flag: str, rule: str) -> ParamEntry:
    """One ``-p [node:]name:=value`` rule; raises RosArgsError with rcl's text."""
    node, name, text = _node_and_name(flag, rule)
    try:
        events = _Events(text)
        if not events.skip_to_content():
            raise ValueError("No value at line 1")
        value = events.value()
    except ValueError as exc:
        raise RosArgsError(f"Couldn't parse parameter override rule: '{flag} {rule}'. Error: {exc}") from None
    return node, name, value


def _params(events: _Events, node: str, prefix: str, out: list[ParamEntry]) -> None:
    import yaml

    while not isinstance(events.peek(), yaml.MappingEndEvent):
        key = events.take()
        if not isinstance(key, yaml.ScalarEvent) or not key.value:
            raise ValueError(f"No key at line {key.start_mark.line + 1}")
        if isinstance(events.peek(), yaml.MappingStartEvent):
            events.take()
            _params(events, node, f"{prefix}{key.value}.", out)
        else:
            out.append((node, prefix + key.value, events.value()))
    events.take()


def _nodes(events: _Events, parts: list[str], out: list[ParamEntry]) -> None:
    import yaml

    while not isinstance(events.peek(), yaml.MappingEndEvent):
        key = events.take()
        line = key.start_mark.line + 1
        if not isinstance(key, yaml.ScalarEvent) or not key.value:
            raise ValueError(f"No key at line {line}")
        if not isinstance(events.peek(), yaml.MappingStartEvent):
            raise ValueError(f"Cannot have a value before {_PARAMS_KEY} at line {line}")
        events.take()
        if key.value == _PARAMS_KEY:
            if not parts:
                raise ValueError(f"There are no node names before {_PARAMS_KEY} at line {line}")
            _params(events, "/".join(parts).replace("//", "/"), "", out)
        else:
            _nodes(events, [*parts, key.value], out)
    events.take()


def param_file_entries(flag: str, path: str) -> list[ParamEntry]:
    """The overrides of a ROS 2 params file, in file order; raises RosArgsError with rcl's text."""
    import yaml

    where = f"Couldn't parse params file: '{flag} {path}'. Error:"
    try:
        text = Path(path).read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError):
        raise RosArgsError(f"{where} Error opening YAML file") from None
    out: list[ParamEntry] = []
    try:
        events = _Events(text)
        if events.skip_to_content():
            if not isinstance(events.take(), yaml.MappingStartEvent):
                raise ValueError("a params file maps node names to ros__parameters")
            _nodes(events, [], out)
    except ValueError as exc:
        raise RosArgsError(f"{where} {exc}") from None
    return out


def _matches(pattern: str, fqn: str) -> bool:
    name = pattern if pattern.startswith("/") else "/" + pattern
    return re.fullmatch(name.replace("/*", r"(/\w+)"), fqn) is not None


def params_for_node(entries: Iterable[ParamEntry], fqn: str) -> dict[str, ParamValue]:
    """The overrides a node of fully qualified name ``fqn`` gets, as rclcpp merges them.

    rcl keeps one table per node pattern, in order of first appearance, a later value of a
    name replacing the earlier one in place; rclcpp applies the matching tables in order.
    """
    tables: dict[str, dict[str, ParamValue]] = {}
    for node, name, value in entries:
        tables.setdefault(node, {})[name] = value
    out: dict[str, ParamValue] = {}
    for node, table in tables.items():
        if _matches(node, fqn):
            out.update(table)
    return out


def typed_param(values: Mapping[str, ParamValue], name: str, declared: str, *also: str) -> ParamValue | None:
    """The override of ``name`` if any, checked against its declared rclcpp type (or ``also`` ones).

    A wrong type raises RosArgsError with rclcpp's text (InvalidParameterTypeException).
    """
    if name not in values:
        return None
    value = values[name]
    got = param_type_name(value)
    if got == declared or got in also or (value == () and declared.endswith("_array")):
        return value
    raise RosArgsError(f"parameter '{name}' has invalid type: Wrong parameter type, parameter {{{name}}} is of type "
                       f"{{{declared}}}, setting it to {{{got}}} is not allowed.")


def warn_unused_params(values: Mapping[str, ParamValue], used: Callable[[str], bool], warn: Callable[[str], None],
                why: Mapping[str, str] | None = None) -> None:
    """Say once per name which overrides the command has no use for (ROS would keep them unread)."""
    for name in values:
        if not used(name):
            reason = (why or {}).get(name.split(".")[0], "not a parameter of this node")
            warn(f"parameter '{name}' is ignored here: {reason}")
