"""Each lint rule: one robot that triggers it, one that does not."""

from __future__ import annotations

import subprocess
from pathlib import Path

import pytest
from conftest import CHECK_URDF_BIN, urdfdom_env

from robotmodel.check import Finding, Severity, lint
from robotmodel.model import parse_urdf


def _inertial(mass: float = 1.0, diag: tuple[float, float, float] = (1.0, 1.0, 1.0), ixy: float = 0.0) -> str:
    return (f'<inertial><mass value="{mass}"/><inertia ixx="{diag[0]}" ixy="{ixy}" ixz="0" '
            f'iyy="{diag[1]}" iyz="0" izz="{diag[2]}"/></inertial>')


def _robot(*, child: str = "", base: str = "", joint: str = 'type="revolute"',
           limit: str = '<limit effort="1" velocity="1" lower="-1" upper="1"/>', extra: str = "") -> str:
    return (f'<robot name="r">{extra}<link name="base">{base or _inertial()}</link>'
            f'<link name="arm">{child or _inertial()}</link>'
            f'<joint name="j" {joint}><parent link="base"/><child link="arm"/>{limit}</joint></robot>')


def _codes(text: str, base_dir: Path | None = None) -> list[str]:
    return [f.code for f in lint(parse_urdf(text), base_dir=base_dir)]


def test_clean_robot_has_no_findings() -> None:
    assert _codes(_robot()) == []


@pytest.mark.parametrize(("child", "bad"), [
    (_inertial(mass=-1.0), True),
    (_inertial(mass=0.0, diag=(0, 0, 0)), True),
    (_inertial(mass=2.0), False),
])
def test_mass(child: str, bad: bool) -> None:
    assert ("mass-not-positive" in _codes(_robot(child=child))) is bad


def test_zero_mass_frame_welded_to_a_massive_body_is_fine() -> None:
    text = _robot(extra="").replace(
        "</robot>",
        '<link name="tool0">' + _inertial(mass=0.0, diag=(0, 0, 0)) + "</link>"
        '<joint name="tool" type="fixed"><parent link="arm"/><child link="tool0"/></joint></robot>',
    )
    assert _codes(text) == []
    # ... but not when the welded frame is the only mass a movable joint drives.
    text = _robot(child=_inertial(mass=0.0, diag=(0, 0, 0)))
    assert "mass-not-positive" in _codes(text)


def _box_inertia(m: float, x: float, y: float, z: float) -> tuple[float, float, float]:
    return (m * (y * y + z * z) / 12, m * (x * x + z * z) / 12, m * (x * x + y * y) / 12)


@pytest.mark.parametrize(("child", "code"), [
    (_inertial(diag=(1.0, -1.0, 1.0)), "inertia-not-positive-definite"),
    (_inertial(diag=(1.0, 1.0, 1.0), ixy=2.0), "inertia-not-positive-definite"),
    (_inertial(diag=(0.0, 0.0, 0.0)), "inertia-not-positive-definite"),
    (_inertial(diag=(1.0, 1.0, 3.0)), "inertia-triangle-inequality"),
    (_inertial(diag=_box_inertia(2.0, 0.1, 0.2, 0.3)), None),
    (_inertial(diag=_box_inertia(2.0, 1.0, 1.0, 0.0)), None),  # a flat plate: a + b == c exactly
])
def test_inertia(child: str, code: str | None) -> None:
    found = [c for c in _codes(_robot(child=child)) if c.startswith("inertia-")]
    assert found == ([code] if code else [])


@pytest.mark.parametrize(("limit", "codes"), [
    ('<limit effort="1" velocity="1" lower="1" upper="-1"/>', ["limit-lower-above-upper"]),
    ('<limit effort="0" velocity="1" lower="-1" upper="1"/>', ["limit-zero-effort"]),
    ('<limit effort="1" velocity="0" lower="-1" upper="1"/>', ["limit-zero-velocity"]),
    ('<limit effort="1" velocity="1" lower="-1" upper="-1"/>', []),
])
def test_limits(limit: str, codes: list[str]) -> None:
    assert _codes(_robot(limit=limit)) == codes


