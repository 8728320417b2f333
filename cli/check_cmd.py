"""``robotmodel check-urdf`` (alias ``check_urdf``): urdfdom's check_urdf, plus lint."""

from __future__ import annotations

import argparse
import json
import sys
from typing import TYPE_CHECKING, Any

from robotmodel.cli._common import add_model_arguments, load_description

from robotmodel.errors import RobotModelError

if TYPE_CHECKING:
    from robotmodel.check import Finding


def register(sub: Any) -> None:
    """Add the ``check-urdf`` subcommand."""
    parser: argparse.ArgumentParser = sub.add_parser(
        "check-urdf", aliases=["check_urdf"],
        help="parse and check a URDF/xacro; prints the tree as urdfdom's check_urdf does",
        description="Check a URDF (or xacro) file ('-' reads stdin). On success stdout is exactly "
        "check_urdf's and lint warnings follow on stderr; on failure stdout is empty, one line per "
        "problem goes to stderr and the exit code is 1 (urdfdom exits 255). Beyond urdfdom it rejects "
        "partial cycles, links with two parents, self-joints, zero axes, NaN/inf and mimics of "
        "missing joints.",
    )
    add_model_arguments(parser)
    parser.add_argument("--strict", action="store_true", help="treat lint warnings as errors")
    parser.add_argument("--format", choices=("text", "json"), default="text",
                        help="json: robot, root, tree and findings (with codes) on stdout")
    parser.set_defaults(func=run)


def _finding_json(f: Finding) -> dict[str, str]:
    return {"code": f.code, "severity": f.severity.value, "element": f.element, "message": f.message}


def run(args: argparse.Namespace) -> int:
    """Check the file; exit 0 when valid (and, with --strict, warning-free)."""
    from robotmodel.check import Finding, Severity, lint, tree_report

    try:
        desc, base_dir = load_description(args)
    except RobotModelError as exc:
        if args.format != "json":
            raise
        print(json.dumps({"ok": False, "error": " ".join(str(exc).splitlines())}, indent=2))
        return 1
    findings = lint(desc, base_dir=base_dir, package_paths=args.package_path)
    if args.strict:
        findings = [Finding(f.code, Severity.ERROR, f.element, f.message) for f in findings]
    failed = any(f.severity is Severity.ERROR for f in findings)
    if args.format == "json":
        report = {
            "ok": not failed,
            "robot": desc.name,
            "root": desc.root,
            "links": len(desc.links),
            "joints": len(desc.joints),
            "tree": [
                {"depth": depth, "joint": j.name, "type": j.type.value, "parent": j.parent, "child": j.child}
                for depth, j in desc.walk()
            ],
            "findings": [_finding_json(f) for f in findings],
        }
        print(json.dumps(report, indent=2))
        return 1 if failed else 0
    # As check_urdf: the tree goes to stdout only when the check passes.
    if not failed:
        sys.stdout.write(tree_report(desc))
        sys.stdout.flush()
    for finding in findings:
        print(f"robotmodel {args.command}: {finding}", file=sys.stderr)
    return 1 if failed else 0
