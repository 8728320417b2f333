"""The bundled seed robots: expand, pass urdfdom and our strict check, physically valid inertias."""

from __future__ import annotations

import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest
import robotmodel.robots
from conftest import CHECK_URDF_BIN, urdfdom_env

from robotmodel.kinematics import KinematicModel, KinematicState
from robotmodel.xacro import expand

SEEDS = ["arm.urdf.xacro", "diffbot.urdf.xacro", "skid_steer.urdf.xacro"]


def test_bundled_names() -> None:
    assert robotmodel.robots.names() == SEEDS


@pytest.fixture(scope="module", params=SEEDS)
def seed(request) -> tuple[str, str]:
    return request.param, expand(robotmodel.robots.path(request.param))


def test_urdfdom_accepts(seed, tmp_path: Path) -> None:
    _name, text = seed
    path = tmp_path / "robot.urdf"
    path.write_text(text, encoding="utf-8")
    result = subprocess.run([str(CHECK_URDF_BIN), str(path)], capture_output=True, text=True, env=urdfdom_env(),
                            check=False)
    assert result.returncode == 0, result.stderr
    assert "Warning" not in result.stderr and "Error" not in result.stderr


def test_strict_check_has_no_warnings(seed) -> None:
    name, _ = seed
    result = subprocess.run([sys.executable, "-m", "robotmodel.cli.main", "check-urdf", "--strict",
                             str(robotmodel.robots.path(name))], capture_output=True, text=True, check=False)
    assert result.returncode == 0 and result.stderr == "", result.stderr


def _expected_inertia(link: ET.Element, mass: float) -> np.ndarray:
    """Solid-body inertia about the centre, recomputed from the collision primitive."""
    shape = link.find("collision/geometry")[0]
    if shape.tag == "box":
        x, y, z = (float(v) for v in shape.get("size").split())
        return mass / 12 * np.diag([y * y + z * z, x * x + z * z, x * x + y * y])
    if shape.tag == "cylinder":
        r, h = float(shape.get("radius")), float(shape.get("length"))
        side = mass * (3 * r * r + h * h) / 12
        return np.diag([side, side, mass * r * r / 2])
    r = float(shape.get("radius"))
    return np.eye(3) * 2 / 5 * mass * r * r


def test_inertias_follow_the_geometry(seed) -> None:
    _, text = seed
    robot = ET.fromstring(text)
    checked = 0
    for link in robot.findall("link"):
        inertial = link.find("inertial")
        if inertial is None:
            continue
        mass = float(inertial.find("mass").get("value"))
        i = {k: float(v) for k, v in inertial.find("inertia").attrib.items()}
        tensor = np.array([[i["ixx"], i["ixy"], i["ixz"]], [i["ixy"], i["iyy"], i["iyz"]], [i["ixz"], i["iyz"], i["izz"]]])
        np.testing.assert_allclose(tensor, _expected_inertia(link, mass), rtol=1e-12, err_msg=link.get("name"))
        # The inertial frame is the collision frame (same origin), so the formula applies as is.
        assert inertial.find("origin").attrib == link.find("collision/origin").attrib if link.find(
            "collision/origin") is not None else True
        moments = np.linalg.eigvalsh(tensor)
        assert moments.min() > 0 and moments[0] + moments[1] >= moments[2]
        checked += 1
    assert checked >= 6


def test_diffbot_sensors_where_the_tf_seeds_expect_them() -> None:
    model = KinematicModel.load(robotmodel.robots.path("diffbot.urdf.xacro"))
    joint = model.description.joint("camera_joint")
    assert (joint.parent, joint.child, joint.origin.xyz) == ("base_link", "camera_link", (0.1, 0.0, 0.2))
    assert joint.origin.rpy[1] > 0  # pitched down
    names = {link.name for link in model.description.links}
    assert {"base_footprint", "base_link", "camera_link", "imu_link", "laser_link", "caster_link"} <= names
    assert model.description.root == "base_footprint"


