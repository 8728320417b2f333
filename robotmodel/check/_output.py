"""The four output formats of ``check-urdf`` and its summary line.

- text: check_urdf's stdout per passing file; one stderr line per finding (named by file
  when several files are checked) — a single file's output is exactly what it always was;
- json: the single-file object, or ``{"ok", "files": [...], "summary"}`` for several;
- github: one workflow command per finding on stdout;
- sarif: one SARIF 2.1.0 log on stdout.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from robotmodel.check._run import FileReport

__all__ = ["json_object", "summary", "text_lines"]


def text_lines(report: FileReport, command: str, *, many: bool) -> list[str]:
    """The stderr lines of ``report`` in the text format (the tree goes to stdout separately)."""
    if report.error is not None:
        return [f"robotmodel {command}: error: {report.error}"]
    lines = []
    for item in report.findings:
        # A finding about the whole file already names it.
        named = not many or item.finding.element == report.job.file
        lines.append(f"robotmodel {command}: {'' if named else report.job.file + ': '}{item.finding}")
    return lines


def _finding(item: Any) -> dict[str, Any]:
    f = item.finding
    return {"code": f.code, "severity": f.severity.value, "element": f.element, "message": f.message,
            "file": item.location.file, "line": item.location.line}


def json_object(report: FileReport, *, many: bool) -> dict[str, Any]:
    """The JSON object for one report; with ``many`` it names its file and args."""
    head: dict[str, Any] = {"file": report.job.file, "args": dict(report.job.args)} if many else {}
    if report.error is not None:
        return {**head, "ok": False, "error": report.error,
                **({"findings": [_finding(i) for i in report.findings]} if many else {})}
    return {
        **head,
        "ok": report.ok,
        "robot": report.robot,
        "root": report.root,
        "links": report.links,
        "joints": report.joints,
        "tree": [{"depth": r.depth, "joint": r.joint, "type": r.type, "parent": r.parent, "child": r.child}
                 for r in report.tree],
        "findings": [_finding(i) for i in report.findings],
    }


def _plural(n: int, word: str) -> str:
    return f"{n} {word}{'' if n == 1 else 's'}"


def summary(reports: Sequence[FileReport], unchecked: Sequence[FileReport]) -> str:
    """One line: how many checks ran, passed and failed, the error and warning totals, fragments left out."""
    from robotmodel.check._lint import Severity

    every = [*reports, *unchecked]
    failed = sum(1 for r in reports if not r.ok)
    errors = sum(r.count(Severity.ERROR) for r in every)
    warnings = sum(r.count(Severity.WARNING) for r in every)
    line = (f"{_plural(len(reports), 'file')} checked: {len(reports) - failed} passed, "
            f"{failed} failed ({_plural(errors, 'error')}, {_plural(warnings, 'warning')})")
    if unchecked:
        line += f"; {_plural(len(unchecked), 'macro-only file')} not checked (no configured entry includes it)"
    return line
