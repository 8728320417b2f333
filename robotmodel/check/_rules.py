"""What each finding code means: the rule table behind SARIF's ``rules`` and the docs.

Lint codes come from :func:`robotmodel.check.lint`; the load codes name why a file could not
be checked at all (its XML, its robot, its xacro expansion, a package it needs).
"""

from __future__ import annotations

from dataclasses import dataclass

from robotmodel.check._lint import Severity
from robotmodel.errors import (
    PackageNotFoundError,
    ResourceError,
    RobotModelError,
    UntrustedInputError,
    URDFError,
    URDFParseError,
    XacroError,
)

__all__ = ["RULES", "Rule", "error_code"]


@dataclass(frozen=True, slots=True)
class Rule:
    """One finding code: a one-line summary, the help text, and how bad it is unless ``--strict``."""

    code: str
    summary: str
    help: str
    severity: Severity


def _rules(*rules: Rule) -> dict[str, Rule]:
    return {r.code: r for r in rules}


_E, _W = Severity.ERROR, Severity.WARNING

#: Every code a check can report, by code.
RULES: dict[str, Rule] = _rules(
    Rule("urdf-malformed", "The file is not well-formed XML or holds a malformed URDF element", (
        "urdfdom rejects the file before building a model: fix the XML, or the element the message names "
        "(a missing attribute, a number that does not parse)."), _E),
    Rule("urdf-invalid", "The robot is not a valid URDF tree", (
        "urdfdom rejects the model: duplicate names, joints naming missing links, no or several roots, "
        "cycles, links with two parents. The message names the element."), _E),
    Rule("xacro-error", "xacro expansion failed", (
        "The xacro document did not expand: an undefined property or macro, a missing argument "
        "(give it as name:=value or in the project config), a bad include. The message says where."), _E),
    Rule("xacro-untrusted", "An untrusted document reached outside its package", (
        "With --untrusted, $(env), $(optenv) and files outside the input's package roots are refused."), _E),
    Rule("resource-not-found", "A ROS package or file the document names cannot be found", (
        "$(find pkg) or package://pkg names a package that is not on --package-path, ROS_PACKAGE_PATH, "
        "AMENT_PREFIX_PATH or beside the file."), _E),
    Rule("mimic-missing-joint", "A joint mimics a joint that does not exist", (
        "<mimic joint=...> must name a joint of the same robot; kinematics cannot follow it otherwise."), _E),
    Rule("limit-lower-above-upper", "A joint's lower limit is above its upper limit", (
        "No position satisfies the limits; swap them or fix the sign."), _W),
    Rule("limit-zero-effort", "A joint's effort limit is not positive", (
        "A controller cannot drive a joint whose effort limit is zero or negative."), _W),
    Rule("limit-zero-velocity", "A joint's velocity limit is not positive", (
        "A joint whose velocity limit is zero or negative cannot move under a controller that honours it."),
        _W),
    Rule("mass-not-positive", "A link's mass is negative, or a moving body weighs nothing", (
        "Masses must be positive; a body a movable joint drives (its child plus everything fixed to it) "
        "must have mass, or dynamics divides by zero."), _W),
    Rule("inertia-not-positive-definite", "A link's inertia tensor is not positive definite", (
        "Every principal moment of inertia must be positive; check the signs and the units of ixx..izz."),
        _W),
    Rule("inertia-triangle-inequality", "A link's principal moments violate the triangle inequality", (
        "For any rigid body each principal moment is at most the sum of the other two; values that break "
        "this are usually a typo or a wrong unit."), _W),
    Rule("material-undefined", "A visual uses a material that is never defined", (
        "Define the material at the top level (with a colour or texture) before the link that uses it, "
        "or give the colour inline."), _W),
    Rule("mesh-not-found", "A mesh file does not resolve to a readable file", (
        "The mesh URI (package://, file:// or a relative path) must name an existing file; pass "
        "--package-path for packages outside the workspace."), _W),
    Rule("moving-link-without-inertial", "A link moved by a joint has no inertial anywhere in its body", (
        "The child of a movable joint, or a link fixed to it, needs an <inertial> for dynamics and "
        "simulators."), _W),
    Rule("fragment-not-checked", "A macro-only xacro file is included by no configured entry point", (
        "A xacro file holding only macros and properties is checked through the robots that include it. "
        "List those in [tool.robotmodel] of pyproject.toml or in robotmodel.toml (see the README)."),
        Severity.WARNING),
)


def error_code(exc: RobotModelError) -> str:
    """The rule code for an error that stopped a file from being checked."""
    if isinstance(exc, URDFParseError):
        return "urdf-malformed"
    if isinstance(exc, URDFError):
        return "urdf-invalid"
    if isinstance(exc, UntrustedInputError):
        return "xacro-untrusted"
    if isinstance(exc, PackageNotFoundError | ResourceError):
        return "resource-not-found"
    if isinstance(exc, XacroError):
        return "xacro-error"
    return "urdf-invalid"
