"""The viewer without a browser: scene tree, joint updates, colours, mesh cache, sliders, CLI errors."""

from __future__ import annotations

import logging
import math
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
import trimesh
import umsgpack
from conftest import BUNDLED, ERD_ROBOTS
from pytransform3d.rotations import matrix_from_axis_angle, matrix_from_euler

from robotmodel.errors import JointValueError
from robotmodel.kinematics import KinematicModel
from robotmodel.model import load, parse_urdf
from robotmodel.viewer import Viewer, load_mesh, slider_joints

PANDA = ERD_ROBOTS / "panda_description" / "urdf" / "panda.urdf"
ARM = BUNDLED / "arm.urdf.xacro"


def _decode(viewer: Viewer) -> tuple[dict[str, np.ndarray], dict[str, dict]]:
    """(path → local 4×4 transform, path → object JSON) of the viewer's current scene."""
    transforms, objects = {}, {}
    for packed in viewer.commands():
        cmd = umsgpack.unpackb(packed)
        if cmd["type"] == "set_transform":
            transforms[cmd["path"]] = np.frombuffer(cmd["matrix"].data, dtype=np.float32).reshape(4, 4).T
        elif cmd["type"] == "set_object":
            objects[cmd["path"]] = cmd["object"]
    return transforms, objects


def _origin(xyz: tuple[float, ...], rpy: tuple[float, ...]) -> np.ndarray:
    m = np.eye(4)
    m[:3, :3] = matrix_from_euler(rpy, 0, 1, 2, True)
    m[:3, 3] = xyz
    return m


def test_scene_tree_mirrors_the_kinematic_tree() -> None:
    desc = load(PANDA)
    _, objects = _decode(Viewer(desc, serve=False, frames="all"))  # every link then holds an object
    # Each link's group sits inside its parent link's group.
    for _, joint in desc.walk():
        parent = next(p for p in objects if p.split("/<")[0].endswith("/" + joint.parent))
        child = next(p for p in objects if p.split("/<")[0].endswith("/" + joint.child))
        assert child.split("/<")[0] == parent.split("/<")[0] + "/" + joint.child


def test_a_joint_update_sets_only_that_joints_local_transform() -> None:
    desc = load(ARM)
    viewer = Viewer(desc, serve=False)
    before, _ = _decode(viewer)
    model = KinematicModel(desc)
    master = next(r.master for r in model.mimics.values())
    mimics = [r for r in model.mimics.values() if r.master == master]
    viewer.display({master: 0.01})
    after, _ = _decode(viewer)
    changed = {p for p in after if p not in before or not np.allclose(after[p], before[p])}
    moved = {desc.joint(master).child, *(desc.joint(r.joint).child for r in mimics)}
    assert {p.rsplit("/", 1)[-1] for p in changed} == moved
    # The new transform is the joint's origin times its motion, computed here by hand.
    joint = desc.joint(master)
    path = next(p for p in changed if p.endswith("/" + joint.child))
    motion = np.eye(4)
    if joint.type.value == "prismatic":
        motion[:3, 3] = np.asarray(joint.axis) * 0.01
    else:
        motion[:3, :3] = matrix_from_axis_angle([*joint.axis, 0.01])
    np.testing.assert_allclose(after[path], _origin(joint.origin.xyz, joint.origin.rpy) @ motion, atol=1e-6)


