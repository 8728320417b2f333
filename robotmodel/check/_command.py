"""``robotmodel check-urdf`` (alias ``check_urdf``): urdfdom's check_urdf, plus lint, for one file or many."""

from __future__ import annotations

import argparse
import json
import os
import sys
from typing import TYPE_CHECKING, Any

from robotmodel.cli._common import add_mapping_arguments, add_model_options

if TYPE_CHECKING:
    from collections.abc import Iterator, Sequence

    from robotmodel.check import CheckJob, FileReport, ProjectConfig

FORMATS = ("text", "json", "github", "sarif")


def register(sub: Any) -> None:
    """Add the ``check-urdf`` subcommand."""
    parser: argparse.ArgumentParser = sub.add_parser(
        "check-urdf", aliases=["check_urdf"],
        help="parse and check URDF/xacro files; prints the tree as urdfdom's check_urdf does",
        description="Check URDF (or xacro) files ('-' reads stdin). For one file, on success stdout is "
        "exactly check_urdf's and lint warnings follow on stderr; on failure stdout is empty, one line per "
        "problem goes to stderr and the exit code is 1 (urdfdom exits 255). Beyond urdfdom it rejects "
        "partial cycles, links with two parents, self-joints, zero axes, NaN/inf and mimics of "
        "missing joints. Several files (and globs, ** included) are checked in parallel and end with a "
        "summary line on stderr; the exit code is 1 if any fails. A robotmodel.toml or [tool.robotmodel] "
        "in pyproject.toml names entry points and their xacro args; macro-only xacro files are checked "
        "through the entries that include them, and without FILE every entry is checked.",
    )
    add_mapping_arguments(parser)
    parser.add_argument("files", metavar="FILE", nargs="*",
                        help="a .urdf or .xacro file or glob ('-' reads stdin)")
    add_model_options(parser)
    parser.add_argument("--strict", action="store_true", help="treat lint warnings as errors")
    parser.add_argument(
        "--format", choices=FORMATS, default="text",
        help="json: robot, root, tree and findings (with codes and places); github: workflow commands "
        "(annotations on the pull request); sarif: a SARIF 2.1.0 log for code scanning",
    )
    parser.add_argument("--config", metavar="PATH",
                        help="the project config (default: robotmodel.toml or a pyproject.toml with "
                        "[tool.robotmodel], searched upward from the working directory)")
    parser.add_argument("--no-config", action="store_true", help="ignore any project config")
    parser.add_argument("-j", "--jobs", type=int, default=0, metavar="N",
                        help="check N files at once (default: one per CPU core)")
    # Kept so errors found after parsing (no FILE, '-' among files) print this command's usage too.
    parser.set_defaults(func=run, parser=parser)


def _config(args: argparse.Namespace) -> ProjectConfig | None:
    from robotmodel.check import find_config, read_config

    if args.no_config:
        return None
    if args.config:
        return read_config(args.config)
    return find_config()


def _stdin_report(args: argparse.Namespace) -> FileReport:
    """The old single-document path: stdin parsed in-process, relative paths from the working directory."""
    from robotmodel.cli._common import load_description

    from robotmodel.check import (
        CheckJob,
        FileReport,
        Finding,
        LocatedFinding,
        Location,
        Severity,
        TreeRow,
        error_code,
        lint,
        tree_report,
    )
    from robotmodel.errors import RobotModelError

    job = CheckJob("-", strict=args.strict)
    args.file = "-"
    here = Location("-", None)
    try:
        desc, base_dir = load_description(args)
    except RobotModelError as exc:
        message = " ".join(str(exc).splitlines())
        return FileReport(job, (LocatedFinding(Finding(error_code(exc), Severity.ERROR, "-", message), here),),
                          error=message)
    findings = lint(desc, base_dir=base_dir, package_paths=args.package_path)
    if args.strict:
        findings = [Finding(f.code, Severity.ERROR, f.element, f.message) for f in findings]
    return FileReport(job, tuple(LocatedFinding(f, here) for f in findings), robot=desc.name, root=desc.root,
                      links=len(desc.links), joints=len(desc.joints),
                      tree=tuple(TreeRow(d, j.name, j.type.value, j.parent, j.child) for d, j in desc.walk()),
                      tree_text=tree_report(desc))


def _workers(args: argparse.Namespace, n: int) -> int:
    return max(1, min(n, args.jobs if args.jobs > 0 else (os.cpu_count() or 1)))


