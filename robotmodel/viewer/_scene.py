"""The robot as a meshcat scene tree that mirrors its kinematic tree.

Each link is a group nested in its parent link's group; the group's transform is the
joint's T_parent_child, so moving a joint sets exactly one transform. Under each link:

- ``<visual>/<i>`` and ``<collision>/<i>``: the geometry, placed by its ``<origin>``;
- ``<frame>``: an axis triad (x red, y green, z blue) with the link's name, created by
  the viewer the first time the link's frame is shown (labels are canvas textures, which
  cost the browser time for every link of a big robot).
"""

from __future__ import annotations

import logging
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
import numpy.typing as npt

from robotmodel.errors import RobotModelError
from robotmodel.kinematics import KinematicModel, KinematicState
from robotmodel.model import Box, Cylinder, Geometry, Mesh, Pose, RobotDescription, Sphere
from robotmodel.spatial import rpy_to_matrix
from robotmodel.viewer import _protocol as wire
from robotmodel.viewer._materials import COLLISION_RGBA, DEFAULT_RGBA, PLACEHOLDER_RGBA, visual_rgba
from robotmodel.viewer._meshes import MeshData, load_mesh
from robotmodel.viewer._resolve import resolve_mesh_uri

__all__ = ["ProgressFn", "RobotScene", "build_scene", "camera_position", "frame_objects", "origin_matrix"]

log = logging.getLogger("robotmodel.viewer")

#: Called as ``progress(done, total, label)`` while meshes load.
ProgressFn = Callable[[int, int, str], None]

ROOT = "robot"
_PLACEHOLDER_SIZE = (0.05, 0.05, 0.05)


def camera_position(model: KinematicModel) -> list[float]:
    """Where meshcat's camera starts so the robot (at its default pose) fills the view."""
    state = KinematicState(model).update(model.default_positions())
    points = np.array([state.link_pose(n).translation for n in model.link_names])
    radius = float(np.max(np.linalg.norm(points, axis=1))) + 0.2
    distance = max(0.6, 1.5 * radius)
    direction = np.array([1.0, 0.55, 0.9])  # three.js is Y-up under meshcat's "rotated" camera node
    return [float(x) for x in direction / np.linalg.norm(direction) * distance]


def origin_matrix(origin: Pose) -> npt.NDArray[np.float64]:
    """The 4×4 matrix of a URDF ``<origin>``."""
    m = np.eye(4)
    m[:3, :3] = rpy_to_matrix(np.asarray(origin.rpy, dtype=np.float64))
    m[:3, 3] = origin.xyz
    return m


@dataclass
class RobotScene:
    """Everything the browser needs to draw the robot, as packed meshcat commands."""

    link_paths: dict[str, str]
    #: (path, packed set_object) in drawing order.
    objects: list[tuple[str, bytes]] = field(default_factory=list)
    #: Transforms that never change: geometry origins.
    transforms: dict[str, bytes] = field(default_factory=dict)
    #: Initial visibility: collision groups start hidden.
    properties: dict[tuple[str, str], bytes] = field(default_factory=dict)
    #: One message per mesh that could not be loaded.
    warnings: list[str] = field(default_factory=list)
    meshes_loaded: int = 0
    meshes_cached: int = 0

    def group(self, link: str, kind: str) -> str:
        """Path of a link's ``visual``, ``collision`` or ``frame`` group."""
        return f"{self.link_paths[link]}/<{kind}>"


def _link_paths(desc: RobotDescription) -> dict[str, str]:
    paths = {desc.root: wire.path_of(ROOT, desc.root)}
    for _, joint in desc.walk():
        paths[joint.child] = paths[joint.parent] + wire.path_of(joint.child)
    return paths


class _MeshLoader:
    """Loads each distinct mesh file once, reporting progress."""

    def __init__(self, desc: RobotDescription, package_paths: list[str], cache_dir: Path | None,
                 progress: ProgressFn | None) -> None:
        self.base = Path(desc.source).parent if desc.source else Path.cwd()
        self.package_paths = package_paths
        self.cache_dir = cache_dir
        self.progress = progress
        self.loaded: dict[str, MeshData | str] = {}
        self.packages: dict[str, Path] = {}
        self.cached = 0

    def preload(self, uris: list[str]) -> None:
        todo = list(dict.fromkeys(uris))
        for i, uri in enumerate(todo):
            if self.progress:
                self.progress(i, len(todo), uri.rsplit("/", 1)[-1])
            self.loaded[uri] = self._load(uri)
        if self.progress:
            self.progress(len(todo), len(todo), "")

    def _resolve(self, uri: str) -> Path:
        # One package search per package, not per mesh: a big robot names dozens of files.
        if uri.startswith("package://"):
            package, sep, rest = uri[len("package://"):].lstrip("/").partition("/")
            if package and sep:
                if package not in self.packages:
                    self.packages[package] = resolve_mesh_uri(f"package://{package}/", self.base, self.package_paths)
                return self.packages[package] / rest
        return resolve_mesh_uri(uri, self.base, self.package_paths)

    def _load(self, uri: str) -> MeshData | str:
        try:
            path = self._resolve(uri)
        except RobotModelError as exc:
            return str(exc)
        try:
            data, hit = load_mesh(path, self.cache_dir)
        except OSError as exc:
            return f"{path}: {exc.strerror or exc}"
        except ValueError as exc:
            return f"{path}: {exc}"
        self.cached += hit
        return data


