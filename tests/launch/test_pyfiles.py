"""Python launch files of real description packages' shapes (tests/launch/pydata) bring their robots up.

Each case runs ``robotmodel launch PKG FILE ARGS`` as a real process on a private bus and
waits until every link of the URDF the file describes (expanded here, with the arguments
the case passes on to xacro, and the frame prefix it gives robot_state_publisher) is
connected to the root on /tf or /tf_static; then Ctrl-C (SIGINT) stops the launcher and
all its processes within 5 s. The links come from the URDF itself, not from the launch
file's plan.
"""

from __future__ import annotations

import re
import shutil
import signal
import sys
import time
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field
from pathlib import Path

import pytest
from conftest import BUNDLED, CMEEL_PREFIX, CORPUS, CORPUS_MISSING
from livebus import Bus, joined

from robotmodel.tf import Buffer, Time
from robotmodel.tf_ros import TransformListener

DATA = Path(__file__).resolve().parent / "pydata"
ERD = CMEEL_PREFIX / "share" / "example-robot-data"
STARTED = re.compile(r"process\[(.+)\]: started with pid \[(\d+)\]")
# Which bundled robots each test package holds in its urdf/ (copied at test time).
ROBOTS = {"tutorial_description": ("arm", "diffbot"), "clearpath_like": ("skid_steer",), "xml_include": ("arm",),
          "yaml_include": ("diffbot",)}


@dataclass(frozen=True)
class Case:
    """A launch file, its arguments, and the URDF it should bring up."""

    pkg: str
    file: str
    args: tuple[str, ...]
    urdf: str  # {ws}/..., {corpus}/... or {erd}/...
    mappings: tuple[tuple[str, str], ...] = ()
    prefix: str = ""
    corpus: bool = False
    processes: tuple[str, ...] = ("joint_state_publisher", "robot_state_publisher")
    env: tuple[tuple[str, str], ...] = field(default=())
    absent: tuple[str, ...] = ()  # links the arguments remove


UR = "{corpus}/Universal_Robots_ROS2_Description/ur_description/urdf/ur.urdf.xacro"
CASES = {
    # urdf_tutorial (ros2) -> urdf_launch display -> urdf_launch description; gui:=false: the plain publisher.
    "urdf_tutorial-display": Case("tutorial_description", "display.launch.py", ("gui:=false",),
                                  "{ws}/tutorial_description/urdf/arm.urdf.xacro",
                                  processes=("joint_state_publisher", "robot_state_publisher", "rviz")),
    # urdf_launch's display used directly, with a model of the user's choice.
    "urdf_launch-display": Case("urdf_launch", "display.launch.py",
                                ("urdf_package:=tutorial_description", "urdf_package_path:=urdf/diffbot.urdf.xacro",
                                 "jsp_gui:=false"), "{ws}/tutorial_description/urdf/diffbot.urdf.xacro",
                                processes=("joint_state_publisher", "robot_state_publisher", "rviz")),
    "urdf_tutorial-humble": Case("tutorial_description", "display_humble.launch.py", ("gui:=false",),
                                 "{ws}/tutorial_description/urdf/diffbot.urdf.xacro",
                                 processes=("joint_state_publisher", "robot_state_publisher", "rviz")),
    "ur-view_ur-ur10e": Case("ur_view", "view_ur.launch.py", ("ur_type:=ur10e", "tf_prefix:=left_"), UR,
                             (("safety_limits", "true"), ("name", "ur"), ("ur_type", "ur10e"),
                              ("tf_prefix", "left_")), corpus=True),
    "turtlebot3-rsp-namespace": Case("tb3_bringup", "robot_state_publisher.launch.py", ("namespace:=tb3_0/",),
                                     "{corpus}/turtlebot3/turtlebot3_description/urdf/turtlebot3_burger.urdf",
                                     (("namespace", "tb3_0/"),), corpus=True, env=(("TURTLEBOT3_MODEL", "burger"),)),
    "franka-visualize-no-gripper": Case("franka_view", "visualize_franka.launch.py", ("load_gripper:=false",),
                                        "{corpus}/franka_description/franka_description/robots/fer/fer.urdf.xacro",
                                        (("hand", "false"), ("ee_id", "franka_hand")), corpus=True,
                                        absent=("fer_hand", "fer_leftfinger")),
    "kinova-view_robot-prefix": Case("kinova_view", "view_robot.launch.py", ("prefix:=k1/",),
                                     "{erd}/robots/kinova_description/robots/kinova.urdf", prefix="k1/"),
    "xarm-display-prefix": Case("xarm_view", "xarm7_display.launch.py", ("prefix:=L_",),
                                "{erd}/robots/xarm_description/urdf/xarm7.urdf", prefix="L_"),
    "clearpath-description": Case("clearpath_like", "description.launch.py", (),
                                  "{ws}/clearpath_like/urdf/skid_steer.urdf.xacro"),
    "python-includes-xml": Case("xml_include", "display.launch.py", ("prefix:=xi/",),
                                "{ws}/xml_include/urdf/arm.urdf.xacro", prefix="xi/"),
    "python-includes-yaml": Case("yaml_include", "display.launch.py", (),
                                 "{ws}/yaml_include/urdf/diffbot.urdf.xacro"),
    "interbotix-timer-namespace": Case("interbotix_like", "xsarm_description.launch.py", ("robot_model:=so101",),
                                       "{erd}/robots/so_arm_description/urdf/so101.urdf"),
}


