"""A RobotDescription built directly is validated as parse_urdf validates the same robot.

Each case is written once as typed values; the XML form of the very same robot is
produced by ``to_urdf`` (which only reads attributes, so it serialises an invalid robot
too) and parsed. Both ways must fail with the same message text.
"""

from __future__ import annotations

import dataclasses
import math
from types import SimpleNamespace

import pytest

from robotmodel.errors import URDFError
from robotmodel.model import (
    Inertia,
    Inertial,
    Joint,
    JointType,
    Limit,
    Link,
    Material,
    Mimic,
    Pose,
    RobotDescription,
    parse_urdf,
    to_urdf,
)

LIMIT = Limit(1.0, 1.0, -1.0, 1.0)


def _links(*names: str) -> tuple[Link, ...]:
    return tuple(Link(n) for n in names)


def _rev(name: str, parent: str, child: str, **kw: object) -> Joint:
    fields: dict[str, object] = {"limit": LIMIT, "axis": (0.0, 0.0, 1.0)}
    fields.update(kw)
    return Joint(name, JointType.REVOLUTE, parent, child, **fields)  # type: ignore[arg-type]


# (id, name, links, joints, materials, expected substring)
CASES = [
    ("mimic-cycle", "r", _links("a", "b", "c"),
     (_rev("j1", "a", "b", mimic=Mimic("j2")), _rev("j2", "b", "c", mimic=Mimic("j1"))), (),
     "mimic joints form a cycle: j1 -> j2 -> j1"),
    ("mimic-self", "r", _links("a", "b"), (_rev("j1", "a", "b", mimic=Mimic("j1")),), (),
     "mimic joints form a cycle: j1 -> j1"),
    ("no-root", "r", _links("a", "b"), (_rev("j1", "a", "b"), _rev("j2", "b", "a")), (),
     "Failed to find root link: No root link found. The robot xml is not a valid tree."),
    ("two-roots", "r", _links("a", "b", "c"), (_rev("j1", "a", "b"),), (),
     "Failed to find root link: Two root links found: [a] and [c]"),
    ("two-parents", "r", _links("a", "b", "c"),
     (_rev("j1", "a", "b"), _rev("j2", "a", "c"), _rev("j3", "b", "c")), (),
     "link [c] has two parent joints, [j2] and [j3]"),
    ("partial-cycle", "r", _links("a", "b", "c", "d"),
     (_rev("j1", "a", "b"), _rev("j2", "c", "d"), _rev("j3", "d", "c")), (),
     "links [c, d] form a cycle that is not connected to root link [a]"),
    ("missing-child", "r", _links("a"), (_rev("j1", "a", "ghost"),), (),
     "Failed to build tree: child link [ghost] of joint [j1] not found"),
    ("missing-parent", "r", _links("b"), (_rev("j1", "nope", "b"),), (),
     "parent link [nope] of joint [j1] not found."),
    ("self-joint", "r", _links("a", "b"), (_rev("j1", "a", "b"), _rev("j2", "b", "b")), (),
     "joint [j2] has link [b] as both its parent and its child"),
    ("no-links", "r", (), (), (), "No link elements found in urdf file"),
    ("no-name", "", _links("a"), (), (), "No name given for the robot."),
    ("duplicate-link", "r", _links("a", "a"), (), (), "link 'a' is not unique."),
    ("duplicate-joint", "r", _links("a", "b", "c"), (_rev("j", "a", "b"), _rev("j", "a", "c")), (),
     "joint 'j' is not unique."),
    ("duplicate-material", "r", _links("a"), (), (Material("m", (1.0, 0, 0, 1)),) * 2,
     "material 'm' is not unique."),
    ("revolute-without-limit", "r", _links("a", "b"), (_rev("j", "a", "b", limit=None),), (),
     "Joint [j] is of type REVOLUTE but it does not specify limits"),
    ("prismatic-without-limit", "r", _links("a", "b"),
     (Joint("j", JointType.PRISMATIC, "a", "b"),), (), "Joint [j] is of type PRISMATIC without limits"),
    ("zero-axis", "r", _links("a", "b"), (_rev("j", "a", "b", axis=(0.0, 0.0, 0.0)),), (),
     "joint [j] has a zero axis"),
    ("nan-origin", "r", _links("a", "b"), (_rev("j", "a", "b", origin=Pose((math.nan, 0.0, 0.0))),), (),
     "value [nan] is not a finite number"),
    ("inf-limit", "r", _links("a", "b"), (_rev("j", "a", "b", limit=Limit(math.inf, 1.0, -1.0, 1.0)),), (),
     "value [inf] is not a finite number"),
    ("nan-inertia", "r", (Link("a", inertial=Inertial(1.0, Inertia(ixx=math.nan))),), (), (),
     "value [nan] is not a finite number"),
]


@pytest.mark.parametrize(("name", "links", "joints", "materials", "message"), [c[1:] for c in CASES],
                         ids=[c[0] for c in CASES])
def test_direct_construction_validated_like_parse(
    name: str, links: tuple[Link, ...], joints: tuple[Joint, ...], materials: tuple[Material, ...],
    message: str,
) -> None:
    text = to_urdf(SimpleNamespace(name=name, links=links, joints=joints,  # type: ignore[arg-type]
                                   materials=materials))
    with pytest.raises(URDFError) as parsed:
        parse_urdf(text)
    with pytest.raises(URDFError) as direct:
        RobotDescription(name, links, joints, materials)
    assert message in str(direct.value)
    # The same text; parse_urdf adds where (source, line) in front.
    assert str(parsed.value).endswith(str(direct.value))
    assert type(parsed.value) is type(direct.value)


def test_mimic_of_missing_joint_accepted_both_ways() -> None:
    # urdfdom loads it (real robots rely on it); lint reports it. Same both ways.
    links, joints = _links("a", "b"), (_rev("j", "a", "b", mimic=Mimic("ghost")),)
    direct = RobotDescription("r", links, joints)
    assert parse_urdf(to_urdf(direct)) == direct


def test_replace_is_validated_too() -> None:
    desc = RobotDescription("r", _links("a", "b"), (_rev("j", "a", "b"),))
    with pytest.raises(URDFError, match=r"child link \[c\] of joint \[j\] not found"):
        dataclasses.replace(desc, joints=(_rev("j", "a", "c"),))


def test_walks_are_bounded_on_a_deep_chain() -> None:
    n = 20000
    links = _links(*(f"l{i}" for i in range(n + 1)))
    joints = tuple(Joint(f"j{i}", JointType.FIXED, f"l{i}", f"l{i + 1}") for i in range(n))
    desc = RobotDescription("deep", links, joints)
    assert desc.root == "l0"
    walk = desc.walk()
    assert len(walk) == n and walk[-1][0] == n


def test_source_text_is_provenance_only() -> None:
    text = '<robot name="r"><link name="a"/></robot>'
    desc = parse_urdf(text)
    assert desc.source_text == text
    assert not hasattr(desc, "urdf")
    # A changed robot is not the text any more: it carries no stale source text.
    changed = dataclasses.replace(desc, name="other")
    assert changed.source_text == ""
    assert RobotDescription("r", desc.links, ()).source_text == ""