def test_panda_meshes_keep_their_own_colours_and_the_urdf_colours_boxes(tmp_path: Path) -> None:
    _, objects = _decode(Viewer(load(PANDA), serve=False, cache_dir=tmp_path))
    link0 = next(o for p, o in objects.items() if "/panda_link0/<visual>/" in p)
    colours = np.frombuffer(link0["geometries"][0]["data"]["attributes"]["color"]["array"].data, np.float32)
    rgb = {tuple(np.round(c * 255).astype(int)) for c in colours.reshape(-1, 3)}
    # link0.dae's materials, read independently with trimesh.
    scene = trimesh.load(ERD_ROBOTS / "panda_description" / "meshes" / "visual" / "link0.dae", force="scene")
    expected = {tuple(int(c) for c in g.visual.material.main_color[:3]) for g in scene.geometry.values()}
    assert rgb == expected
    urdf = """<robot name="r"><material name="teal"><color rgba="0 0.5 0.5 1"/></material>
      <link name="a"><visual><geometry><box size="1 2 3"/></geometry><material name="teal"/></visual></link></robot>"""
    _, objects = _decode(Viewer(parse_urdf(urdf), serve=False))
    box = next(o for p, o in objects.items() if "<visual>" in p)
    assert box["materials"][0]["color"] == (0 << 16) | (128 << 8) | 128
    assert (box["geometries"][0]["width"], box["geometries"][0]["height"], box["geometries"][0]["depth"]) == (1, 2, 3)


def test_mesh_scale_scales_the_vertices(tmp_path: Path) -> None:
    stl = ERD_ROBOTS / "panda_description" / "meshes" / "collision" / "link1.stl"
    urdf = f"""<robot name="r"><link name="a"><visual><geometry><mesh filename="file://{stl}" scale="2 1 0.5"/>
      </geometry></visual></link></robot>"""
    _, objects = _decode(Viewer(parse_urdf(urdf), serve=False, cache_dir=tmp_path))
    obj = next(o for p, o in objects.items() if "<visual>" in p)
    verts = np.frombuffer(obj["geometries"][0]["data"]["attributes"]["position"]["array"].data, np.float32)
    bounds = trimesh.load(stl).bounds
    np.testing.assert_allclose(verts.reshape(-1, 3).min(axis=0), bounds[0] * [2, 1, 0.5], rtol=1e-5, atol=1e-6)


def test_mesh_cache_is_keyed_by_file_and_mtime(tmp_path: Path) -> None:
    src = tmp_path / "part.stl"
    shutil.copy(ERD_ROBOTS / "panda_description" / "meshes" / "collision" / "link3.stl", src)
    cache = tmp_path / "cache"
    first, hit1 = load_mesh(src, cache)
    second, hit2 = load_mesh(src, cache)
    assert (hit1, hit2) == (False, True)
    np.testing.assert_array_equal(first.vertices, second.vertices)
    reference = trimesh.load(src)
    np.testing.assert_allclose(first.vertices, reference.vertices, rtol=1e-6)
    st = src.stat()
    os.utime(src, ns=(st.st_atime_ns, st.st_mtime_ns + 1_000_000_000))
    _, hit3 = load_mesh(src, cache)
    assert hit3 is False


def test_a_missing_mesh_becomes_a_placeholder_and_one_warning(tmp_path: Path, caplog: pytest.LogCaptureFixture
                                                             ) -> None:
    urdf = tmp_path / "r.urdf"
    urdf.write_text("""<robot name="r"><link name="base"><visual><geometry><mesh filename="meshes/gone.stl"/>
      </geometry></visual><visual><geometry><mesh filename="meshes/gone.stl"/></geometry></visual>
      <collision><geometry><mesh filename="meshes/gone.stl"/></geometry></collision></link></robot>""")
    with caplog.at_level(logging.WARNING, logger="robotmodel.viewer"):
        viewer = Viewer(load(urdf), serve=False, cache_dir=tmp_path / "cache")
    warnings = [r.getMessage() for r in caplog.records]
    assert len(warnings) == 1
    assert "link 'base'" in warnings[0] and "meshes/gone.stl" in warnings[0]
    _, objects = _decode(viewer)
    boxes = [o for p, o in objects.items() if "/base/<visual>/" in p]
    assert len(boxes) == 2 and all(b["geometries"][0]["type"] == "BoxGeometry" for b in boxes)
    out = tmp_path / "r.html"
    result = subprocess.run([sys.executable, "-m", "robotmodel.cli.main", "view", str(urdf), "--static-html", str(out)],
                            capture_output=True, text=True, timeout=120, check=False)
    assert result.returncode == 0 and out.is_file()
    assert [line for line in result.stderr.splitlines() if "gone.stl" in line] != []
    assert "Traceback" not in result.stderr


