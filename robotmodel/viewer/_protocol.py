"""meshcat's wire format: msgpack-encoded commands that its three.js viewer executes.

The browser side is meshcat's own ``main.min.js``; we build the commands here with
``umsgpack`` (a meshcat dependency) instead of importing meshcat's Python package,
which pulls in IPython and a ZMQ server process we do not use.
"""

from __future__ import annotations

import uuid
from collections.abc import Sequence
from typing import Any

import numpy as np
import numpy.typing as npt
import umsgpack

__all__ = [
    "Command",
    "box_geometry",
    "cylinder_geometry",
    "delete",
    "label_object",
    "lines_object",
    "mesh_geometry",
    "mesh_object",
    "path_of",
    "phong_material",
    "set_object",
    "set_property",
    "set_transform",
    "sphere_geometry",
]

#: One packed command, ready to send as a binary websocket message.
Command = bytes

# meshcat's msgpack extension codes for typed arrays (see its geometry.py).
_EXT_UINT32 = 0x16
_EXT_FLOAT32 = 0x17


def path_of(*parts: str) -> str:
    """A meshcat path; '/' inside a name would split it, so it becomes '|'."""
    return "/" + "/".join(p.replace("/", "|") for p in parts)


def _uid() -> str:
    return str(uuid.uuid4())


def _typed(array: npt.NDArray[Any], item_size: int) -> dict[str, Any]:
    code, name = (_EXT_UINT32, "Uint32Array") if array.dtype == np.uint32 else (_EXT_FLOAT32, "Float32Array")
    return {"itemSize": item_size, "type": name, "array": umsgpack.Ext(code, array.tobytes()), "normalized": False}


def box_geometry(size: Sequence[float]) -> dict[str, Any]:
    """three.js BoxGeometry with full side lengths x, y, z."""
    return {"uuid": _uid(), "type": "BoxGeometry", "width": float(size[0]), "height": float(size[1]),
            "depth": float(size[2])}


def sphere_geometry(radius: float) -> dict[str, Any]:
    """three.js SphereGeometry."""
    return {"uuid": _uid(), "type": "SphereGeometry", "radius": float(radius), "widthSegments": 24,
            "heightSegments": 16}


def cylinder_geometry(radius: float, length: float) -> dict[str, Any]:
    """three.js CylinderGeometry; its axis is Y, so the object's matrix turns it onto URDF's Z."""
    return {"uuid": _uid(), "type": "CylinderGeometry", "radiusTop": float(radius), "radiusBottom": float(radius),
            "height": float(length), "radialSegments": 32}


def mesh_geometry(vertices: npt.NDArray[np.float32], faces: npt.NDArray[np.uint32],
                  colors: npt.NDArray[np.float32] | None = None,
                  normals: npt.NDArray[np.float32] | None = None) -> dict[str, Any]:
    """An indexed BufferGeometry; ``colors`` are per-vertex RGB in 0..1, ``normals`` unit vectors.

    Without normals meshcat's viewer computes them in the browser.
    """
    attributes = {"position": _typed(np.ascontiguousarray(vertices, dtype=np.float32), 3)}
    if normals is not None:
        attributes["normal"] = _typed(np.ascontiguousarray(normals, dtype=np.float32), 3)
    if colors is not None:
        attributes["color"] = _typed(np.ascontiguousarray(colors, dtype=np.float32), 3)
    return {"uuid": _uid(), "type": "BufferGeometry",
            "data": {"attributes": attributes, "index": _typed(np.ascontiguousarray(faces, dtype=np.uint32), 1)}}


def phong_material(rgba: Sequence[float], *, vertex_colors: bool = False, wireframe: bool = False) -> dict[str, Any]:
    """A lit material; alpha below 1 makes it transparent."""
    r, g, b, a = (min(1.0, max(0.0, float(c))) for c in rgba)
    color = (round(r * 255) << 16) | (round(g * 255) << 8) | round(b * 255)
    return {"uuid": _uid(), "type": "MeshPhongMaterial", "color": 0xFFFFFF if vertex_colors else color,
            "reflectivity": 0.5, "side": 2, "transparent": a < 1.0, "opacity": a, "vertexColors": vertex_colors,
            "wireframe": wireframe, "shininess": 30}


