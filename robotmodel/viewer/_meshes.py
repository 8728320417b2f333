"""Mesh files (STL, DAE, OBJ, ... through trimesh) to flat triangle arrays, cached on disk.

Conversion is the slow part of showing a big robot, so each file is converted once and
stored as a ``.npz`` keyed by its absolute path, modification time and size: a changed
file is converted again, an unchanged one is read back in about a millisecond.
"""

from __future__ import annotations

import hashlib
import logging
import os
import re
import tempfile
from pathlib import Path
from typing import Any, NamedTuple

import numpy as np
import numpy.typing as npt

__all__ = ["MeshData", "default_cache_dir", "load_mesh"]

# Bump when the stored layout or the conversion changes, so old entries are ignored.
_CACHE_VERSION = "3"
_UNIT_RE = re.compile(rb"<unit\b[^>]*\bmeter\s*=\s*\"([^\"]+)\"")


class MeshData(NamedTuple):
    """Triangles of one mesh file in its own frame, in metres.

    ``colors`` are per-vertex RGB from the file's materials; ``own`` marks the vertices
    whose part had a material (the others take the URDF colour). ``normals`` are unit
    vertex normals, computed once here so the browser does not (a tenth of a second for
    a big robot).
    """

    vertices: npt.NDArray[np.float32]
    faces: npt.NDArray[np.uint32]
    colors: npt.NDArray[np.float32]
    own: npt.NDArray[np.bool_]
    normals: npt.NDArray[np.float32]

    def scaled(self, scale: tuple[float, float, float]) -> MeshData:
        """The same mesh with URDF's per-axis ``scale`` applied."""
        if scale == (1.0, 1.0, 1.0):
            return self
        factors = np.asarray(scale, dtype=np.float32)
        # Normals transform by the inverse transpose: divide by the scale, renormalize.
        normals = self.normals / np.where(factors == 0, 1, factors)
        normals /= np.maximum(np.linalg.norm(normals, axis=1, keepdims=True), 1e-12)
        return self._replace(vertices=(self.vertices * factors).astype(np.float32),
                             normals=normals.astype(np.float32))


def default_cache_dir() -> Path:
    """``$ROBOTMODEL_CACHE_DIR``, else ``$XDG_CACHE_HOME/robotmodel/meshes``, else ``~/.cache/...``."""
    explicit = os.environ.get("ROBOTMODEL_CACHE_DIR")
    if explicit:
        return Path(explicit)
    base = os.environ.get("XDG_CACHE_HOME") or str(Path.home() / ".cache")
    return Path(base) / "robotmodel" / "meshes"


def _collada_unit(path: Path) -> float:
    # rviz rescales Collada files by their <unit meter="..."> (trimesh only records it).
    with path.open("rb") as f:
        head = f.read(65536)
    match = _UNIT_RE.search(head)
    if not match:
        return 1.0
    try:
        unit = float(match.group(1))
    except ValueError:
        return 1.0
    return unit if unit > 0.0 else 1.0


def _part_colour(mesh: Any) -> tuple[npt.NDArray[np.float32], bool]:
    """Per-vertex RGB of one trimesh part, and whether the file gave it a colour."""
    visual = mesh.visual
    n = len(mesh.vertices)
    kind = getattr(visual, "kind", None)
    if kind in {"vertex", "face"}:
        rgb = np.asarray(visual.vertex_colors, dtype=np.float32)[:, :3] / 255.0
        return rgb, True
    material = getattr(visual, "material", None)
    texture = getattr(material, "image", None)
    if texture is None:
        texture = getattr(material, "baseColorTexture", None)
    if kind == "texture" and texture is not None and getattr(visual, "uv", None) is not None:
        # Textures are baked into per-vertex colours (sampled at the UVs): an approximation,
        # but far closer than the material's plain colour (often white under a texture).
        try:
            rgb = np.asarray(visual.to_color().vertex_colors, dtype=np.float32)
            if rgb.shape[:1] == (n,) and rgb.ndim == 2:
                return rgb[:, :3] / 255.0, True
        except (ValueError, TypeError, IndexError):
            pass  # a texture trimesh cannot sample: fall back to the material's colour
    main = getattr(material, "main_color", None)
    if main is not None:
        rgb = np.asarray(main, dtype=np.float32)[:3] / 255.0
        return np.tile(rgb, (n, 1)), True
    return np.zeros((n, 3), dtype=np.float32), False


