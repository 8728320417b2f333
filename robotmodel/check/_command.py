"""``check-urdf FILE...`` as a program: configs, globs and fragments planned, checks run in parallel, four formats.

:func:`run_check` takes a :class:`CheckOptions` (the command's options by name) and returns
the exit code: 0 when every check passes (and, with ``strict``, warning-free). Output is
check_urdf's for one file; see :mod:`robotmodel.check._output` for the formats and
:mod:`robotmodel.check._plan` for which checks run.
"""

from __future__ import annotations

import json
import os
import sys
from collections.abc import Callable, Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, NoReturn

if TYPE_CHECKING:
    from robotmodel.check._project import ProjectConfig
    from robotmodel.check._run import CheckJob, FileReport

__all__ = ["FORMATS", "CheckOptions", "run_check"]

FORMATS = ("text", "json", "github", "sarif")


@dataclass
class CheckOptions:
    """What ``check-urdf`` is asked for; field names are its options'. ``command`` names it in messages."""

    files: Sequence[str] = ()
    mappings: Mapping[str, str] = field(default_factory=dict)
    package_path: Sequence[str] = ()
    untrusted: bool = False
    strict: bool = False
    format: str = "text"
    config: str | None = None
    no_config: bool = False
    jobs: int = 0
    command: str = "check-urdf"


def _usage_error(message: str) -> NoReturn:
    from robotmodel.errors import RobotModelError

    raise RobotModelError(message)


def _config(args: CheckOptions) -> ProjectConfig | None:
    from robotmodel.check._project import find_config, read_config

    if args.no_config:
        return None
    if args.config:
        return read_config(args.config)
    return find_config()


def _stdin_report(args: CheckOptions) -> FileReport:
    """The old single-document path: stdin parsed in-process, relative paths from the working directory."""
    from robotmodel.check._lint import Finding, Severity, lint
    from robotmodel.check._locations import Location
    from robotmodel.check._report import tree_report
    from robotmodel.check._rules import error_code
    from robotmodel.check._run import CheckJob, FileReport, LocatedFinding, TreeRow
    from robotmodel.errors import RobotModelError
    from robotmodel.model import load_source

    job = CheckJob("-", strict=args.strict)
    here = Location("-", None)
    try:
        desc, base_dir = load_source("-", args.mappings, package_paths=args.package_path, untrusted=args.untrusted)
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


def _workers(args: CheckOptions, n: int) -> int:
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
    from robotmodel.check._lint import Finding, Severity
    from robotmodel.check._locations import Location, display_path
    from robotmodel.check._run import CheckJob, FileReport, LocatedFinding

    severity = Severity.ERROR if strict else Severity.WARNING
    finding = Finding("fragment-not-checked", severity, file,
                      "macro-only xacro file included by no configured entry point; not checked on its own")
    return FileReport(CheckJob(file), (LocatedFinding(finding, Location(display_path(file), None)),),
                      robot="", tree_text="")


def run_check(args: CheckOptions, usage_error: Callable[[str], NoReturn] = _usage_error) -> int:
    """Check the files; returns 0 when all are valid (and, with ``strict``, warning-free), else 1.

    ``usage_error`` hears of a bad command line ('-' among other files; no FILE and no
    configured entry) and must not return (the command prints its usage and exits 2).
    """
    from robotmodel.check._plan import expand_files, plan_checks
    from robotmodel.check._run import CheckJob, check_file

    if list(args.files) == ["-"]:
        reports = iter([_stdin_report(args)])
        return _emit(args, reports, [], many=False)
    if "-" in args.files:
        usage_error("'-' (stdin) cannot be combined with other files")
    config = _config(args)
    if not args.files and (config is None or not config.entries):
        usage_error("the following arguments are required: FILE")
    package_paths = [*args.package_path, *((str(p) for p in config.package_paths) if config else ())]
    base = CheckJob("", package_paths=tuple(package_paths), untrusted=args.untrusted, strict=args.strict,
                    locate=args.format != "text")
    files = expand_files(args.files)
    jobs, orphans = plan_checks(
        files, base, args.mappings, config,
        lambda entry_jobs: list(_map(_includes_of, entry_jobs, _workers(args, len(entry_jobs)))))
    unchecked = [_orphan(f, args.strict) for f in orphans]
    # One FILE checked once prints exactly what check-urdf always printed for it (no summary).
    many = not (len(jobs) == 1 and not unchecked and len(list(args.files)) == 1)
    return _emit(args, _map(check_file, jobs, _workers(args, len(jobs))), unchecked, many=many)


def _emit(args: CheckOptions, reports: Iterator[FileReport], unchecked: list[FileReport], *,
          many: bool) -> int:
    from robotmodel.check._output import json_object, summary, text_lines

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
            from robotmodel.check._github import workflow_command

            for report in every:
                for item in report.findings:
                    print(workflow_command(item.finding, item.location))
        else:
            from importlib.metadata import version

            from robotmodel.check._sarif import to_sarif

            log = to_sarif(((i.finding, i.location) for r in every for i in r.findings), version=version("robotmodel"))
            print(json.dumps(log, indent=2))
        sys.stdout.flush()
    if many or args.format in ("github", "sarif"):
        print(f"robotmodel {args.command}: {summary(done, unchecked)}", file=sys.stderr)
    return 0 if all(r.ok for r in [*done, *unchecked]) else 1
