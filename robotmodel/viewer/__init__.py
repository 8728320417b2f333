"""See the robot: meshcat's browser viewer with meshes, joint sliders and TF frames.

- :class:`Viewer`: build a robot's scene (meshes converted once and cached on disk), serve
  it with a joint slider panel on 127.0.0.1, move joints with :meth:`Viewer.display`
  (redrawn at most 30 times a second, coalescing to the latest), show link frames
  (:meth:`Viewer.show_frames`) and TF frames (:meth:`Viewer.show_tf`), swap the robot
  (:meth:`Viewer.set_description`), export a self-contained page (:meth:`Viewer.static_html`),
  place the camera (:meth:`Viewer.set_camera`) or have it follow a point (:meth:`Viewer.track`).
- :func:`screenshot` / :func:`screenshot_html`: render a page in headless Chromium to PNG.
- :func:`build_scene`, :func:`load_mesh`: the scene as meshcat commands; one mesh file as
  triangle arrays (through the cache).
- :class:`Browser`: a small DevTools-protocol driver for headless Chromium.
"""

from __future__ import annotations

from robotmodel.errors import ViewerError
from robotmodel.viewer._browser import Browser, find_chromium
from robotmodel.viewer._meshes import MeshData, default_cache_dir, load_mesh
from robotmodel.viewer._scene import RobotScene, build_scene
from robotmodel.viewer._screenshot import screenshot, screenshot_html
from robotmodel.viewer._sliders import SliderJoint, slider_joints
from robotmodel.viewer._viewer import FramesSpec, JointCallback, Viewer

__all__ = [
    "Browser",
    "FramesSpec",
    "JointCallback",
    "MeshData",
    "RobotScene",
    "SliderJoint",
    "Viewer",
    "ViewerError",
    "build_scene",
    "default_cache_dir",
    "find_chromium",
    "load_mesh",
    "screenshot",
    "screenshot_html",
    "slider_joints",
]