def test_skid_steer_has_four_continuous_wheels_on_base_link() -> None:
    desc = KinematicModel.load(robotmodel.robots.path("skid_steer.urdf.xacro")).description
    wheels = [j for j in desc.joints if j.type.value == "continuous"]
    assert len(wheels) == 4 and {j.parent for j in wheels} == {"base_link"}
    assert "laser_link" in {link.name for link in desc.links}


def test_arm_gripper_fingers_move_symmetrically() -> None:
    model = KinematicModel.load(robotmodel.robots.path("arm.urdf.xacro"))
    assert "arm_shoulder_joint" in model.variables and len(model.variables) == 7  # 6 arm joints + 1 finger
    state = KinematicState(model)
    closed = state.update({"gripper_left_finger_joint": 0.0})
    left0, right0 = closed.link_matrix("gripper_left_finger_link")[:3, 3], closed.link_matrix("gripper_right_finger_link")[:3, 3]
    opened = state.update({"gripper_left_finger_joint": 0.03})
    left1, right1 = opened.link_matrix("gripper_left_finger_link")[:3, 3], opened.link_matrix("gripper_right_finger_link")[:3, 3]
    np.testing.assert_allclose(left1 - left0, -(right1 - right0), atol=1e-12)
    assert np.linalg.norm(left1 - left0) == pytest.approx(0.03)


def _tree_from_xml(text: str) -> list[str]:
    """check_urdf's listing rebuilt independently from the XML: root, then children by joint name, depth-first."""
    robot = ET.fromstring(text)
    joints = sorted(robot.findall("joint"), key=lambda j: j.get("name"))
    children: dict[str, list[str]] = {}
    for j in joints:
        children.setdefault(j.find("parent").get("link"), []).append(j.find("child").get("link"))
    child_links = {j.find("child").get("link") for j in joints}
    (root,) = [link.get("name") for link in robot.findall("link") if link.get("name") not in child_links]
    lines = [f"robot name is: {robot.get('name')}", "---------- Successfully Parsed XML ---------------",
             f"root Link: {root} has {len(children.get(root, []))} child(ren)"]

    def walk(link: str, depth: int) -> None:
        for i, child in enumerate(children.get(link, []), 1):
            lines.append("    " * depth + f"child({i}):  {child}")
            walk(child, depth + 1)

    walk(root, 1)
    return lines


def test_urdfdom_tree_matches_the_design(seed, tmp_path: Path) -> None:
    name, text = seed
    path = tmp_path / "robot.urdf"
    path.write_text(text, encoding="utf-8")
    out = subprocess.run([str(CHECK_URDF_BIN), str(path)], capture_output=True, text=True, env=urdfdom_env(),
                         check=True).stdout
    assert out.splitlines() == _tree_from_xml(text)
    designed_roots = {"arm.urdf.xacro": "world", "diffbot.urdf.xacro": "base_footprint",
                      "skid_steer.urdf.xacro": "base_link"}
    assert out.splitlines()[2].startswith(f"root Link: {designed_roots[name]} ")


def test_mimic_joints_refer_to_existing_joints(seed) -> None:
    _, text = seed
    robot = ET.fromstring(text)
    joint_names = {j.get("name") for j in robot.findall("joint")}
    mimics = list(robot.iter("mimic"))
    for mimic in mimics:
        assert mimic.get("joint") in joint_names
    assert len(mimics) == (1 if robot.get("name") == "arm" or "gripper_left_finger_joint" in joint_names else 0)


def test_xacro_cli_expands_each_seed_to_the_same_text(seed, tmp_path: Path) -> None:
    """The upstream ``xacro`` CLI (run from elsewhere, so relative includes must resolve against the file) agrees."""
    name, text = seed
    source = robotmodel.robots.path(name)
    result = subprocess.run([sys.executable, "-c", "import sys, xacro; sys.argv[0] = 'xacro'; xacro.main()",
                             str(source)], capture_output=True, text=True, cwd=tmp_path, check=False)
    assert result.returncode == 0, result.stderr
    assert result.stdout.strip() == text.strip()
