"""See the robot: meshcat's browser viewer with meshes, joint sliders and TF frames.

- :class:`Viewer`: build a robot's scene (meshes converted once and cached on disk), serve
  it with a joint slider panel on 127.0.0.1, move joints with :meth:`Viewer.display`
  (redrawn at most 30 times a second, coalescing to the latest), show link frames
  (:meth:`Viewer.show_frames`) and TF frames (:meth:`Viewer.show_tf`), swap the robot
  (:meth:`Viewer.set_description`), export a self-contained page (:meth:`Viewer.static_html`),
  place the camera (:meth:`Viewer.set_camera`) or have it follow a point (:meth:`Viewer.track`).
- :class:`LiveViewer`: a Viewer fed from the bus, as rviz's RobotModel and TF displays
  (robot from ``/robot_description``, joints from ``/joint_states``, frames from ``/tf``)
  or joint_state_publisher_gui (sliders published on ``/joint_states``).
- :func:`run_view`, :func:`run_joint_state_publisher_gui`, :func:`serve_live`: the
  ``robotmodel view`` and ``joint-state-publisher-gui`` programs, from a :class:`ViewOptions`
  (:func:`build_viewer`, :func:`camera_spec`, :func:`frames_spec`, :func:`size_spec` read its texts).
- :func:`screenshot` / :func:`screenshot_html`: render a page in headless Chromium to PNG.
- :func:`build_scene`, :func:`load_mesh`: the scene as meshcat commands; one mesh file as
  triangle arrays (through the cache).
- :class:`Browser`: a small DevTools-protocol driver for headless Chromium.
"""

from __future__ import annotations

from robotmodel.errors import ViewerError
from robotmodel.viewer._browser import Browser, find_chromium
from robotmodel.viewer._live import LiveViewer, serve_live
from robotmodel.viewer._meshes import MeshData, default_cache_dir, load_mesh
from robotmodel.viewer._options import ViewOptions, build_viewer, camera_spec, frames_spec, size_spec
from robotmodel.viewer._program import run_joint_state_publisher_gui, run_view
from robotmodel.viewer._scene import RobotScene, build_scene
from robotmodel.viewer._screenshot import screenshot, screenshot_html
from robotmodel.viewer._sliders import SliderJoint, slider_joints
from robotmodel.viewer._viewer import FramesSpec, JointCallback, Viewer

__all__ = [
    "Browser",
    "FramesSpec",
    "JointCallback",
    "LiveViewer",
    "MeshData",
    "RobotScene",
    "SliderJoint",
    "ViewOptions",
    "Viewer",
    "ViewerError",
    "build_scene",
    "build_viewer",
    "camera_spec",
    "default_cache_dir",
    "find_chromium",
    "frames_spec",
    "load_mesh",
    "run_joint_state_publisher_gui",
    "run_view",
    "screenshot",
    "screenshot_html",
    "serve_live",
    "size_spec",
    "slider_joints",
]
