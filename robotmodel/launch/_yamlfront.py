"""ROS 2 YAML launch files (launch_yaml) read into the XML launcher's element tree.

The file is ``launch:`` followed by a list of one-key mappings, each an action (``arg``,
``node``, ``include``, ``group``, ...) whose scalar keys are its attributes; a list of
mappings under a key is that many child elements of that tag (``param``, ``remap``, an
include's ``arg``), and ``children:`` holds a group's actions. Lines are kept for errors.
"""

from __future__ import annotations

from pathlib import Path

import yaml

from robotmodel.errors import LaunchError
from robotmodel.launch._xml import Element

__all__ = ["parse_yaml_file"]


def parse_yaml_file(path: Path) -> Element:
    """The ``<launch>`` element equivalent of YAML launch file ``path``."""
    try:
        node = yaml.compose(path.read_text(encoding="utf-8"), Loader=yaml.SafeLoader)
    except OSError as exc:
        raise LaunchError(f"{path}: cannot read launch file: {exc.strerror or exc}") from None
    except yaml.YAMLError as exc:
        mark = getattr(exc, "problem_mark", None)
        line = mark.line + 1 if mark is not None else 1
        raise LaunchError(f"{path}:{line}: invalid YAML: {getattr(exc, 'problem', None) or exc}") from None
    if not isinstance(node, yaml.MappingNode) or len(node.value) != 1 or node.value[0][0].value != "launch":
        raise LaunchError(f"{path}:1: a YAML launch file is one mapping with the key 'launch'")
    root = Element("launch", {}, node.start_mark.line + 1)
    root.children = _actions(path, node.value[0][1])
    return root


def _actions(path: Path, node: yaml.Node) -> list[Element]:
    if isinstance(node, yaml.ScalarNode) and node.value in ("", "~", "null"):
        return []
    if not isinstance(node, yaml.SequenceNode):
        raise LaunchError(f"{path}:{node.start_mark.line + 1}: expected a list of actions")
    out: list[Element] = []
    for item in node.value:
        if not isinstance(item, yaml.MappingNode) or len(item.value) != 1:
            raise LaunchError(f"{path}:{item.start_mark.line + 1}: each action is a mapping with one key (its tag)")
        key, body = item.value[0]
        out.append(_element(path, str(key.value), body, key.start_mark.line + 1))
    return out


def _element(path: Path, tag: str, body: yaml.Node, line: int) -> Element:
    elem = Element(tag, {}, line)
    if isinstance(body, yaml.ScalarNode):
        return elem
    if not isinstance(body, yaml.MappingNode):
        raise LaunchError(f"{path}:{line}: <{tag}>: expected a mapping of attributes")
    for key_node, value in body.value:
        key = str(key_node.value)
        if key == "children":
            elem.children.extend(_actions(path, value))
        elif isinstance(value, yaml.SequenceNode) and value.value and all(
                isinstance(v, yaml.MappingNode) for v in value.value):
            elem.children.extend(_element(path, key, v, v.start_mark.line + 1) for v in value.value)
        elif isinstance(value, yaml.ScalarNode):
            elem.attrib[key] = _scalar(value)
        else:
            elem.attrib[key] = yaml.serialize(value).strip().replace("\n", " ")
    return elem


def _scalar(node: yaml.ScalarNode) -> str:
    loaded = yaml.safe_load(yaml.serialize(node)) if node.style is None else node.value
    if isinstance(loaded, bool):
        return "true" if loaded else "false"
    return str(node.value)
