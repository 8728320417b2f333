"""Remap rules as each launch system gathers them for a node, in the form rcl reads (``from:=to``).

- ROS 1 (roslaunch): a ``<remap>`` at launch or group scope applies to the nodes after it in
  that scope, included files included; one inside a ``<node>`` to that node only. A rule
  replaces an earlier one with the same ``from`` (as written). The node (roscpp, rospy)
  resolves both sides against its own namespace (``~x`` against its name) and keeps the
  last rule per resolved ``from``; since rcl applies the *first* matching rule, the list
  handed on keeps only that last rule per resolved name, so the two agree.
- ROS 2 (launch_ros): ``<set_remap>`` rules of the scope come first, then the node's own
  ``<remap>`` rules, all verbatim; rcl picks the first match. (Their scoping is the
  loader's: :mod:`robotmodel.launch._loader`.)
"""

from __future__ import annotations

import re
from collections.abc import Sequence

__all__ = ["Remap", "ros1_add", "ros1_for_node", "ros1_problem"]

#: One rule: (from, to), as written in the launch file (after substitution).
Remap = tuple[str, str]

# roslaunch's idea of a legal name: an optional leading '/' or '~', a letter, then word characters or '/'.
_ROS1_NAME = re.compile(r"[~/A-Za-z][\w/]*")


def _canonical(name: str) -> str:
    """The canonical form roslaunch uses: repeated and trailing '/' dropped, a leading one kept."""
    if name in ("", "/"):
        return name
    body = "/".join(part for part in name.split("/") if part)
    return "/" + body if name.startswith("/") else body


def _legal(name: str) -> bool:
    return name == "" or (_ROS1_NAME.fullmatch(name) is not None and "//" not in name)


def ros1_problem(source: str, target: str) -> str | None:
    """What roslaunch refuses in a ``<remap>`` (its texts), or None."""
    source, target = _canonical(source), _canonical(target)
    if not source or not target:
        return "remap from/to attributes cannot be empty"
    if not _legal(source):
        return f"remap from [{source}] is not a valid ROS name"
    if not _legal(target):
        return f"remap to [{target}] is not a valid ROS name"
    return None


def ros1_add(rules: list[Remap], source: str, target: str) -> None:
    """Add a checked rule to a ROS 1 scope's (or node's) list, replacing one with the same ``from``."""
    rule = (_canonical(source), _canonical(target))
    rules[:] = [r for r in rules if r[0] != rule[0]]
    rules.append(rule)


def _resolve(name: str, namespace: str, node: str) -> str:
    if name.startswith("/"):
        return name
    if name.startswith("~"):
        return namespace.rstrip("/") + "/" + node + "/" + name[1:].lstrip("/")
    return namespace.rstrip("/") + "/" + name


def _rcl_form(name: str) -> str:
    # rcl writes a private name as '~/x'; ROS 1's '~x' means the same.
    return "~/" + name[1:].lstrip("/") if name.startswith("~") and name != "~" else name


def ros1_for_node(rules: Sequence[Remap], namespace: str, node: str) -> tuple[Remap, ...]:
    """The node's rules for rcl: the last rule per resolved ``from``, private names in rcl's form."""
    last: dict[str, int] = {}
    for index, (source, _) in enumerate(rules):
        last[_resolve(source, namespace, node)] = index
    keep = sorted(last.values())
    return tuple((_rcl_form(rules[i][0]), _rcl_form(rules[i][1])) for i in keep)
