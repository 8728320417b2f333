"""Tree validation: the robot must be one tree of links joined by joints."""

from __future__ import annotations

from collections.abc import Sequence

from robotmodel.errors import URDFError
from robotmodel.model._types import Joint

__all__ = ["validate_tree"]


def validate_tree(links: Sequence[str], joints: Sequence[Joint]) -> str:
    """Check that ``joints`` join ``links`` into one tree; return the root link's name.

    Joints are visited in name order, as urdfdom does, so the first error reported is
    the one ``check_urdf`` would report.
    """
    names = set(links)
    parent_joint: dict[str, Joint] = {}
    by_name = {j.name: j for j in joints}
    for joint in sorted(joints, key=lambda j: j.name):
        if joint.parent not in names:
            raise URDFError(
                f"Failed to build tree: parent link [{joint.parent}] of joint [{joint.name}] not found.  "
                "This is not valid according to the URDF spec. Every link you refer to from a joint needs "
                f"to be explicitly defined in the robot description. To fix this problem you can either "
                f"remove this joint [{joint.name}] from your urdf file, or add "
                f'"<link name="{joint.parent}" />" to your urdf file.'
            )
        if joint.child not in names:
            raise URDFError(
                f"Failed to build tree: child link [{joint.child}] of joint [{joint.name}] not found"
            )
        if joint.parent == joint.child:
            raise URDFError(
                f"joint [{joint.name}] has link [{joint.child}] as both its parent and its child"
            )
        if joint.child in parent_joint:
            raise URDFError(
                f"link [{joint.child}] has two parent joints, [{parent_joint[joint.child].name}] and "
                f"[{joint.name}]; a URDF must be a tree"
            )
        parent_joint[joint.child] = joint
    roots = sorted(n for n in names if n not in parent_joint)
    if len(roots) > 1:
        raise URDFError(f"Failed to find root link: Two root links found: [{roots[0]}] and [{roots[1]}]")
    if not roots:
        raise URDFError("Failed to find root link: No root link found. The robot xml is not a valid tree.")
    root = roots[0]
    children: dict[str, list[str]] = {}
    for joint in joints:
        children.setdefault(joint.parent, []).append(joint.child)
    seen = {root}
    stack = [root]
    while stack:
        for child in children.get(stack.pop(), ()):
            if child not in seen:
                seen.add(child)
                stack.append(child)
    cut_off = sorted(names - seen)
    if cut_off:
        raise URDFError(
            f"links [{', '.join(cut_off)}] form a cycle that is not connected to root link [{root}]"
        )
    _check_mimics(joints, by_name)
    return root


def _check_mimics(joints: Sequence[Joint], by_name: dict[str, Joint]) -> None:
    """Reject mimic cycles; each joint is walked once (chains end in joints known to be fine)."""
    acyclic: set[str] = set()
    for joint in joints:
        path: list[str] = []
        on_path: set[str] = set()
        current: Joint | None = joint
        while current is not None and current.name not in acyclic:
            if current.name in on_path:
                raise URDFError(f"mimic joints form a cycle: {' -> '.join([*path, current.name])}")
            path.append(current.name)
            on_path.add(current.name)
            mimic = current.mimic
            # A mimic of a missing joint is loadable (urdfdom, RSP and real robots such as
            # alex_psyonic_hands accept it); check_urdf reports it, see robotmodel.check.
            current = by_name.get(mimic.joint) if mimic is not None else None
        acyclic.update(path)
