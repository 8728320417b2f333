"""``robotmodel check-urdf`` (alias ``check_urdf``): urdfdom's check_urdf, plus lint."""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path
from typing import Any

from robotmodel.cli._common import add_model_arguments, split_mappings

from robotmodel.check import Severity, lint, tree_report
from robotmodel.model import load


def register(sub: Any) -> None:
    """Add the ``check-urdf`` subcommand."""
    parser: argparse.ArgumentParser = sub.add_parser(
        "check-urdf", aliases=["check_urdf"],
        help="parse and check a URDF/xacro; prints the tree as urdfdom's check_urdf does",
        description="Check a URDF (or xacro) file. On success stdout is exactly check_urdf's; "
        "lint warnings follow on stderr.",
    )
    add_model_arguments(parser)
    parser.add_argument("--strict", action="store_true", help="treat lint warnings as errors")
    parser.add_argument("--format", choices=("text", "json"), default="text", help="output format")
    parser.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    """Check the file; exit 0 when valid (and, with --strict, warning-free)."""
    mappings = split_mappings(args.mappings)
    if args.file == "-":
        desc = load(sys.stdin.read(), mappings, package_paths=args.package_path, untrusted=args.untrusted)
        base_dir = Path.cwd()
    else:
        desc = load(args.file, mappings, package_paths=args.package_path, untrusted=args.untrusted)
        base_dir = Path(args.file).resolve().parent
    findings = lint(desc, base_dir=base_dir, package_paths=args.package_path)
    failed = any(f.severity is Severity.ERROR for f in findings) or (args.strict and bool(findings))
    if args.format == "json":
        report = {
            "robot": desc.name,
            "root": desc.root,
            "links": len(desc.links),
            "joints": len(desc.joints),
            "tree": [
                {"depth": depth, "joint": j.name, "type": j.type.value, "parent": j.parent, "child": j.child}
                for depth, j in desc.walk()
            ],
            "findings": [
                {"code": f.code, "severity": f.severity.value, "element": f.element, "message": f.message}
                for f in findings
            ],
            "ok": not failed,
        }
        print(json.dumps(report, indent=2))
    else:
        sys.stdout.write(tree_report(desc))
        sys.stdout.flush()
        for finding in findings:
            print(finding, file=sys.stderr)
    return 1 if failed else 0