_CYLINDER_TO_Z = (1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, -1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0)
_IDENTITY = (1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0)


def mesh_object(geometry: dict[str, Any], material: dict[str, Any]) -> dict[str, Any]:
    """A three.js Object JSON holding one mesh; cylinders get turned from Y onto Z."""
    matrix = _CYLINDER_TO_Z if geometry["type"] == "CylinderGeometry" else _IDENTITY
    return {
        "metadata": {"version": 4.5, "type": "Object"},
        "geometries": [geometry], "materials": [material],
        "object": {"uuid": _uid(), "type": "Mesh", "geometry": geometry["uuid"], "material": material["uuid"],
                   "matrix": list(matrix)},
    }


def lines_object(points: npt.NDArray[np.float32], colors: npt.NDArray[np.float32], width: float = 1.0
                 ) -> dict[str, Any]:
    """LineSegments through ``points`` (pairs), coloured per vertex."""
    geometry = {"uuid": _uid(), "type": "BufferGeometry", "data": {"attributes": {
        "position": _typed(np.ascontiguousarray(points, dtype=np.float32), 3),
        "color": _typed(np.ascontiguousarray(colors, dtype=np.float32), 3)}}}
    material = {"uuid": _uid(), "type": "LineBasicMaterial", "color": 0xFFFFFF, "vertexColors": True,
                "linewidth": width}
    return {"metadata": {"version": 4.5, "type": "Object"}, "geometries": [geometry], "materials": [material],
            "object": {"uuid": _uid(), "type": "LineSegments", "geometry": geometry["uuid"],
                       "material": material["uuid"], "matrix": list(_IDENTITY)}}


def label_object(text: str, height: float) -> dict[str, Any]:
    """A camera-facing text sprite (meshcat draws ``_text`` textures on a canvas)."""
    texture = {"uuid": _uid(), "type": "_text", "text": text, "font_size": 40, "font_face": "sans-serif"}
    material = {"uuid": _uid(), "type": "SpriteMaterial", "map": texture["uuid"], "transparent": True,
                "depthTest": False}
    s = float(height)
    matrix = (s, 0.0, 0.0, 0.0, 0.0, s, 0.0, 0.0, 0.0, 0.0, s, 0.0, 0.0, 0.0, 0.0, 1.0)
    return {"metadata": {"version": 4.5, "type": "Object"}, "geometries": [], "materials": [material],
            "textures": [texture], "images": [],
            "object": {"uuid": _uid(), "type": "Sprite", "material": material["uuid"], "matrix": list(matrix)}}


def set_object(path: str, obj: dict[str, Any]) -> Command:
    """Place ``obj`` at ``path`` (replacing what was there)."""
    return bytes(umsgpack.packb({"type": "set_object", "path": path, "object": obj}))


def set_transform(path: str, matrix: npt.NDArray[np.float64]) -> Command:
    """Set the local transform of ``path`` from a 4×4 homogeneous matrix."""
    column_major = np.asarray(matrix, dtype=np.float32).T.reshape(16)
    return bytes(umsgpack.packb({"type": "set_transform", "path": path,
                                 "matrix": umsgpack.Ext(_EXT_FLOAT32, column_major.tobytes())}))


def set_property(path: str, name: str, value: Any) -> Command:
    """Set a property (``visible``, ``color``, ...) of the object at ``path``."""
    return bytes(umsgpack.packb({"type": "set_property", "path": path, "property": name, "value": value}))


def delete(path: str) -> Command:
    """Remove ``path`` and everything under it."""
    return bytes(umsgpack.packb({"type": "delete", "path": path}))