def test_sliders_follow_joint_state_publisher_gui() -> None:
    urdf = """<robot name="r"><link name="a"/><link name="b"/><link name="c"/><link name="d"/><link name="e"/>
      <joint name="wheel" type="continuous"><parent link="a"/><child link="b"/></joint>
      <joint name="lift" type="prismatic"><parent link="a"/><child link="c"/><axis xyz="0 0 1"/>
        <limit lower="0.2" upper="1.0" effort="1" velocity="1"/></joint>
      <joint name="arm" type="revolute"><parent link="a"/><child link="d"/>
        <limit lower="-2" upper="2" effort="1" velocity="1"/>
        <safety_controller k_velocity="1" soft_lower_limit="-1" soft_upper_limit="1.5"/></joint>
      <joint name="twin" type="revolute"><parent link="a"/><child link="e"/><mimic joint="arm" multiplier="2"/>
        <limit lower="-4" upper="4" effort="1" velocity="1"/></joint></robot>"""
    sliders = {s.name: s for s in slider_joints(KinematicModel(parse_urdf(urdf)))}
    assert list(sliders) == ["wheel", "lift", "arm"]
    assert (sliders["wheel"].min, sliders["wheel"].max, sliders["wheel"].zero) == (-math.pi, math.pi, 0.0)
    assert (sliders["lift"].min, sliders["lift"].max, sliders["lift"].zero) == (0.2, 1.0, pytest.approx(0.6))
    assert (sliders["arm"].min, sliders["arm"].max, sliders["arm"].zero) == (-1.0, 1.5, 0.0)


def _cli(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "robotmodel.cli.main", *args], capture_output=True, text=True,
                          timeout=120, check=False)


@pytest.mark.parametrize(("args", "needle"), [
    (["--frames", "nope"], "has no link 'nope'"),
    (["--joint", "left_wheel_joint=abc"], "'abc' is not a number"),
    (["--joint", "wheel=1"], "unknown joint 'wheel'"),
])
def test_cli_bad_input_is_one_line_and_no_file(tmp_path: Path, args: list[str], needle: str) -> None:
    out = tmp_path / "out.html"
    result = _cli("view", str(BUNDLED / "diffbot.urdf.xacro"), "--static-html", str(out), *args)
    assert result.returncode == 1
    errors = [line for line in result.stderr.splitlines() if "error" in line]
    assert len(errors) == 1 and needle in errors[0], result.stderr
    assert not out.exists() and list(tmp_path.iterdir()) == []


def test_command_modules_import_nothing_heavy() -> None:
    code = ("import sys, robotmodel.cli.view_cmd, robotmodel.cli.jsp_gui_cmd; "
            "print(sorted(m for m in ('meshcat', 'trimesh', 'pinocchio', 'tornado', 'zenoh') if m in sys.modules))")
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60, check=True)
    assert result.stdout.strip() == "[]"


def test_set_description_replaces_the_robot() -> None:
    viewer = Viewer(load(ARM), serve=False, frames="all")
    viewer.set_description(load(BUNDLED / "diffbot.urdf.xacro"))
    _, objects = _decode(viewer)
    links = {p.split("/<")[0].rsplit("/", 1)[-1] for p in objects if p.startswith("/robot/")}
    assert links == {link.name for link in load(BUNDLED / "diffbot.urdf.xacro").links}
    assert [s.name for s in viewer.sliders] == ["left_wheel_joint", "right_wheel_joint"]
    viewer.display({"left_wheel_joint": 1.0})
    with pytest.raises(JointValueError, match="arm_shoulder_joint"):
        viewer.display({"arm_shoulder_joint": 1.0})


def test_collada_unit_rescales_as_rviz_does(tmp_path: Path) -> None:
    original = ERD_ROBOTS / "panda_description" / "meshes" / "visual" / "hand.dae"
    text = original.read_text()
    assert 'meter="1"' in text
    millimetres = tmp_path / "hand_mm.dae"
    millimetres.write_text(text.replace('meter="1"', 'meter="0.001"', 1))
    metres, _ = load_mesh(original, tmp_path / "cache")
    scaled, _ = load_mesh(millimetres, tmp_path / "cache")
    np.testing.assert_allclose(scaled.vertices, metres.vertices * 0.001, rtol=1e-6)


