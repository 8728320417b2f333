"""SARIF 2.1.0 for check results, the format code-scanning tools (GitHub's among them) upload.

One run of the ``robotmodel`` driver; its rules are :data:`robotmodel.check.RULES` (ids are
the finding codes, with their help text); each finding is a result at its physical location.
Paths below the working directory are written relative to ``%SRCROOT%`` (the repository
root in CI), others as absolute ``file:`` URIs. Every result has a ``region.startLine``, as
GitHub code scanning requires: a finding about a whole file gets line 1 and the property
``wholeFile: true``.
"""

from __future__ import annotations

from collections.abc import Iterable
from pathlib import Path
from typing import Any
from urllib.parse import quote

from robotmodel.check._lint import Finding, Severity
from robotmodel.check._locations import Location
from robotmodel.check._rules import RULES

__all__ = ["SARIF_SCHEMA", "to_sarif"]

#: The schema URI written in the log's ``$schema``.
SARIF_SCHEMA = "https://docs.oasis-open.org/sarif/sarif/v2.1.0/errata01/os/schemas/sarif-schema-2.1.0.json"

_LEVEL = {Severity.ERROR: "error", Severity.WARNING: "warning"}


def _rule(code: str) -> dict[str, Any]:
    rule = RULES[code]
    return {
        "id": code,
        "name": "".join(part.capitalize() for part in code.split("-")),
        "shortDescription": {"text": rule.summary},
        "fullDescription": {"text": rule.help},
        "help": {"text": rule.help},
        "defaultConfiguration": {"level": _LEVEL[rule.severity]},
    }


def _artifact(file: str) -> dict[str, str]:
    path = Path(file)
    if path.is_absolute():
        return {"uri": path.as_uri()}
    return {"uri": quote(path.as_posix()), "uriBaseId": "%SRCROOT%"}


def _result(finding: Finding, location: Location, rule_index: int) -> dict[str, Any]:
    # GitHub shows only results with a region.startLine: a finding about the whole file points at
    # its first line and says so in its property bag.
    physical = {"artifactLocation": _artifact(location.file), "region": {"startLine": location.line or 1}}
    text = finding.message if finding.element in ("", location.file) else f"{finding.element}: {finding.message}"
    result: dict[str, Any] = {
        "ruleId": finding.code,
        "ruleIndex": rule_index,
        "level": _LEVEL[finding.severity],
        "message": {"text": text},
        "locations": [{"physicalLocation": physical}],
    }
    if location.line is None:
        result["properties"] = {"wholeFile": True}
    return result


def to_sarif(items: Iterable[tuple[Finding, Location]], *, version: str) -> dict[str, Any]:
    """A SARIF 2.1.0 log (as JSON-ready dicts) of the (finding, location) pairs, by robotmodel ``version``."""
    codes = list(RULES)
    index = {code: i for i, code in enumerate(codes)}
    results = [_result(f, loc, index[f.code]) for f, loc in items]
    return {
        "$schema": SARIF_SCHEMA,
        "version": "2.1.0",
        "runs": [{
            "tool": {"driver": {
                "name": "robotmodel",
                "version": version,
                "semanticVersion": version,
                "rules": [_rule(code) for code in codes],
            }},
            "originalUriBaseIds": {"%SRCROOT%": {"uri": Path.cwd().as_uri() + "/"}},
            "invocations": [{"executionSuccessful": True}],
            "results": results,
        }],
    }
