"""Odd inputs that urdfdom handles one way and we used to handle another (or crash on).

Each case runs the real ``check_urdf`` on the same file; our verdict, and on success our
stdout, must be urdfdom's. Failures are one line on stderr, never a traceback.
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest
from conftest import CHECK_URDF_BIN, urdfdom_env

from robotmodel.check import lint
from robotmodel.errors import URDFParseError
from robotmodel.model import parse_urdf

AB = '<link name="a"/><link name="b"/>'


def _rev(inner: str, limit: str = '<limit effort="1" velocity="1" lower="-1" upper="1"/>') -> str:
    return (f'<robot name="r">{AB}<joint name="j" type="revolute"><parent link="a"/><child link="b"/>'
            f"{limit}{inner}</joint></robot>")


def _run(argv: list[str]) -> subprocess.CompletedProcess[str]:
    return subprocess.run(argv, capture_output=True, text=True, timeout=120, check=False)


def _ours(*args: str) -> subprocess.CompletedProcess[str]:
    return _run([sys.executable, "-m", "robotmodel.cli.main", *args])


def _urdfdom(path: Path) -> subprocess.CompletedProcess[str]:
    # urdfdom prints names as the file's bytes, which need not be UTF-8.
    return subprocess.run([str(CHECK_URDF_BIN), str(path)], capture_output=True, text=True, errors="replace",
                          env=urdfdom_env(), timeout=30, check=False)


# (id, text, whether urdfdom accepts it)
CASES = [
    ("dynamics-empty", _rev("<dynamics/>"), False),
    ("dynamics-friction-only", _rev('<dynamics friction="0.5"/>'), True),
    ("limit-whitespace-around", _rev("", '<limit effort="1" velocity="&#9;1&#10;" lower="-1" upper="1"/>'), False),
    ("limit-trailing-space", _rev("", '<limit effort="1 " velocity="1" lower="-1" upper="1"/>'), False),
    ("limit-leading-whitespace", _rev("", '<limit effort=" 1" velocity="&#9;1" lower="-1" upper="1"/>'), True),
    ("mimic-trailing-newline", _rev('<mimic joint="j" multiplier="1&#10;"/>'), False),
    ("origin-tab-separated", _rev('<origin xyz="1&#9;0 0"/>'), False),
    ("origin-leading-tab", _rev('<origin xyz="&#9;1 0 0"/>'), True),
    ("origin-extra-spaces", _rev('<origin xyz="  1  0 0 "/>'), True),
    ("tab-in-link-name", '<robot name="r"><link name="a&#9;b"/><link name="c"/><joint name="j" type="fixed">'
     '<parent link="a&#9;b"/><child link="c"/></joint></robot>', True),
    ("newline-in-robot-name", '<robot name="x&#10;y"><link name="a"/></robot>', True),
]


@pytest.mark.parametrize(("text", "accepted"), [c[1:] for c in CASES], ids=[c[0] for c in CASES])
def test_check_urdf_verdict_and_output_match_urdfdom(text: str, accepted: bool, tmp_path: Path) -> None:
    path = tmp_path / "case.urdf"
    path.write_text(text, encoding="utf-8")
    ref = _urdfdom(path)
    assert (ref.returncode == 0) is accepted, ref.stderr
    ours = _ours("check-urdf", str(path))
    assert "Traceback" not in ours.stderr
    if accepted:
        assert ours.stdout == ref.stdout
    else:
        assert ours.returncode != 0 and ours.stdout == ""
        assert ours.stderr.count("\n") == 1, ours.stderr
        fk = _ours("fk", str(path))
        assert fk.returncode != 0 and fk.stdout == ""
        assert fk.stderr.count("\n") == 1, fk.stderr


@pytest.mark.parametrize("encoding", ["iso-8859-1", "utf-16", "utf-16-le"])
def test_declared_encodings_are_honoured(encoding: str, tmp_path: Path) -> None:
    text = (f'<?xml version="1.0" encoding="{encoding}"?>\n'
            '<robot name="r\u00e9"><link name="\u00e4"/><link name="b"/><joint name="j" type="fixed">'
            '<parent link="\u00e4"/><child link="b"/></joint></robot>\n')
    data = text.encode(encoding if encoding != "utf-16-le" else "utf-16")
    desc = parse_urdf(data)
    assert desc.name == "r\u00e9" and desc.root == "\u00e4"
    path = tmp_path / "case.urdf"
    path.write_bytes(data)
    # urdfdom (tinyxml2) passes Latin-1 bytes through as they are and fails on UTF-16 (it
    # reads UTF-8 only); we decode what the declaration says, so names are right in both.
    assert (_urdfdom(path).returncode == 0) is (encoding == "iso-8859-1")
    ours = _ours("check-urdf", str(path))
    assert ours.returncode == 0, ours.stderr
    assert "root Link: \u00e4 has 1 child(ren)" in ours.stdout


def test_wrong_declared_encoding_is_one_clean_error() -> None:
    data = b'<?xml version="1.0" encoding="no-such-codec"?><robot name="r"><link name="a"/></robot>'
    with pytest.raises(URDFParseError, match="malformed XML"):
        parse_urdf(data)


def test_overlong_mesh_filename_is_a_finding(tmp_path: Path) -> None:
    name = "m" * 300 + ".stl"
    text = (f'<robot name="r"><link name="a"><visual><geometry><mesh filename="{name}"/></geometry></visual>'
            f'</link></robot>')
    desc = parse_urdf(text)
    findings = [f for f in lint(desc, base_dir=tmp_path) if f.code == "mesh-not-found"]
    assert len(findings) == 1 and "File name too long" in findings[0].message
    path = tmp_path / "long.urdf"
    path.write_text(text, encoding="utf-8")
    ours = _ours("check-urdf", str(path))
    assert "Traceback" not in ours.stderr
    assert "mesh-not-found" in ours.stderr


def test_overlong_package_mesh_is_a_finding(tmp_path: Path) -> None:
    text = ('<robot name="r"><link name="a"><visual><geometry>'
            f'<mesh filename="package://{"p" * 300}/m.stl"/></geometry></visual></link></robot>')
    findings = [f for f in lint(parse_urdf(text), base_dir=tmp_path) if f.code == "mesh-not-found"]
    assert len(findings) == 1