@pytest.fixture
def ws(tmp_path: Path) -> Path:
    """The test packages, each with its bundled robots in urdf/."""
    root = tmp_path / "ws"
    shutil.copytree(DATA, root)
    for pkg, robots in ROBOTS.items():
        folder = root / pkg / "urdf"
        folder.mkdir(exist_ok=True)
        for name in (*robots, "inertia_macros"):
            suffix = ".xacro" if name == "inertia_macros" else ".urdf.xacro"
            shutil.copy(BUNDLED / f"{name}{suffix}", folder)
    return root


def _path(template: str, ws: Path) -> Path:
    return Path(template.format(ws=ws, corpus=CORPUS, erd=ERD))


def expected_links(case: Case, ws: Path) -> list[str]:
    """Every link of the URDF the case describes, with its frame prefix."""
    from robotmodel.xacro import expand

    text = expand(_path(case.urdf, ws), dict(case.mappings), package_paths=[CORPUS] if case.corpus else [])
    return [case.prefix + link.get("name", "") for link in ET.fromstring(text).iter("link")]


def zero_joints(case: Case, ws: Path) -> list[tuple[str, str, tuple[float, ...]]]:
    """(parent, child, origin xyz) of each joint published at 0: fixed ones, and movable ones
    joint_state_publisher starts at 0 (0 within the limits, no mimic). Their TF is the joint's origin."""
    from robotmodel.xacro import expand

    tree = ET.fromstring(expand(_path(case.urdf, ws), dict(case.mappings),
                                package_paths=[CORPUS] if case.corpus else []))
    out = []
    for joint in tree.findall("joint"):  # not the <joint>s of <transmission>s
        kind, limit, origin = joint.get("type"), joint.find("limit"), joint.find("origin")
        if kind in ("floating", "planar") or joint.find("mimic") is not None:
            continue
        if kind in ("revolute", "prismatic") and limit is not None and not (
                float(limit.get("lower", 0)) <= 0 <= float(limit.get("upper", 0))):
            continue
        xyz = tuple(float(v) for v in (origin.get("xyz", "0 0 0") if origin is not None else "0 0 0").split())
        parent, child = joint.find("parent"), joint.find("child")
        assert parent is not None and child is not None
        out.append((case.prefix + parent.get("link", ""), case.prefix + child.get("link", ""), xyz))
    return out


def root_link(case: Case, ws: Path) -> str:
    """The link that is no joint's child."""
    from robotmodel.xacro import expand

    tree = ET.fromstring(expand(_path(case.urdf, ws), dict(case.mappings),
                                package_paths=[CORPUS] if case.corpus else []))
    children = {c.get("link") for c in tree.iter("child")}
    roots = [case.prefix + link.get("name", "") for link in tree.iter("link") if link.get("name") not in children]
    assert len(roots) == 1, roots
    return roots[0]