def test_continuous_joint_has_no_position_limits() -> None:
    limit = '<limit effort="1" velocity="1" lower="1" upper="-1"/>'
    assert _codes(_robot(joint='type="continuous"', limit=limit)) == []


def _mesh(uri: str) -> str:
    return _inertial() + f'<visual><geometry><mesh filename="{uri}"/></geometry></visual>'


def test_mesh_resolution(tmp_path: Path) -> None:
    pkg = tmp_path / "my_pkg"
    (pkg / "meshes").mkdir(parents=True)
    (pkg / "package.xml").write_text("<package><name>my_pkg</name></package>")
    (pkg / "meshes" / "arm.stl").write_text("solid x\nendsolid x\n")
    urdf_dir = pkg / "urdf"
    urdf_dir.mkdir()
    for uri in ("package://my_pkg/meshes/arm.stl", "../meshes/arm.stl",
                f"file://{pkg / 'meshes' / 'arm.stl'}"):
        assert _codes(_robot(child=_mesh(uri)), urdf_dir) == [], uri
    for uri in ("package://my_pkg/meshes/nope.stl", "../meshes/nope.stl", "package://no_such_pkg/a.stl"):
        assert _codes(_robot(child=_mesh(uri)), urdf_dir) == ["mesh-not-found"], uri


def _material(name: str, color: bool) -> str:
    inner = '<color rgba="1 0 0 1"/>' if color else ""
    return (f'<visual><geometry><box size="1 1 1"/></geometry>'
            f'<material name="{name}">{inner}</material></visual>')


def test_materials(tmp_path: Path) -> None:
    undefined = _robot(child=_inertial() + _material("red", color=False))
    assert _codes(undefined) == ["material-undefined"]
    # urdfdom, run on the same text, warns about exactly this one.
    path = tmp_path / "m.urdf"
    path.write_text(undefined)
    ref = subprocess.run([str(CHECK_URDF_BIN), str(path)], capture_output=True, text=True,
                         env=urdfdom_env(), check=False)
    assert "link 'arm' material 'red' undefined." in ref.stderr
    defined_globally = _robot(child=_inertial() + _material("red", color=False),
                              extra='<material name="red"><color rgba="1 0 0 1"/></material>')
    assert _codes(defined_globally) == []
    # A colour given in an earlier link's visual defines the name for later links, as in urdfdom.
    defined_earlier = _robot(base=_inertial() + _material("red", color=True),
                             child=_inertial() + _material("red", color=False))
    assert _codes(defined_earlier) == []


def test_moving_link_without_inertial() -> None:
    assert _codes(_robot(child="<visual><geometry><box size='1 1 1'/></geometry></visual>")) == [
        "moving-link-without-inertial"
    ]
    # The mass may sit on a link welded below it.
    welded = _robot(child="").replace(f'<link name="arm">{_inertial()}</link>', '<link name="arm"/>').replace(
        "</robot>",
        f'<link name="shell">{_inertial()}</link>'
        '<joint name="weld" type="fixed"><parent link="arm"/><child link="shell"/></joint></robot>',
    )
    assert _codes(welded) == []
    # A fixed joint moves nothing.
    assert _codes(_robot(child="", joint='type="fixed"', limit="").replace(
        f'<link name="arm">{_inertial()}</link>', '<link name="arm"/>')) == []


def test_mimic_of_missing_joint_is_an_error() -> None:
    text = _robot(limit='<limit effort="1" velocity="1" lower="-1" upper="1"/><mimic joint="ghost"/>')
    findings = lint(parse_urdf(text))
    assert findings == [Finding("mimic-missing-joint", Severity.ERROR, "joint [j]",
                                "mimics joint [ghost], which does not exist")]
    existing = text.replace("</robot>", '<link name="hand">' + _inertial() + "</link>"
                            '<joint name="ghost" type="continuous"><parent link="arm"/><child link="hand"/>'
                            "</joint></robot>")
    assert lint(parse_urdf(existing)) == []
    with pytest.raises(Exception, match="mimic joints form a cycle"):
        parse_urdf(text.replace('"ghost"', '"j"'))