def _convert(path: Path) -> MeshData:
    import trimesh

    # trimesh logs a traceback for each texture it cannot find (e.g. a DAE's missing bump
    # map) although the geometry loads; the viewer only wants to hear about failed meshes.
    trimesh_log = logging.getLogger("trimesh")
    level = trimesh_log.level
    trimesh_log.setLevel(logging.CRITICAL)
    try:
        scene: Any = trimesh.load(str(path), force="scene")
    finally:
        trimesh_log.setLevel(level)
    vertices: list[npt.NDArray[np.float32]] = []
    faces: list[npt.NDArray[np.uint32]] = []
    colors: list[npt.NDArray[np.float32]] = []
    own: list[npt.NDArray[np.bool_]] = []
    normals: list[npt.NDArray[np.float32]] = []
    offset = 0
    for node in scene.graph.nodes_geometry:
        transform, name = scene.graph[node]
        mesh = scene.geometry[name]
        if not hasattr(mesh, "faces") or len(mesh.faces) == 0:
            continue  # point clouds and paths have no surface to draw
        v = np.asarray(mesh.vertices, dtype=np.float64)
        v = v @ transform[:3, :3].T + transform[:3, 3]
        rgb, has = _part_colour(mesh)
        vertices.append(v.astype(np.float32))
        faces.append(np.asarray(mesh.faces, dtype=np.uint32) + np.uint32(offset))
        colors.append(rgb)
        own.append(np.full(len(v), has))
        normals.append((np.asarray(mesh.vertex_normals, dtype=np.float64) @ transform[:3, :3].T).astype(np.float32))
        offset += len(v)
    if not vertices:
        raise ValueError("no triangles")
    unit = _collada_unit(path) if path.suffix.lower() == ".dae" else 1.0
    all_v = np.concatenate(vertices)
    if unit != 1.0:
        all_v = (all_v * unit).astype(np.float32)
    return MeshData(all_v, np.concatenate(faces), np.concatenate(colors), np.concatenate(own),
                    np.concatenate(normals))


def _key(path: Path) -> str:
    st = path.stat()
    text = f"{_CACHE_VERSION}|{path}|{st.st_mtime_ns}|{st.st_size}"
    return hashlib.sha256(text.encode()).hexdigest()[:32]


def _read(entry: Path) -> MeshData | None:
    try:
        with np.load(entry, allow_pickle=False) as z:
            return MeshData(z["vertices"], z["faces"], z["colors"], z["own"], z["normals"])
    except (OSError, ValueError, KeyError):
        return None  # absent, or damaged by an interrupted writer: convert again


def _write(entry: Path, data: MeshData) -> None:
    try:
        entry.parent.mkdir(parents=True, exist_ok=True)
        fd, tmp = tempfile.mkstemp(prefix=".mesh.", suffix=".npz", dir=entry.parent)
        with os.fdopen(fd, "wb") as f:
            np.savez(f, vertices=data.vertices, faces=data.faces, colors=data.colors, own=data.own,
                     normals=data.normals)
        os.replace(tmp, entry)
    except OSError:
        pass  # a read-only cache only costs speed


def load_mesh(path: str | os.PathLike[str], cache_dir: Path | None = None) -> tuple[MeshData, bool]:
    """Load the mesh file at ``path``; returns the data and whether it came from the cache.

    ``cache_dir=None`` uses :func:`default_cache_dir`. Raises ``OSError`` when the file
    cannot be read and ``ValueError`` when trimesh cannot make triangles of it.
    """
    resolved = Path(path).resolve()
    key = _key(resolved)
    entry = (cache_dir if cache_dir is not None else default_cache_dir()) / f"{key}.npz"
    cached = _read(entry)
    if cached is not None:
        return cached, True
    try:
        data = _convert(resolved)
    except OSError:
        raise
    except Exception as exc:  # trimesh raises many kinds for files it cannot parse
        raise ValueError(f"cannot read mesh: {exc}") from None
    _write(entry, data)
    return data, False