def _words(case: Case, ws: Path) -> list[str]:
    words = ["--package-path", str(ws)]
    if case.corpus:
        words += ["--package-path", str(CORPUS)]
    return [*words, case.pkg, case.file, *case.args]


def _environ(case: Case) -> dict[str, str]:
    # example-robot-data is found as an installed package (its share/ament_index), as under a ROS prefix.
    return {"AMENT_PREFIX_PATH": str(CMEEL_PREFIX), "RMW_IMPLEMENTATION": "rmw_zenoh_cpp", **dict(case.env)}


def _gone(pid: int) -> bool:
    try:
        stat = Path(f"/proc/{pid}/stat").read_text()
    except OSError:
        return True
    return stat.rsplit(")", 1)[1].split()[0] == "Z"


@pytest.mark.parametrize("name", sorted(CASES))
def test_launch_py_brings_every_link_up_and_ctrl_c_stops_all(name: str, ws: Path, tmp_path: Path,
                                                             monkeypatch: pytest.MonkeyPatch) -> None:
    case = CASES[name]
    if case.corpus and not CORPUS.is_dir():
        pytest.skip(CORPUS_MISSING)
    links = expected_links(case, ws)
    root = root_link(case, ws)
    bus = Bus(tmp_path)
    bus.env.update(_environ(case))
    for key, value in _environ(case).items():
        monkeypatch.setenv(key, value)
    live = joined(bus, monkeypatch)
    next(live)
    try:
        _bring_up(bus, case, ws, links, root)
    finally:
        live.close()


def _bring_up(live: Bus, case: Case, ws: Path, links: list[str], root: str) -> None:
    proc = live.start(sys.executable, "-m", "robotmodel.cli.main", "launch", "--no-browser", *_words(case, ws))
    pids: dict[str, int] = {}

    def enough() -> bool:
        for line in proc.err:
            m = STARTED.search(line)
            if m:
                pids[m.group(1)] = int(m.group(2))
        return len(pids) >= len(case.processes)

    proc.wait_for(enough, 60, f"{len(case.processes)} processes started")
    kinds = sorted(re.sub(r"-\d+$", "", label).rsplit("/", 1)[-1] for label in pids)
    assert kinds == sorted(k if k != "rviz" else "rviz2" for k in case.processes), pids
    buffer = Buffer()
    with TransformListener(buffer):
        deadline = time.monotonic() + 60
        missing = links
        while missing and time.monotonic() < deadline:
            missing = [link for link in links if link != root and not buffer.can_transform(root, link, Time())]
            if missing:
                time.sleep(0.1)
        assert not missing, f"not on /tf or /tf_static within 60 s: {missing}\n{buffer.all_frames_as_string()}"
        # The arguments changed the robot as the URDF says: each joint at 0 sits at its origin.
        for parent, child, xyz in zero_joints(case, ws):
            t = buffer.lookup_transform(parent, child, Time()).transform.translation
            assert (t.x, t.y, t.z) == pytest.approx(xyz, abs=1e-6), (parent, child)
        frames = buffer.all_frames_as_string()
        assert not [f for f in case.absent if f"Frame {f} " in frames], frames
    start = time.monotonic()
    assert proc.stop(signal.SIGINT, timeout=5.0) == 0
    while not all(_gone(pid) for pid in pids.values()):
        assert time.monotonic() - start < 5.0, f"still running 5 s after Ctrl-C: {pids}"
        time.sleep(0.05)
    assert "Traceback" not in "\n".join(proc.err)


def test_thirteen_files_of_twelve_shapes_are_covered() -> None:
    files = sorted(p.relative_to(DATA).as_posix() for p in DATA.glob("*/launch/*.py"))
    assert len(files) >= 12, files
    readme = (DATA / "README.md").read_text()
    assert all(f in readme for f in files), [f for f in files if f not in readme]
