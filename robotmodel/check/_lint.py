"""Physical and referential lint of a robot description, beyond what urdfdom checks."""

from __future__ import annotations

import os
from collections.abc import Iterator, Sequence
from dataclasses import dataclass
from enum import Enum
from pathlib import Path

import numpy as np

from robotmodel.errors import RobotModelError
from robotmodel.model import Inertial, JointType, Mesh, RobotDescription
from robotmodel.resources import resolve_uri

__all__ = ["Finding", "Severity", "lint"]

# Inertia checks tolerate rounding in hand-written URDFs: relative to the largest moment.
_REL_TOL = 1e-9


class Severity(Enum):
    """How bad a finding is: errors fail the check, warnings only with ``--strict``."""

    ERROR = "error"
    WARNING = "warning"


@dataclass(frozen=True, slots=True)
class Finding:
    """One problem found: a stable ``code``, the element it is about, and a message."""

    code: str
    severity: Severity
    element: str
    message: str

    def __str__(self) -> str:
        return f"{self.severity.value}: [{self.code}] {self.element}: {self.message}"


def _body(desc: RobotDescription, link: str) -> list[str]:
    """``link`` and every link welded to it by fixed joints below it: one rigid body."""
    body = [link]
    stack = [link]
    while stack:
        for j in desc.child_joints(stack.pop()):
            if j.type is JointType.FIXED:
                body.append(j.child)
                stack.append(j.child)
    return body


def _mass_findings(desc: RobotDescription) -> Iterator[Finding]:
    for link in desc.links:
        inertial = link.inertial
        if inertial is None:
            continue
        if inertial.mass < 0.0:
            yield Finding("mass-not-positive", Severity.WARNING, f"link [{link.name}]",
                          f"mass is {inertial.mass:g}")
        elif inertial.mass > 0.0:
            yield from _inertia_findings(link.name, inertial)
    # A zero-mass frame welded to a massive link is normal (tool0, ee_link); a body that
    # a movable joint drives must weigh something, or dynamics divides by zero.
    for joint in desc.movable_joints:
        inertials = [i for n in _body(desc, joint.child) if (i := desc.link(n).inertial) is not None]
        if inertials and sum(i.mass for i in inertials) == 0.0:
            yield Finding("mass-not-positive", Severity.WARNING, f"link [{joint.child}]",
                          f"mass is 0 on a body moved by joint [{joint.name}]")


def _material_findings(desc: RobotDescription) -> Iterator[Finding]:
    # As urdfdom: a material given a colour or texture inside a visual becomes defined
    # for the links that come after it in the document.
    defined = {m.name for m in desc.materials}
    for link in desc.links:
        for visual in link.visuals:
            mat = visual.material
            if mat is None:
                continue
            if mat.color is not None or mat.texture is not None:
                defined.add(mat.name)
            elif mat.name not in defined:
                yield Finding("material-undefined", Severity.WARNING, f"link [{link.name}]",
                              f"material '{mat.name}' is used but never defined")


def _resolve_mesh(uri: str, base: Path, package_paths: Sequence[str | os.PathLike[str]]) -> Path:
    if uri.startswith("package:///"):
        # No package name: Pinocchio joins the rest to each package directory, and real
        # files rely on it (example-robot-data's talos_full_v2); search the file's parents.
        rest = uri[len("package:///"):]
        roots = [Path(p) for p in package_paths] + [base, *base.parents]
        for root in roots:
            if (root / rest).is_file():
                return root / rest
        return base / rest
    return resolve_uri(uri, base_dir=base, package_paths=package_paths)


def _inertia_findings(name: str, inertial: Inertial) -> Iterator[Finding]:
    i = inertial.inertia
    tensor = np.array([[i.ixx, i.ixy, i.ixz], [i.ixy, i.iyy, i.iyz], [i.ixz, i.iyz, i.izz]])
    moments = np.linalg.eigvalsh(tensor)
    element = f"link [{name}]"
    if moments.min() <= 0.0:
        yield Finding("inertia-not-positive-definite", Severity.WARNING, element,
                      f"inertia is not positive definite (principal moments {np.array2string(moments)})")
        return
    a, b, c = sorted(float(m) for m in moments)
    if a + b < c * (1.0 - _REL_TOL):
        yield Finding("inertia-triangle-inequality", Severity.WARNING, element,
                      f"principal moments {a:.6g}, {b:.6g}, {c:.6g} violate the triangle inequality "
                      "(no rigid body has them)")


