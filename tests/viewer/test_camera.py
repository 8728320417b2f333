"""The viewer's camera: ``--camera`` parsing and errors, ``track`` keeping the offset, and in Chromium
the page's camera standing where asked with the target drawn at the middle of the canvas.

The expected pixel comes from the page's own camera matrices (projected here with numpy), and
the scene's frame from the page's scene root, so the Z-up/Y-up conversion is checked, not assumed.
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from conftest import BUNDLED
from viewerhelpers import CAMERA, READY, project

from robotmodel.errors import RobotModelError
from robotmodel.model import load
from robotmodel.viewer import Browser, Viewer, camera_spec

DIFFBOT = BUNDLED / "diffbot.urdf.xacro"
VIEW = [sys.executable, "-m", "robotmodel.cli.main", "view"]


@pytest.mark.parametrize(("text", "expected"), [
    ("1,2,3", ((1.0, 2.0, 3.0), (0.0, 0.0, 0.0))),
    ("-0.6,-0.45,0.4:0,0,0", ((-0.6, -0.45, 0.4), (0.0, 0.0, 0.0))),
    ("4, 5.5 ,-6:1e-1,2,3", ((4.0, 5.5, -6.0), (0.1, 2.0, 3.0))),
])
def test_camera_spec_parses_position_and_target(text: str, expected: tuple) -> None:
    assert camera_spec(text) == expected


@pytest.mark.parametrize(("text", "message"), [
    ("1,2", "--camera expects X,Y,Z or X,Y,Z:TX,TY,TZ (metres), got '1,2'"),
    ("1,2,3:4,5", "got '1,2,3:4,5'"),
    ("1,2,3:4,5,6:7,8,9", "got '1,2,3:4,5,6:7,8,9'"),
    ("a,b,c", "got 'a,b,c'"),
    ("1,2,nan", "got '1,2,nan'"),
    ("1,inf,2", "got '1,inf,2'"),
    ("", "got ''"),
    ("1,2,3:1,2,3", "--camera 1,2,3:1,2,3: the camera cannot stand on the point it looks at"),
    ("0,0,0", "the camera cannot stand on the point it looks at"),
])
def test_camera_spec_rejects_bad_values(text: str, message: str) -> None:
    with pytest.raises(RobotModelError) as info:
        camera_spec(text)
    assert message in str(info.value)


def test_bad_camera_and_track_are_one_line_errors_with_no_file(tmp_path: Path) -> None:
    out = tmp_path / "x.html"
    for args, text in (([str(DIFFBOT), "--camera=1,2", "--static-html", str(out)], "--camera expects"),
                       ([str(DIFFBOT), "--track", "base_link", "--static-html", str(out)], "--track needs --tf")):
        done = subprocess.run([*VIEW, *args], capture_output=True, text=True, timeout=120, check=False)
        assert done.returncode != 0
        assert done.stderr.strip().count("\n") == 0 and text in done.stderr, done.stderr
    assert list(tmp_path.iterdir()) == []


def test_track_moves_the_camera_with_its_target() -> None:
    viewer = Viewer(load(DIFFBOT), serve=False)
    viewer.set_camera((-0.6, -0.45, 0.4), (0.0, 0.0, 0.0))
    viewer.track((2.0, 1.0, 0.1))
    viewer.track((3.0, -1.0, 0.1))
    position, target = viewer.camera
    assert target == (3.0, -1.0, 0.1)
    np.testing.assert_allclose(np.subtract(position, target), (-0.6, -0.45, 0.4), atol=1e-12)
    viewer.set_camera(target=(0.0, 0.0, 0.0))  # the position stays
    assert viewer.camera == (position, (0.0, 0.0, 0.0))
    with pytest.raises(ValueError, match="camera target"):
        viewer.track((1.0, 2.0))


def test_page_camera_stands_where_asked_and_looks_at_the_target(tmp_path: Path) -> None:
    position, target = (2.0, -3.0, 1.5), (0.5, 0.2, 0.1)
    viewer = Viewer(load(DIFFBOT), serve=False)
    viewer.set_camera(position, target)
    page = tmp_path / "camera.html"
    page.write_text(viewer.static_html())
    with Browser(width=800, height=600, timeout=60) as browser:
        browser.navigate(page.as_uri())
        browser.wait_for(READY, timeout=60)
        seen = browser.evaluate("""(() => { viewer.render(); const s = viewer.scene; s.updateMatrixWorld(true);
            const p = new MeshCat.THREE.Vector3(); viewer.camera.getWorldPosition(p);
            p.applyMatrix4(s.matrixWorld.clone().invert()); return p.toArray(); })()""")
        camera = browser.evaluate(CAMERA)
    np.testing.assert_allclose(seen, position, atol=1e-5)  # in the scene's (Z-up) frame
    # ``project`` maps scene points through the robot's root, which is the identity here.
    np.testing.assert_allclose(np.asarray(camera["root"]).reshape(4, 4).T[:3, 3], 0.0, atol=1e-9)
    x, y = project(camera, np.array(target))  # type: ignore[misc]
    assert abs(x - (camera["left"] + camera["width"] / 2)) <= 1
    assert abs(y - (camera["top"] + camera["height"] / 2)) <= 1
    # A point beside the target is not at the centre: the check can fail.
    x2, _ = project(camera, np.add(target, (0.5, 0.0, 0.0)))  # type: ignore[misc]
    assert abs(x2 - (camera["left"] + camera["width"] / 2)) > 20
