"""Which joints joint_state_publisher publishes, with their limits, defaults and mimic rules.

joint_state_publisher reads the description XML itself rather than through urdfdom, and
some of its rules depend on what the XML literally says (an absent ``soft_lower_limit``
is not 0, a ``<mimic>`` on a fixed joint is never looked at). So this reads the XML text
too: every ``<joint>`` directly under ``<robot>``, in document order.
"""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET
from collections.abc import Mapping
from dataclasses import dataclass

from robotmodel.errors import URDFError, URDFParseError

__all__ = ["DependentJoint", "FreeJoint", "JointLayout", "read_layout"]

# joint_state_publisher leaves these out of its message entirely.
_NOT_PUBLISHED = ("fixed", "floating", "planar")


@dataclass(frozen=True, slots=True)
class FreeJoint:
    """A joint whose value is set (default, ``set()``, a source topic), with its slider range."""

    name: str
    lower: float
    upper: float
    zero: float
    continuous: bool


@dataclass(frozen=True, slots=True)
class DependentJoint:
    """A mimic joint: value = ``factor`` × value of the free joint ``parent`` + ``offset``.

    ``parent`` is the free joint at the end of the mimic chain (chains are composed).
    """

    name: str
    parent: str
    factor: float
    offset: float


@dataclass(frozen=True, slots=True)
class JointLayout:
    """The joints of one description as joint_state_publisher sees them.

    ``names`` is the message's joint order (document order, mimic joints included);
    ``unresolved`` lists mimic joints whose chain does not end at a free joint, which
    are left out of ``names``; ``every_joint`` names all joints, fixed ones included.
    """

    robot: str
    names: tuple[str, ...]
    free: Mapping[str, FreeJoint]
    dependent: Mapping[str, DependentJoint]
    unresolved: tuple[str, ...] = ()
    every_joint: frozenset[str] = frozenset()


def _float(name: str, jtype: str, which: str, text: str) -> float:
    try:
        return float(text)
    except ValueError:
        raise URDFError(f'"{which}" limit must be a float for joint "{name}" of type "{jtype}"') from None


def _mimic_float(name: str, tag: Mapping[str, str], attribute: str, default: float) -> float:
    try:
        return float(tag.get(attribute, default))
    except ValueError:
        raise URDFError(f"mimic {attribute} of joint \"{name}\" is not a number: {tag[attribute]!r}") from None


def _limits(joint: ET.Element, name: str, jtype: str, use_smallest: bool) -> tuple[float, float]:
    if jtype == "continuous":
        lower, upper = -math.pi, math.pi
    else:
        limit = joint.find(".//limit")
        if limit is None:
            raise URDFError(f'Limits must be specified for joint "{name}" of type "{jtype}"')
        for which in ("lower", "upper"):
            if which not in limit.attrib:
                raise URDFError(f'"{which}" limit must be specified for joint "{name}" of type "{jtype}"')
        lower = _float(name, jtype, "lower", limit.attrib["lower"])
        upper = _float(name, jtype, "upper", limit.attrib["upper"])
    safety = joint.findall(".//safety_controller")
    # Only a single safety controller narrows the range, and only by the attributes it has.
    if use_smallest and len(safety) == 1:
        soft = safety[0].attrib
        if "soft_lower_limit" in soft:
            lower = max(lower, _float(name, jtype, "soft_lower_limit", soft["soft_lower_limit"]))
        if "soft_upper_limit" in soft:
            upper = min(upper, _float(name, jtype, "soft_upper_limit", soft["soft_upper_limit"]))
    return lower, upper


def _default(name: str, lower: float, upper: float, zeros: Mapping[str, float]) -> float:
    if name in zeros:
        return float(zeros[name])  # used as given, not clamped
    if lower > 0 or upper < 0:
        return (lower + upper) / 2
    return 0.0


def _resolve(
    direct: dict[str, tuple[str, float, float]], free: Mapping[str, FreeJoint],
) -> tuple[dict[str, DependentJoint], list[str]]:
    resolved: dict[str, DependentJoint] = {}
    unresolved: list[str] = []
    for name, rule in direct.items():
        parent, factor, offset = rule
        chain = [name]
        while parent in direct:
            if parent in chain:
                raise URDFError(f"Found an infinite recursive mimic chain: {[*chain, parent]}")
            chain.append(parent)
            parent, parent_factor, parent_offset = direct[parent]
            offset += factor * parent_offset
            factor *= parent_factor
        if parent in free:
            resolved[name] = DependentJoint(name, parent, factor, offset)
        else:
            unresolved.append(name)
    return resolved, unresolved


def read_layout(
    urdf: str,
    zeros: Mapping[str, float] | None = None,
    *,
    use_mimic_tags: bool = True,
    use_smallest_joint_limits: bool = True,
    dependent_joints: Mapping[str, tuple[str, float, float]] | None = None,
) -> JointLayout:
    """joint_state_publisher's joints of the URDF text ``urdf``.

    ``dependent_joints`` (ROS 1's parameter: joint -> (parent, factor, offset)) makes those
    joints follow another one as a mimic tag would; a joint's own mimic tag comes first.

    Raises :class:`URDFError` with joint_state_publisher's text for a revolute or
    prismatic joint without usable limits, and for a mimic cycle.
    """
    try:
        root = ET.fromstring(urdf)
    except ET.ParseError as exc:
        raise URDFParseError(f"robot description is not well-formed XML: {exc}") from None
    robot = root if root.tag == "robot" else root.find(".//robot")
    if robot is None:
        raise URDFError('URDF must have a "robot" tag')
    zeros = zeros or {}
    names: list[str] = []
    free: dict[str, FreeJoint] = {}
    direct: dict[str, tuple[str, float, float]] = {}
    for joint in robot.findall("joint"):
        jtype = joint.get("type", "")
        if jtype in _NOT_PUBLISHED:
            continue
        name = joint.get("name", "")
        lower, upper = _limits(joint, name, jtype, use_smallest_joint_limits)
        names.append(name)
        mimics = joint.findall(".//mimic")
        if use_mimic_tags and len(mimics) == 1:
            tag = mimics[0].attrib
            direct[name] = (tag.get("joint", ""), _mimic_float(name, tag, "multiplier", 1.0),
                            _mimic_float(name, tag, "offset", 0.0))
            continue
        if dependent_joints and name in dependent_joints:
            direct[name] = dependent_joints[name]
            continue
        free[name] = FreeJoint(name, lower, upper, _default(name, lower, upper, zeros), jtype == "continuous")
    dependent, unresolved = _resolve(direct, free)
    published = tuple(n for n in names if n not in unresolved)
    every = frozenset(j.get("name", "") for j in robot.findall("joint"))
    return JointLayout(robot.get("name", ""), published, free, dependent, tuple(unresolved), every)