def _mesh_uris(desc: RobotDescription) -> Iterator[tuple[str, str]]:
    for link in desc.links:
        for geometry in [v.geometry for v in link.visuals] + [c.geometry for c in link.collisions]:
            if isinstance(geometry, Mesh):
                yield link.name, geometry.filename


def lint(
    desc: RobotDescription,
    *,
    base_dir: str | os.PathLike[str] | None = None,
    package_paths: Sequence[str | os.PathLike[str]] = (),
) -> list[Finding]:
    """All lint findings for ``desc``; mesh URIs resolve against ``base_dir`` and ``package_paths``."""
    findings: list[Finding] = []
    joint_names = {j.name for j in desc.joints}
    for joint in desc.joints:
        element = f"joint [{joint.name}]"
        if joint.mimic is not None and joint.mimic.joint not in joint_names:
            findings.append(Finding("mimic-missing-joint", Severity.ERROR, element,
                                    f"mimics joint [{joint.mimic.joint}], which does not exist"))
        limit = joint.limit
        if limit is None or joint.type not in (JointType.REVOLUTE, JointType.PRISMATIC, JointType.CONTINUOUS):
            continue
        # A continuous joint has no position limits, whatever its <limit> says.
        if (joint.type is not JointType.CONTINUOUS and limit.lower is not None and limit.upper is not None
                and limit.lower > limit.upper):
            findings.append(Finding("limit-lower-above-upper", Severity.WARNING, element,
                                    f"lower limit {limit.lower:g} is above upper limit {limit.upper:g}"))
        if limit.effort <= 0.0:
            findings.append(Finding("limit-zero-effort", Severity.WARNING, element,
                                    f"effort limit is {limit.effort:g}; the joint cannot be driven"))
        if limit.velocity <= 0.0:
            findings.append(Finding("limit-zero-velocity", Severity.WARNING, element,
                                    f"velocity limit is {limit.velocity:g}; the joint cannot move"))
    findings.extend(_mass_findings(desc))
    findings.extend(_massless_moving_bodies(desc))
    findings.extend(_material_findings(desc))
    base = Path(base_dir) if base_dir is not None else Path.cwd()
    resolved: dict[str, str | None] = {}
    for link_name, uri in _mesh_uris(desc):
        if uri not in resolved:
            resolved[uri] = _mesh_problem(uri, base, package_paths)
        problem = resolved[uri]
        if problem is not None:
            findings.append(Finding("mesh-not-found", Severity.WARNING, f"link [{link_name}]", problem))
    return findings


def _mesh_problem(uri: str, base: Path, package_paths: Sequence[str | os.PathLike[str]]) -> str | None:
    """Why the mesh ``uri`` cannot be read, or None when it resolves to a file."""
    try:
        path = _resolve_mesh(uri, base, package_paths)
    except RobotModelError as exc:
        return f"mesh '{uri}' does not resolve: {exc}"
    except (OSError, ValueError) as exc:
        # A name too long, a NUL byte, a denied directory: the filesystem's answer is the finding.
        return f"mesh '{uri}' does not resolve: {exc.strerror if isinstance(exc, OSError) else exc}"
    try:
        if path.is_file():
            return None
    except (OSError, ValueError) as exc:
        reason = exc.strerror if isinstance(exc, OSError) else exc
        return f"mesh '{uri}' resolves to {path}, which cannot be read: {reason}"
    return f"mesh '{uri}' resolves to {path}, which does not exist"


def _massless_moving_bodies(desc: RobotDescription) -> Iterator[Finding]:
    """A movable joint must move some mass: its child plus everything fixed to it."""
    for joint in desc.movable_joints:
        if all(desc.link(n).inertial is None for n in _body(desc, joint.child)):
            yield Finding("moving-link-without-inertial", Severity.WARNING, f"link [{joint.child}]",
                          f"moves with joint [{joint.name}] but neither it nor anything fixed to it "
                          "has an <inertial>")
