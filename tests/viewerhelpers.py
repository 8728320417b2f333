"""Helpers for the viewer's browser tests: where the robot projects, and what colour is there.

The expected positions come from our FK (checked against Pinocchio and yourdfpy elsewhere)
and trimesh's bounds of the mesh files; the page only supplies its camera matrices.
"""

from __future__ import annotations

import io
import socket
from pathlib import Path

import numpy as np
import trimesh
from PIL import Image

from robotmodel.kinematics import KinematicModel, KinematicState
from robotmodel.model import Box, Cylinder, Mesh, RobotDescription, Sphere
from robotmodel.resources import resolve_uri
from robotmodel.spatial import rpy_to_matrix
from robotmodel.viewer import Browser

# What the page exposes once the scene is in and drawn.
READY = "window.robotmodel && window.robotmodel.synced > 0 && window.robotmodel.renders > 0"
MESH_COUNT = "(() => { let n = 0; viewer.scene.traverse(o => { if (o.isMesh && o.visible) n++; }); return n; })()"
HIDE_HELPERS = """(() => { viewer.set_property(["Grid"], "visible", false);
  viewer.set_property(["Axes"], "visible", false); viewer.render(); return true; })()"""
CAMERA = """(() => { const c = viewer.camera; c.updateWorldMatrix(true, false); c.matrixWorldInverse.copy(c.matrixWorld).invert(); const r = viewer.renderer.domElement;
  const b = r.getBoundingClientRect();
  const root = viewer.scene_tree.find(["robot"]).object; root.updateWorldMatrix(true, false);
  return {root: Array.from(root.matrixWorld.elements), view: Array.from(c.matrixWorldInverse.elements), proj: Array.from(c.projectionMatrix.elements),
          left: b.left, top: b.top, width: b.width, height: b.height}; })()"""


def png_pixels(png: bytes) -> np.ndarray:
    """RGB array (H, W, 3) of a PNG."""
    return np.asarray(Image.open(io.BytesIO(png)).convert("RGB")).astype(int)


def is_robot_grey(rgb: np.ndarray) -> np.ndarray:
    """Grey, white or black: every robot material used here; meshcat's sky gradient never is."""
    return (rgb.max(axis=-1) - rgb.min(axis=-1)) < 40


def _geometry_centre(desc: RobotDescription, geometry: object, base: Path) -> np.ndarray:
    if isinstance(geometry, Mesh):
        path = resolve_uri(geometry.filename.replace("package:///", "package://"), base_dir=base)
        bounds = trimesh.load(str(path), force="scene").bounds
        return np.asarray(bounds).mean(axis=0) * np.asarray(geometry.scale)
    if isinstance(geometry, Box | Cylinder | Sphere):
        return np.zeros(3)
    raise TypeError(geometry)


def grey_points(desc: RobotDescription, positions: dict[str, float], *, limit: int = 12) -> list[np.ndarray]:
    """World points at the centres of visuals the URDF colours grey (or leaves to the mesh)."""
    state = KinematicState(KinematicModel(desc)).update(positions)
    named = {m.name: m.color for m in desc.materials}
    base = Path(desc.source).parent if desc.source else Path.cwd()
    points = []
    for link in desc.links:
        for visual in link.visuals:
            color = None
            if visual.material is not None:
                color = visual.material.color or named.get(visual.material.name)
            if color is not None and max(color[:3]) - min(color[:3]) > 0.15:
                continue  # coloured: not a grey point
            local = np.eye(4)
            local[:3, :3] = rpy_to_matrix(np.asarray(visual.origin.rpy))
            local[:3, 3] = visual.origin.xyz
            world = state.link_matrix(link.name)
            centre = world @ local @ np.append(_geometry_centre(desc, visual.geometry, base), 1.0)
            points.append(centre[:3])
    step = max(1, len(points) // limit)
    return points[::step][:limit]


def project(camera: dict, point: np.ndarray) -> tuple[int, int] | None:
    """Pixel (x, y) of a world point through the page's camera; None when behind it or off the canvas."""
    view = np.asarray(camera["view"]).reshape(4, 4).T
    proj = np.asarray(camera["proj"]).reshape(4, 4).T
    # meshcat's own frame change between its scene (Z-up) and three.js's world (Y-up).
    root = np.asarray(camera["root"]).reshape(4, 4).T
    clip = proj @ view @ root @ np.append(point, 1.0)
    if clip[3] <= 0:
        return None
    ndc = clip[:3] / clip[3]
    x = camera["left"] + (ndc[0] + 1) / 2 * camera["width"]
    y = camera["top"] + (1 - ndc[1]) / 2 * camera["height"]
    if not (camera["left"] <= x < camera["left"] + camera["width"] and 0 <= y < camera["height"]):
        return None
    return int(x), int(y)


def robot_fraction(browser: Browser, png: bytes, points: list[np.ndarray]) -> tuple[float, float]:
    """(share of projected points on robot-grey pixels, share of the image's corners that are grey)."""
    camera = browser.evaluate(CAMERA)
    rgb = png_pixels(png)
    hits = []
    for point in points:
        pixel = project(camera, point)
        if pixel is None:
            continue
        x, y = pixel
        patch = rgb[max(0, y - 1):y + 2, max(0, x - 1):x + 2]
        hits.append(bool(is_robot_grey(patch).mean() >= 0.5))
    left, top = int(camera["left"]), int(camera["top"])
    w, h = int(camera["width"]), int(camera["height"])
    # (meshcat's "Open Controls" bar covers the top right corner)
    corners = [rgb[top + 5, left + 5], rgb[top + h // 2, left + w - 6], rgb[top + h - 6, left + 5],
               rgb[top + h - 6, left + w - 6]]
    assert hits, "no visual projects into the canvas"
    return float(np.mean(hits)), float(np.mean([is_robot_grey(c) for c in corners]))


def loopback_only(pid: int) -> list[str]:
    """Addresses the process listens on (TCP listeners and bound UDP sockets, IPv4 and IPv6), from /proc."""
    inodes = set()
    for fd in Path(f"/proc/{pid}/fd").iterdir():
        try:
            target = str(fd.readlink())
        except OSError:
            continue
        if target.startswith("socket:["):
            inodes.add(target[8:-1])
    found = []
    tables = (("tcp", socket.AF_INET), ("tcp6", socket.AF_INET6), ("udp", socket.AF_INET), ("udp6", socket.AF_INET6))
    for table, family in tables:
        lines = Path(f"/proc/{pid}/net/{table}").read_text().splitlines()[1:]
        for line in lines:
            fields = line.split()
            local, state, inode = fields[1], fields[3], fields[9]
            # TCP: sockets in LISTEN (0A); UDP: every bound socket receives.
            if inode not in inodes or (table.startswith("tcp") and state != "0A"):
                continue
            addr_hex, port_hex = local.split(":")
            raw = bytes.fromhex(addr_hex)
            if family == socket.AF_INET:
                addr = socket.inet_ntop(family, raw[::-1])
            else:
                addr = socket.inet_ntop(family, b"".join(raw[i:i + 4][::-1] for i in range(0, 16, 4)))
            found.append(f"{addr}:{int(port_hex, 16)}")
    return found
