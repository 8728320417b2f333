"""Which link and joint of the old description is which of the new: same names, then renames.

A rename is found from the tree, never from names alone:

- the two ends of a joint present on both sides are the same links (a joint that kept its
  name but whose child now has a new name: the child was renamed);
- a joint of each side with the same parent, child and type (after mapping renamed links)
  is the same joint under a new name;
- when those found nothing more: the two roots, if neither is matched yet, are the same link;
- and when a joint and its child link were both renamed, the unmatched joints under the same
  (mapped) parent with the same type pair up when there is one on each side, or, among
  several, when exactly one pair has the same origin.

The rules repeat until nothing more pairs up, so a rename deep in the tree is found from
either end.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from robotmodel.model import Pose, RobotDescription

__all__ = ["Matching", "match"]


@dataclass(frozen=True, slots=True)
class Matching:
    """Old name → new name for every link and joint present on both sides (renamed or not)."""

    links: dict[str, str]
    joints: dict[str, str]


class _Pairs:
    """A growing one-to-one old → new name map."""

    def __init__(self, old: list[str], new: list[str]) -> None:
        present = set(new)
        self.forward = {name: name for name in old if name in present}
        self.taken = set(self.forward.values())
        self.grew = False

    def pair(self, old: str, new: str) -> None:
        if old in self.forward or new in self.taken:
            return
        self.forward[old] = new
        self.taken.add(new)
        self.grew = True


def _same_origin(a: Pose, b: Pose, tolerance: float) -> bool:
    return all(math.isclose(x, y, rel_tol=0.0, abs_tol=tolerance) for x, y in zip(a.xyz + a.rpy, b.xyz + b.rpy,
                                                                                   strict=True))


def _sure_rules(old: RobotDescription, new: RobotDescription, links: _Pairs, joints: _Pairs) -> None:
    for old_name, new_name in list(joints.forward.items()):
        a, b = old.joint(old_name), new.joint(new_name)
        links.pair(a.parent, b.parent)
        links.pair(a.child, b.child)
    # A link has one parent joint: when both ends map, the edge is the same joint renamed.
    for joint in old.joints:
        if joint.name in joints.forward:
            continue
        child = links.forward.get(joint.child)
        parent = links.forward.get(joint.parent)
        if child is None or parent is None:
            continue
        other = new.parent_joint(child)
        if other is not None and other.parent == parent and other.type is joint.type:
            joints.pair(joint.name, other.name)


def _grouped_rule(old: RobotDescription, new: RobotDescription, links: _Pairs, joints: _Pairs,
                  tolerance: float) -> None:
    # Only once the tree said all it could: a root replaced by a new link above a renamed one
    # must not pair with it when the old root's children already told where it went.
    links.pair(old.root, new.root)
    for old_parent, new_parent in list(links.forward.items()):
        olds = [j for j in old.child_joints(old_parent)
                if j.name not in joints.forward and j.child not in links.forward]
        news = [j for j in new.child_joints(new_parent)
                if j.name not in joints.taken and j.child not in links.taken]
        for kind in sorted({j.type for j in olds}, key=lambda t: t.value):
            a = [j for j in olds if j.type is kind]
            b = [j for j in news if j.type is kind]
            if len(a) == 1 and len(b) == 1:
                pairs = [(a[0], b[0])]
            else:
                pairs = []
                for ja in a:
                    same = [jb for jb in b if _same_origin(ja.origin, jb.origin, tolerance)]
                    back = [jx for jx in a if same and _same_origin(jx.origin, same[0].origin, tolerance)]
                    if len(same) == 1 and len(back) == 1:
                        pairs.append((ja, same[0]))
            for ja, jb in pairs:
                joints.pair(ja.name, jb.name)
                links.pair(ja.child, jb.child)


def match(old: RobotDescription, new: RobotDescription, tolerance: float) -> Matching:
    """Pair the links and joints of ``old`` with those of ``new`` (see the module documentation)."""
    links = _Pairs([x.name for x in old.links], [x.name for x in new.links])
    joints = _Pairs([x.name for x in old.joints], [x.name for x in new.joints])
    while True:
        links.grew = joints.grew = False
        _sure_rules(old, new, links, joints)
        if links.grew or joints.grew:
            continue
        _grouped_rule(old, new, links, joints, tolerance)
        if not (links.grew or joints.grew):
            break
    return Matching(links.forward, joints.forward)
