r"""ROS 2 name remapping rules, with rcl's syntax and semantics.

A rule is ``[node:]from:=to``:

- ``from:=to`` remaps a topic (or service) name. ``from`` and ``to`` may be absolute
  (``/joint_states``), relative (``joint_states``, under the node's namespace) or private
  (``~/state``, under the node's fully qualified name); both are expanded against the node
  before use, so a rule matches the *expanded* name whatever spelling the code used.
  ``rostopic://`` or ``rosservice://`` before ``from`` limits a rule to topics or services.
- ``__node:=name`` (or ``__name:=``) renames the node; ``__ns:=/ns`` moves it (the
  namespace must be fully qualified).
- A ``node:`` prefix limits the rule to the node of that name (for topic rules: the node's
  name after any ``__node`` rule, as rcl matches them).

The first rule that matches wins. Wildcards (``*``, ``**``) and back-references (``\1``)
are refused, as rcl refuses them.

>>> rules = parse_rules(["joint_states:=/arm/joint_states", "rsp:/tf:=/r1/tf"])
>>> remap_topic(rules, "/r1/joint_states", "rsp", "/r1")
'/arm/joint_states'
>>> remap_topic(rules, "/tf", "rsp", "/r1"), remap_topic(rules, "/tf", "other", "/r1")
('/r1/tf', '/tf')
"""

from __future__ import annotations

import re
from collections.abc import Iterable
from dataclasses import dataclass
from enum import Enum

from robotmodel.bus._names import resolve_topic
from robotmodel.errors import BusError

__all__ = [
    "RemapKind",
    "RemapRule",
    "node_name_of",
    "node_namespace_of",
    "parse_rules",
    "remap_topic",
    "rule_problem",
]

_TOKEN = r"[A-Za-z_][A-Za-z0-9_]*"
_PREFIX = re.compile(rf"^({_TOKEN}):(?!=)")
_NAME = re.compile(rf"^(~/|/)?{_TOKEN}(/{_TOKEN})*$")
_NAMESPACE = re.compile(rf"^/({_TOKEN}/)*({_TOKEN})?$")


class RemapKind(Enum):
    """What a rule renames."""

    NAME = "name"            # topics and services
    TOPIC = "topic"          # rostopic://
    SERVICE = "service"      # rosservice://
    NODE_NAME = "node_name"  # __node / __name
    NAMESPACE = "namespace"  # __ns


@dataclass(frozen=True)
class RemapRule:
    """One parsed rule; ``node`` is its ``node:`` prefix (None: every node)."""

    kind: RemapKind
    match: str
    replacement: str
    node: str | None = None
    text: str = ""

    @classmethod
    def parse(cls, text: str) -> RemapRule:
        """Parse ``[node:]from:=to``; raises BusError with rcl's reason when it is not a rule."""
        rule, problem = _parse(text)
        if rule is None:
            raise BusError(f"Couldn't parse remap rule: '{text}'. Error: {problem}")
        return rule


def _bad_token(part: str, *, replacement: bool) -> str:
    for token in part.split("/"):
        if replacement and re.fullmatch(r"\\[1-9]", token):
            return "Backreferences are not implemented"
        if not replacement and token == "**":
            return "Wildcard '**' is not implemented"
        if not replacement and token == "*":
            return "Wildcard '*' is not implemented"
    return ""


def _parse(text: str) -> tuple[RemapRule | None, str]:
    rest = text
    node: str | None = None
    prefix = _PREFIX.match(rest)
    if prefix and not rest.startswith(("rostopic:", "rosservice:")):
        node, rest = prefix.group(1), rest[prefix.end():]
    lhs, sep, rhs = rest.partition(":=")
    if not sep:
        return None, "expected ':=' between the name and its replacement"
    if lhs in ("__node", "__name"):
        if not re.fullmatch(_TOKEN, rhs):
            return None, f"Node name not remapped to invalid name: '{rhs}'"
        return RemapRule(RemapKind.NODE_NAME, lhs, rhs, node, text), ""
    if lhs == "__ns":
        if not _NAMESPACE.fullmatch(rhs):
            return None, f"Namespace not remapped to a fully qualified name (found: {rhs})"
        return RemapRule(RemapKind.NAMESPACE, lhs, rhs, node, text), ""
    kind = RemapKind.NAME
    for scheme, scheme_kind in (("rostopic://", RemapKind.TOPIC), ("rosservice://", RemapKind.SERVICE)):
        if lhs.startswith(scheme):
            kind, lhs = scheme_kind, lhs[len(scheme):]
    if not _NAME.fullmatch(lhs):
        why = _bad_token(lhs.removeprefix("~/").lstrip("/"), replacement=False)
        return None, why or f"'{lhs}' is not a valid name to match"
    if not _NAME.fullmatch(rhs):
        why = _bad_token(rhs.removeprefix("~/").lstrip("/"), replacement=True)
        return None, why or f"'{rhs}' is not a valid replacement name"
    return RemapRule(kind, lhs, rhs, node, text), ""


def rule_problem(text: str) -> str:
    """Why ``text`` is not a remap rule rcl accepts ('' when it is one)."""
    return _parse(text)[1]


def parse_rules(rules: Iterable[str | RemapRule]) -> tuple[RemapRule, ...]:
    """Parse rule texts (parsed rules pass through), keeping their order; raises BusError."""
    return tuple(r if isinstance(r, RemapRule) else RemapRule.parse(r) for r in rules)


def _first(rules: Iterable[RemapRule], kind: RemapKind, node_name: str) -> RemapRule | None:
    for rule in rules:
        if rule.kind is kind and (rule.node is None or rule.node == node_name):
            return rule
    return None


def node_name_of(rules: Iterable[RemapRule], node_name: str) -> str:
    """The node's name after the first ``__node`` rule that applies to ``node_name``."""
    rule = _first(rules, RemapKind.NODE_NAME, node_name)
    return node_name if rule is None else rule.replacement


def node_namespace_of(rules: Iterable[RemapRule], node_name: str, namespace: str) -> str:
    """The node's namespace after the first ``__ns`` rule for ``node_name`` (its name before renaming)."""
    rule = _first(rules, RemapKind.NAMESPACE, node_name)
    return namespace if rule is None else rule.replacement


def remap_topic(rules: Iterable[RemapRule], name: str, node_name: str, namespace: str) -> str:
    """The topic ``name`` (fully qualified) after the first rule that matches it, as rcl remaps.

    Each rule's ``from`` is expanded against the node (a rule whose name cannot be expanded
    there is skipped); the replacement is expanded the same way.
    """
    for rule in rules:
        if rule.kind not in (RemapKind.NAME, RemapKind.TOPIC):
            continue
        if rule.node is not None and rule.node != node_name:
            continue
        try:
            expanded = resolve_topic(rule.match, namespace, node_name)
        except BusError:
            continue
        if expanded == name:
            return resolve_topic(rule.replacement, namespace, node_name)
    return name
