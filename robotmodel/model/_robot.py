"""The whole robot: its links, joints and materials, validated on construction."""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import cached_property

from robotmodel.errors import UnknownJointError, UnknownLinkError, URDFError
from robotmodel.model._types import Joint, Link, Material
from robotmodel.model._validate import validate_description

__all__ = ["RobotDescription"]


@dataclass(frozen=True)
class RobotDescription:
    """A whole robot: links, joints and named materials, in document order.

    The typed fields are the single source of truth: every engine is built from them
    (Pinocchio through :func:`robotmodel.model.to_urdf`), so a description changed with
    :func:`dataclasses.replace` is what every engine sees. Construction validates the
    robot with the same checks and messages as :func:`robotmodel.model.parse_urdf`
    (one tree, unique names, limits, finite numbers, no mimic cycles), raising
    :class:`robotmodel.errors.URDFError`.

    Provenance only, never read by any engine: ``source`` is the file the description came
    from, ``source_text`` the URDF XML it was parsed from (after xacro expansion). Only
    :func:`~robotmodel.model.parse_urdf` sets ``source_text``; a description built or
    changed (``dataclasses.replace``) in Python has none.
    """

    name: str
    links: tuple[Link, ...]
    joints: tuple[Joint, ...]
    materials: tuple[Material, ...] = ()
    source: str | None = field(default=None, compare=False)
    # Not an __init__ argument, so dataclasses.replace leaves it empty: a changed robot has
    # no source text (publishers then send to_urdf of it), never its original's stale one.
    source_text: str = field(default="", init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        validate_description(self.name, self.links, self.joints, self.materials)

    @cached_property
    def _links(self) -> dict[str, Link]:
        return {link.name: link for link in self.links}

    @cached_property
    def _joints(self) -> dict[str, Joint]:
        return {joint.name: joint for joint in self.joints}

    @cached_property
    def _parent_joints(self) -> dict[str, Joint]:
        return {joint.child: joint for joint in self.joints}

    @cached_property
    def _child_joints(self) -> dict[str, tuple[Joint, ...]]:
        grouped: dict[str, list[Joint]] = {}
        for joint in self.joints:
            grouped.setdefault(joint.parent, []).append(joint)
        # urdfdom keeps joints in a map keyed by name, so children come in joint-name order.
        return {k: tuple(sorted(v, key=lambda j: j.name)) for k, v in grouped.items()}

    @cached_property
    def root(self) -> str:
        """The root link: the one link that is no joint's child."""
        roots = sorted(name for name in self._links if name not in self._parent_joints)
        return roots[0]

    def link(self, name: str) -> Link:
        """The link called ``name`` (:class:`~robotmodel.errors.UnknownLinkError` otherwise)."""
        try:
            return self._links[name]
        except KeyError:
            raise UnknownLinkError(self.name, name) from None

    def joint(self, name: str) -> Joint:
        """The joint called ``name`` (:class:`~robotmodel.errors.UnknownJointError` otherwise)."""
        try:
            return self._joints[name]
        except KeyError:
            raise UnknownJointError(f"robot '{self.name}' has no joint '{name}'", name) from None

    def child_joints(self, link: str) -> tuple[Joint, ...]:
        """Joints whose parent is ``link``, in joint-name order (as urdfdom lists them)."""
        return self._child_joints.get(link, ())

    def parent_joint(self, link: str) -> Joint | None:
        """The joint whose child is ``link``; None for the root."""
        return self._parent_joints.get(link)

    @property
    def movable_joints(self) -> tuple[Joint, ...]:
        """Joints with a degree of freedom, in document order."""
        return tuple(j for j in self.joints if j.type.is_movable)

    def walk(self) -> list[tuple[int, Joint]]:
        """Depth-first pre-order (depth, joint) pairs from the root, children in joint-name order."""
        order: list[tuple[int, Joint]] = []
        stack = [(1, j) for j in reversed(self.child_joints(self.root))]
        while stack:
            depth, joint = stack.pop()
            order.append((depth, joint))
            if len(order) > len(self.joints):
                # Construction proved a tree; only a description mutated behind the frozen
                # dataclass's back gets here, and it must not loop.
                raise URDFError(f"robot '{self.name}': the joints do not form a tree")
            stack.extend((depth + 1, j) for j in reversed(self.child_joints(joint.child)))
        return order