def _primitive(geometry: Geometry) -> dict[str, Any]:
    if isinstance(geometry, Box):
        return wire.box_geometry(geometry.size)
    if isinstance(geometry, Cylinder):
        return wire.cylinder_geometry(geometry.radius, geometry.length)
    if isinstance(geometry, Sphere):
        return wire.sphere_geometry(geometry.radius)
    raise TypeError(geometry)


def _mesh_object(data: MeshData, rgba: tuple[float, float, float, float]) -> dict[str, Any]:
    if not data.own.any():
        return wire.mesh_object(wire.mesh_geometry(data.vertices, data.faces, normals=data.normals),
                                wire.phong_material(rgba))
    colors = data.colors
    if not data.own.all():
        colors = colors.copy()
        colors[~data.own] = rgba[:3]
    material = wire.phong_material((1.0, 1.0, 1.0, rgba[3]), vertex_colors=True)
    return wire.mesh_object(wire.mesh_geometry(data.vertices, data.faces, colors, data.normals), material)


def _triad(size: float) -> dict[str, Any]:
    points = np.array([[0, 0, 0], [size, 0, 0], [0, 0, 0], [0, size, 0], [0, 0, 0], [0, 0, size]], np.float32)
    colors = np.array([[1, 0, 0], [1, 0, 0], [0, 0.8, 0], [0, 0.8, 0], [0, 0, 1], [0, 0, 1]], np.float32)
    return wire.lines_object(points, colors, width=2.0)


def build_scene(desc: RobotDescription, *, package_paths: list[str] | None = None, cache_dir: Path | None = None,
                progress: ProgressFn | None = None, frame_size: float = 0.1) -> RobotScene:
    """Build the scene of ``desc``: geometry and colours (joints at their origin).

    A mesh that cannot be resolved or read becomes a magenta placeholder box and one
    warning (logged on ``robotmodel.viewer``) naming the link and the path.
    """
    scene = RobotScene(link_paths=_link_paths(desc))
    loader = _MeshLoader(desc, list(package_paths or ()), cache_dir, progress)
    geometries = [v.geometry for link in desc.links for v in link.visuals]
    geometries += [c.geometry for link in desc.links for c in link.collisions]
    loader.preload([g.filename for g in geometries if isinstance(g, Mesh)])
    named = {m.name: m for m in desc.materials}
    warned: set[tuple[str, str]] = set()
    for link in desc.links:
        if link.name not in scene.link_paths:
            continue  # not connected to the root: nothing places it
        elements = [("visual", v.geometry, v.origin, visual_rgba(desc, v, named) or DEFAULT_RGBA)
                    for v in link.visuals]
        elements += [("collision", c.geometry, c.origin, COLLISION_RGBA) for c in link.collisions]
        counters = {"visual": 0, "collision": 0}
        for kind, geometry, origin, rgba in elements:
            path = f"{scene.group(link.name, kind)}/{counters[kind]}"
            counters[kind] += 1
            if isinstance(geometry, Mesh):
                data = loader.loaded[geometry.filename]
                if isinstance(data, str):
                    obj = wire.mesh_object(wire.box_geometry(_PLACEHOLDER_SIZE), wire.phong_material(PLACEHOLDER_RGBA))
                    if (link.name, geometry.filename) not in warned:
                        warned.add((link.name, geometry.filename))
                        message = (f"link '{link.name}': cannot load mesh '{geometry.filename}' ({data}); "
                                   "drawing a placeholder box")
                        scene.warnings.append(message)
                        log.warning("%s", message)
                else:
                    obj = _mesh_object(data.scaled(geometry.scale), rgba)
            else:
                obj = wire.mesh_object(_primitive(geometry), wire.phong_material(rgba))
            scene.objects.append((path, wire.set_object(path, obj)))
            if origin != Pose():
                scene.transforms[path] = wire.set_transform(path, origin_matrix(origin))
        collision = scene.group(link.name, "collision")
        scene.properties[(collision, "visible")] = wire.set_property(collision, "visible", False)
    scene.meshes_loaded = sum(1 for d in loader.loaded.values() if not isinstance(d, str))
    scene.meshes_cached = loader.cached
    return scene


def frame_objects(path: str, name: str, size: float) -> list[tuple[str, bytes, bytes | None]]:
    """Commands drawing a named triad under ``path``: (sub-path, set_object, set_transform or None)."""
    offset = np.eye(4)
    offset[:3, 3] = (0.0, 0.0, size * 0.3)
    label = f"{path}/label"
    return [(f"{path}/axes", wire.set_object(f"{path}/axes", _triad(size)), None),
            (label, wire.set_object(label, wire.label_object(name, size * 3.0)), wire.set_transform(label, offset))]
