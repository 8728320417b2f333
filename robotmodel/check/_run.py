"""Check one file end to end (load, lint, place findings) into a picklable :class:`FileReport`.

A report carries everything every output format needs, so files can be checked in worker
processes and printed, in order, by the parent.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path

from robotmodel.check._lint import Finding, Severity, lint
from robotmodel.check._locations import Location, SourceIndex, display_path, element_of, error_location
from robotmodel.check._report import tree_report
from robotmodel.check._rules import error_code
from robotmodel.errors import RobotModelError
from robotmodel.model import load

__all__ = ["CheckJob", "FileReport", "LocatedFinding", "TreeRow", "check_file", "job_args"]


@dataclass(frozen=True, slots=True)
class CheckJob:
    """One check to run: a file (``-`` is not accepted here), its xacro args and the load options."""

    file: str
    args: tuple[tuple[str, str], ...] = ()
    package_paths: tuple[str, ...] = ()
    untrusted: bool = False
    strict: bool = False
    #: Look up each finding's file and line (costs a xacro ``--deps`` run for some xacro files).
    locate: bool = True
    #: Set when the file was checked on behalf of a macro-only file it includes.
    via: str | None = None


@dataclass(frozen=True, slots=True)
class LocatedFinding:
    """A :class:`Finding` and the place in the sources it points at."""

    finding: Finding
    location: Location


@dataclass(frozen=True, slots=True)
class TreeRow:
    """One joint of the kinematic tree, depth first, as ``check-urdf --format json`` lists it."""

    depth: int
    joint: str
    type: str
    parent: str
    child: str


@dataclass(frozen=True, slots=True)
class FileReport:
    """The outcome of one :class:`CheckJob`.

    ``error`` is the one-line message when the file could not be loaded (``findings`` then
    holds it as a finding with a load code, see :data:`robotmodel.check.RULES`); otherwise
    ``tree_text`` is check_urdf's stdout for it.
    """

    job: CheckJob
    findings: tuple[LocatedFinding, ...] = ()
    error: str | None = None
    robot: str = ""
    root: str = ""
    links: int = 0
    joints: int = 0
    tree: tuple[TreeRow, ...] = field(default=())
    tree_text: str = ""

    @property
    def ok(self) -> bool:
        """No error-level finding (with ``strict``, every finding is one)."""
        return self.error is None and not any(f.finding.severity is Severity.ERROR for f in self.findings)

    def count(self, severity: Severity) -> int:
        """How many findings of ``severity`` (a load error counts as one error)."""
        return sum(1 for f in self.findings if f.finding.severity is severity)


def _includes(job: CheckJob) -> list[str]:
    from robotmodel.xacro import dependencies

    try:
        return dependencies(job.file, dict(job.args), package_paths=job.package_paths, untrusted=job.untrusted)
    except RobotModelError:
        return []


def _place(finding: Finding, index: SourceIndex) -> Location:
    if finding.code == "mesh-not-found" and finding.message.startswith("mesh '"):
        uri = finding.message[len("mesh '"):].split("'", 1)[0]
        at = index.locate_value("filename", uri)
        if at is not None:
            return at
    element = element_of(finding.element)
    if element is None:
        return Location(display_path(index.entry), None)
    return index.locate(*element)


def check_file(job: CheckJob) -> FileReport:
    """Load, lint and (with ``job.locate``) place the findings of ``job.file``; never raises on bad input."""
    index = SourceIndex(job.file, (lambda: _includes(job)) if _has_includes(job.file) else None)
    unplaced = Location(display_path(job.file), None)
    try:
        desc = load(job.file, dict(job.args), package_paths=job.package_paths, untrusted=job.untrusted)
    except RobotModelError as exc:
        message = " ".join(str(exc).splitlines())
        where = error_location(message, index) if job.locate else unplaced
        finding = Finding(error_code(exc), Severity.ERROR, job.file, message)
        return FileReport(job, (LocatedFinding(finding, where),), error=message)
    findings = lint(desc, base_dir=Path(job.file).resolve().parent, package_paths=job.package_paths)
    if job.strict:
        findings = [Finding(f.code, Severity.ERROR, f.element, f.message) for f in findings]
    located = tuple(LocatedFinding(f, _place(f, index) if job.locate else unplaced) for f in findings)
    tree = tuple(TreeRow(depth, j.name, j.type.value, j.parent, j.child) for depth, j in desc.walk())
    return FileReport(job, located, robot=desc.name, root=desc.root, links=len(desc.links),
                      joints=len(desc.joints), tree=tree, tree_text=tree_report(desc))


def _has_includes(path: str) -> bool:
    # Only a document that includes others needs xacro's --deps to find its sources. A pipe
    # (a shell's <(...)) is not read here: it can be read once, by the load.
    try:
        return Path(path).is_file() and b"xacro:include" in Path(path).read_bytes()
    except OSError:
        return False


def job_args(args: Mapping[str, str]) -> tuple[tuple[str, str], ...]:
    """Xacro args as a :class:`CheckJob` holds them (sorted pairs, hashable)."""
    return tuple(sorted(args.items()))
