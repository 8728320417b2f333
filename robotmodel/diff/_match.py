"""Which link and joint of the old description is which of the new: same names, then renames.

A rename is found from the tree, never from names alone:

- the two ends of a joint present on both sides are the same links (a joint that kept its
  name but whose child now has a new name: the child was renamed);
- a joint of each side with the same parent, child and type (after mapping renamed links)
  is the same joint under a new name;
- when those found nothing more: the two roots, if neither is matched yet, are the same link;
- and when a joint and its child link were both renamed, the unmatched joints under the same
  (mapped) parent with the same type pair up when there is one on each side; among several,
  a pair that is alike and unique on both sides pairs up, likeness growing finer until the
  rest is one on each side: the same origin; then also a child link with the same inertial,
  visuals, collisions and number of child joints; then joint names that are one another
  with a prefix or suffix added (a tf_prefix, a namespace).

The rules repeat until nothing more pairs up, so a rename deep in the tree is found from
either end.
"""

from __future__ import annotations

import math
from collections import deque
from dataclasses import dataclass

from robotmodel.model import Joint, Pose, RobotDescription

__all__ = ["Matching", "match"]


@dataclass(frozen=True, slots=True)
class Matching:
    """Old name → new name for every link and joint present on both sides (renamed or not)."""

    links: dict[str, str]
    joints: dict[str, str]


class _Pairs:
    """A growing one-to-one old → new name map; each new pair is queued for the rules to follow up."""

    def __init__(self, old: list[str], new: list[str]) -> None:
        present = set(new)
        self.forward = {name: name for name in old if name in present}
        self.taken = set(self.forward.values())
        self.queue: deque[tuple[str, str]] = deque(self.forward.items())

    def pair(self, old: str, new: str) -> None:
        if old in self.forward or new in self.taken:
            return
        self.forward[old] = new
        self.taken.add(new)
        self.queue.append((old, new))


def _same_origin(a: Pose, b: Pose, tolerance: float) -> bool:
    return all(math.isclose(x, y, rel_tol=0.0, abs_tol=tolerance) for x, y in zip(a.xyz + a.rpy, b.xyz + b.rpy,
                                                                                   strict=True))


class _Matcher:
    """The rules of the module documentation, run from work queues.

    Each pair is followed up once (and a parent again when one of its joints pairs), so a
    whole renamed tree takes linear time, not one pass over the robot per level.
    """

    def __init__(self, old: RobotDescription, new: RobotDescription, tolerance: float) -> None:
        self.old, self.new, self.tolerance = old, new, tolerance
        self.links = _Pairs([x.name for x in old.links], [x.name for x in new.links])
        self.joints = _Pairs([x.name for x in old.joints], [x.name for x in new.joints])
        # Matched parents whose unmatched child joints the grouped rule should look at.
        self.parents: deque[tuple[str, str]] = deque()

    def run(self) -> Matching:
        while True:
            self._sure_rules()
            if self.links.queue or self.joints.queue:
                continue
            # Only once the tree said all it could: a root replaced by a new link above a renamed
            # one must not pair with it when the old root's children already told where it went.
            self.links.pair(self.old.root, self.new.root)
            if self.links.queue:
                continue
            if not self.parents:
                return Matching(self.links.forward, self.joints.forward)
            self._grouped_rule(*self.parents.popleft())

    def _sure_rules(self) -> None:
        old, new, links, joints = self.old, self.new, self.links, self.joints
        while links.queue or joints.queue:
            while joints.queue:
                old_joint, new_joint = joints.queue.popleft()
                a, b = old.joint(old_joint), new.joint(new_joint)
                links.pair(a.parent, b.parent)
                links.pair(a.child, b.child)
                # One child fewer to pair under this parent: the grouped rule may now decide there.
                parent = links.forward.get(a.parent)
                if parent is not None:
                    self.parents.append((a.parent, parent))
            while links.queue:
                old_link, new_link = links.queue.popleft()
                self.parents.append((old_link, new_link))
                edges = [old.parent_joint(old_link), *old.child_joints(old_link)]
                for joint in edges:
                    if joint is not None and joint.name not in joints.forward:
                        self._same_edge(joint)

    def _same_edge(self, joint: Joint) -> None:
        """A link has one parent joint: when both ends map, the edge is the same joint renamed."""
        child = self.links.forward.get(joint.child)
        parent = self.links.forward.get(joint.parent)
        if child is None or parent is None:
            return
        other = self.new.parent_joint(child)
        if other is not None and other.parent == parent and other.type is joint.type:
            self.joints.pair(joint.name, other.name)

    def _grouped_rule(self, old_parent: str, new_parent: str) -> None:
        links, joints = self.links, self.joints
        olds = [j for j in self.old.child_joints(old_parent)
                if j.name not in joints.forward and j.child not in links.forward]
        news = [j for j in self.new.child_joints(new_parent)
                if j.name not in joints.taken and j.child not in links.taken]
        for kind in sorted({j.type for j in olds}, key=lambda t: t.value):
            a = [j for j in olds if j.type is kind]
            b = [j for j in news if j.type is kind]
            for ja, jb in self._pair_up(a, b):
                joints.pair(ja.name, jb.name)
                links.pair(ja.child, jb.child)

    def _pair_up(self, a: list[Joint], b: list[Joint]) -> list[tuple[Joint, Joint]]:
        """Pairs among same-type sibling joints: one on each side, else by ever finer likeness."""
        pairs: list[tuple[Joint, Joint]] = []
        for alike in (self._same_origin, self._same_body, _same_stem):
            if len(a) == 1 and len(b) == 1:
                break
            for ja in list(a):
                same = [jb for jb in b if alike(ja, jb)]
                if len(same) == 1 and [jx for jx in a if alike(jx, same[0])] == [ja]:
                    pairs.append((ja, same[0]))
                    a.remove(ja)
                    b.remove(same[0])
        if len(a) == 1 and len(b) == 1:
            pairs.append((a[0], b[0]))
        return pairs

    def _same_origin(self, a: Joint, b: Joint) -> bool:
        return _same_origin(a.origin, b.origin, self.tolerance)

    def _same_body(self, a: Joint, b: Joint) -> bool:
        """Same origin, and a child link with the same inertial, shapes and number of child joints."""
        if not self._same_origin(a, b):
            return False
        la, lb = self.old.link(a.child), self.new.link(b.child)
        return (la.inertial, la.visuals, la.collisions, len(self.old.child_joints(a.child))) == (
            lb.inertial, lb.visuals, lb.collisions, len(self.new.child_joints(b.child)))


def _same_stem(a: Joint, b: Joint) -> bool:
    """One name is the other with a prefix or suffix added (a tf_prefix, a namespace, ``_v2``)."""
    short, long = sorted((a.name, b.name), key=len)
    return short != long and (long.startswith(short) or long.endswith(short))


def match(old: RobotDescription, new: RobotDescription, tolerance: float) -> Matching:
    """Pair the links and joints of ``old`` with those of ``new`` (see the module documentation)."""
    return _Matcher(old, new, tolerance).run()