def _includes_of(job: CheckJob) -> list[str] | None:
    """The files ``job``'s document includes; None when it does not expand (so what it includes is unknown)."""
    from robotmodel.errors import RobotModelError
    from robotmodel.xacro import dependencies

    try:
        return dependencies(job.file, dict(job.args), package_paths=job.package_paths, untrusted=job.untrusted)
    except RobotModelError:
        return None


def _map(func: Any, jobs: Sequence[CheckJob], workers: int) -> Iterator[Any]:
    """``func`` over ``jobs`` in order; in a process pool when there is more than one to run.

    Processes, not threads: lint and parsing hold the GIL, and each xacro expansion is a child
    process already. Results come back in input order, so output never interleaves.
    """
    if workers <= 1 or len(jobs) <= 1:
        yield from map(func, jobs)
        return
    from concurrent.futures import ProcessPoolExecutor

    with ProcessPoolExecutor(max_workers=workers) as pool:
        yield from pool.map(func, jobs)


def _orphan(file: str, strict: bool) -> FileReport:
    from robotmodel.check import CheckJob, FileReport, Finding, LocatedFinding, Location, Severity, display_path

    severity = Severity.ERROR if strict else Severity.WARNING
    finding = Finding("fragment-not-checked", severity, file,
                      "macro-only xacro file included by no configured entry point; not checked on its own")
    return FileReport(CheckJob(file), (LocatedFinding(finding, Location(display_path(file), None)),),
                      robot="", tree_text="")


def run(args: argparse.Namespace) -> int:
    """Check the files; exit 0 when all are valid (and, with --strict, warning-free)."""
    from robotmodel.cli._check_plan import expand_files, plan_checks
    from robotmodel.cli._common import apply_verbose

    from robotmodel.check import CheckJob, check_file

    apply_verbose(args)
    if args.files == ["-"]:
        reports = iter([_stdin_report(args)])
        return _emit(args, reports, [], many=False)
    if "-" in args.files:
        args.parser.error("'-' (stdin) cannot be combined with other files")
    config = _config(args)
    if not args.files and (config is None or not config.entries):
        args.parser.error("the following arguments are required: FILE")
    package_paths = [*args.package_path, *((str(p) for p in config.package_paths) if config else ())]
    base = CheckJob("", package_paths=tuple(package_paths), untrusted=args.untrusted, strict=args.strict,
                    locate=args.format != "text")
    files = expand_files(args.files)
    jobs, orphans = plan_checks(
        files, base, args.mappings, config,
        lambda entry_jobs: list(_map(_includes_of, entry_jobs, _workers(args, len(entry_jobs)))))
    unchecked = [_orphan(f, args.strict) for f in orphans]
    # One FILE checked once prints exactly what check-urdf always printed for it (no summary).
    many = not (len(jobs) == 1 and not unchecked and len(args.files) == 1)
    return _emit(args, _map(check_file, jobs, _workers(args, len(jobs))), unchecked, many=many)


def _emit(args: argparse.Namespace, reports: Iterator[FileReport], unchecked: list[FileReport], *,
          many: bool) -> int:
    from robotmodel.cli._check_output import json_object, summary, text_lines

    done: list[FileReport] = []
    if args.format == "text":
        for report in reports:
            done.append(report)
            if report.ok:  # as check_urdf: the tree only for a robot that passes
                sys.stdout.write(report.tree_text)
                sys.stdout.flush()
            for line in text_lines(report, args.command, many=many):
                print(line, file=sys.stderr)
        for report in unchecked:
            for line in text_lines(report, args.command, many=True):
                print(line, file=sys.stderr)
    else:
        done = list(reports)
        every = [*done, *unchecked]
        if args.format == "json":
            if many:
                obj: Any = {"ok": all(r.ok for r in every), "files": [json_object(r, many=True) for r in every],
                            "summary": summary(done, unchecked)}
            else:
                obj = json_object(every[0], many=False)
            print(json.dumps(obj, indent=2))
        elif args.format == "github":
            from robotmodel.check import workflow_command

            for report in every:
                for item in report.findings:
                    print(workflow_command(item.finding, item.location))
        else:
            from importlib.metadata import version

            from robotmodel.check import to_sarif

            log = to_sarif(((i.finding, i.location) for r in every for i in r.findings), version=version("robotmodel"))
            print(json.dumps(log, indent=2))
        sys.stdout.flush()
    if many or args.format in ("github", "sarif"):
        print(f"robotmodel {args.command}: {summary(done, unchecked)}", file=sys.stderr)
    return 0 if all(r.ok for r in [*done, *unchecked]) else 1
