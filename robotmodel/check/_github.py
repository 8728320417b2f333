"""GitHub Actions workflow commands for check results, so findings show on the pull request.

One line per finding: ``::error file=F,line=L,title=CODE::message`` (``::warning`` for
warnings, ``::notice`` for notes). GitHub reads the data after ``::`` with ``%``, CR and LF
percent-encoded, and property values with ``,`` and ``:`` encoded as well.
"""

from __future__ import annotations

from collections.abc import Iterable

from robotmodel.check._lint import Finding, Severity
from robotmodel.check._locations import Location

__all__ = ["escape_data", "escape_property", "workflow_command", "workflow_commands"]


def escape_data(text: str) -> str:
    """Encode a workflow command's message: ``%``, CR and LF."""
    return text.replace("%", "%25").replace("\r", "%0D").replace("\n", "%0A")


def escape_property(text: str) -> str:
    """Encode a workflow command's property value: as :func:`escape_data`, plus ``:`` and ``,``."""
    return escape_data(text).replace(":", "%3A").replace(",", "%2C")


def workflow_command(finding: Finding, location: Location, *, level: str | None = None) -> str:
    """The annotation line for ``finding`` at ``location`` (``level`` overrides its severity)."""
    kind = level or ("error" if finding.severity is Severity.ERROR else "warning")
    props: list[tuple[str, str]] = [("file", location.file)]
    if location.line is not None:
        props.append(("line", str(location.line)))
    props.append(("title", finding.code))
    head = ",".join(f"{key}={escape_property(value)}" for key, value in props)
    text = finding.message if finding.element == location.file or not finding.element else (
        f"{finding.element}: {finding.message}")
    return f"::{kind} {head}::{escape_data(text)}"


def workflow_commands(items: Iterable[tuple[Finding, Location]]) -> list[str]:
    """:func:`workflow_command` for each (finding, location)."""
    return [workflow_command(f, loc) for f, loc in items]