def test_obj_meshes_load_through_trimesh(tmp_path: Path) -> None:
    stl = ERD_ROBOTS / "panda_description" / "meshes" / "collision" / "link2.stl"
    obj = tmp_path / "link2.obj"
    trimesh.load(stl).export(obj)
    data, _ = load_mesh(obj, tmp_path / "cache")
    reference = trimesh.load(obj, force="mesh")
    assert len(data.faces) == len(reference.faces)
    np.testing.assert_allclose(data.vertices.min(axis=0), reference.bounds[0], rtol=1e-5, atol=1e-6)
    assert not data.own.any()  # no .mtl: the URDF colour applies


def test_collisions_toggle() -> None:
    viewer = Viewer(load(PANDA), serve=False)

    def visible() -> set[bool]:
        return {umsgpack.unpackb(c)["value"] for c in viewer.commands()
                if umsgpack.unpackb(c)["type"] == "set_property" and "<collision>" in umsgpack.unpackb(c)["path"]}

    assert visible() == {False}
    viewer.show_collisions(True)
    assert visible() == {True}


def test_a_port_in_use_is_one_line_error() -> None:
    import socket

    with socket.socket() as taken:
        taken.bind(("127.0.0.1", 0))
        taken.listen()
        port = taken.getsockname()[1]
        result = _cli("view", str(BUNDLED / "diffbot.urdf.xacro"), "--port", str(port))
    assert result.returncode == 1
    assert result.stderr == f"robotmodel view: error: cannot listen on 127.0.0.1: port {port} in use " \
                            "(Address already in use)\n"


def test_textures_become_vertex_colours(tmp_path: Path) -> None:
    dae = ERD_ROBOTS / "anymal_c_simple_description" / "meshes" / "base.dae"
    scene = trimesh.load(dae, force="scene")
    parts = [scene.geometry[scene.graph[node][1]] for node in scene.graph.nodes_geometry]
    textured = next(i for i, g in enumerate(parts) if getattr(g.visual.material, "baseColorTexture", None) is not None)
    data, _ = load_mesh(dae, tmp_path / "cache")
    start = sum(len(g.vertices) for g in parts[:textured])
    part = parts[textured]
    ours = data.colors[start:start + len(part.vertices)] * 255
    # The texture sampled by hand at each vertex's UV (nearest texel, V up).
    image = np.asarray(part.visual.material.baseColorTexture.convert("RGB"))
    h, w = image.shape[:2]
    uv = np.asarray(part.visual.uv) % 1.0
    texels = image[((1 - uv[:, 1]) * (h - 1)).round().astype(int), (uv[:, 0] * (w - 1)).round().astype(int)]
    np.testing.assert_allclose(ours.mean(axis=0), texels.mean(axis=0), atol=8)
    assert ours.mean() < 200  # not the material's plain white


def test_progress_bar_on_a_terminal(tmp_path: Path) -> None:
    import pty

    out = tmp_path / "panda.html"
    env = dict(os.environ, ROBOTMODEL_CACHE_DIR=str(tmp_path / "cache"))
    pid, fd = pty.fork()
    if pid == 0:  # the child: stdout and stderr are the terminal
        os.execve(sys.executable, [sys.executable, "-m", "robotmodel.cli.main", "view", str(PANDA),
                                   "--static-html", str(out)], env)
    chunks = []
    while True:
        try:
            data = os.read(fd, 65536)
        except OSError:  # EIO: the child closed the terminal
            break
        if not data:
            break
        chunks.append(data)
    _, status = os.waitpid(pid, 0)
    text = b"".join(chunks).decode(errors="replace")
    assert os.waitstatus_to_exitcode(status) == 0, text
    meshes = len({g.filename for link in load(PANDA).links for g in
                  [v.geometry for v in link.visuals] + [c.geometry for c in link.collisions] if hasattr(g, "filename")})
    assert f"meshes [{'#' * 30}] {meshes}/{meshes}" in text
    assert f"meshes [{'.' * 30}] 0/{meshes}" in text
    assert f"loaded {meshes} meshes (0 from the cache)" in text


def test_open_hands_the_url_to_the_users_browser(tmp_path: Path) -> None:
    import signal
    import time

    opened = tmp_path / "opened.txt"
    browser = tmp_path / "browser.py"
    browser.write_text(f"import sys, pathlib\npathlib.Path({str(opened)!r}).write_text(sys.argv[1])\n")
    env = dict(os.environ, BROWSER=f"{sys.executable} {browser} %s")
    proc = subprocess.Popen([sys.executable, "-m", "robotmodel.cli.main", "view", str(BUNDLED / "diffbot.urdf.xacro"),
                             "--port", "0", "--open"], env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            text=True)
    try:
        assert proc.stdout is not None
        url = proc.stdout.readline().strip()
        deadline = time.monotonic() + 30
        while not (opened.exists() and opened.read_text()) and time.monotonic() < deadline:
            time.sleep(0.05)
        assert opened.read_text() == url
        assert re.fullmatch(r"http://127\.0\.0\.1:\d+/", url)
    finally:
        proc.send_signal(signal.SIGINT)
        try:
            code = proc.wait(timeout=30)
        finally:
            proc.kill()  # reaped even when it did not stop
            proc.wait()
    assert code == 0


def test_normals_are_sent_unit_and_outward_and_follow_the_scale(tmp_path: Path) -> None:
    stl = ERD_ROBOTS / "panda_description" / "meshes" / "collision" / "link1.stl"
    data, _ = load_mesh(stl, tmp_path / "cache")
    np.testing.assert_allclose(np.linalg.norm(data.normals, axis=1), 1.0, atol=1e-5)
    outward = np.einsum("ij,ij->i", data.normals, data.vertices - data.vertices.mean(axis=0))
    assert (outward > 0).mean() > 0.8  # a closed, convex-ish link: normals point away from its middle
    scaled = data.scaled((2.0, 1.0, 0.5))
    # A plane n·x = 0 scaled by S has the normal S⁻¹n (normalized).
    expected = data.normals / np.array([2.0, 1.0, 0.5])
    expected /= np.linalg.norm(expected, axis=1, keepdims=True)
    np.testing.assert_allclose(scaled.normals, expected, atol=1e-5)
    urdf = f"""<robot name="r"><link name="a"><visual><geometry><mesh filename="file://{stl}"/>
      </geometry></visual></link></robot>"""
    _, objects = _decode(Viewer(parse_urdf(urdf), serve=False, cache_dir=tmp_path / "cache"))
    attributes = next(o for p, o in objects.items() if "<visual>" in p)["geometries"][0]["data"]["attributes"]
    assert set(attributes) == {"position", "normal"}


def test_screenshot_without_a_browser_is_one_line_and_no_file(tmp_path: Path) -> None:
    out = tmp_path / "shot.png"
    env = dict(os.environ, ROBOTMODEL_CHROMIUM=str(tmp_path / "no-such-chromium"))
    result = subprocess.run([sys.executable, "-m", "robotmodel.cli.main", "view", str(BUNDLED / "diffbot.urdf.xacro"),
                             "--screenshot", str(out)], env=env, capture_output=True, text=True, timeout=120,
                            check=False)
    assert result.returncode == 1, result.stderr
    errors = [line for line in result.stderr.splitlines() if "error" in line]
    assert len(errors) == 1 and "no-such-chromium" in errors[0], result.stderr
    assert "Traceback" not in result.stderr
    assert list(tmp_path.iterdir()) == []


def test_an_unwritable_output_is_one_line(tmp_path: Path) -> None:
    blocker = tmp_path / "file"
    blocker.write_text("")
    result = _cli("view", str(BUNDLED / "diffbot.urdf.xacro"), "--static-html", str(blocker / "sub" / "out.html"))
    assert result.returncode == 1
    assert result.stderr.startswith("robotmodel view: error: cannot write ") and result.stderr.count("\n") == 1
