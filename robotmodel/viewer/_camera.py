"""Where meshcat's camera stands and what it looks at, in the scene's own (Z-up) coordinates.

meshcat's camera orbits the target of three.js's OrbitControls, which its command set
cannot move (translating ``/Cameras/default`` moves the camera but it keeps looking at
the origin). So the camera's position travels as meshcat's own ``position`` property,
which late-joining pages receive with the scene, and the target as a panel message that
the page applies to ``viewer.controls.target``. Both are sent in three.js's Y-up world,
which is the camera node's frame too: meshcat's scene rotation and the camera's
``rotated`` node cancel out.
"""

from __future__ import annotations

import threading
from collections.abc import Callable, Sequence
from typing import Any

import numpy as np
import numpy.typing as npt

from robotmodel.viewer import _protocol as wire
from robotmodel.viewer._scene import ROOT
from robotmodel.viewer._server import SceneStore, ViewerServer

__all__ = ["CAMERA", "Camera", "CameraControls", "from_three", "to_three"]

#: meshcat's default camera object, whose ``position`` property places it.
CAMERA = "/Cameras/default/rotated/<object>"


def to_three(point: Sequence[float] | npt.NDArray[np.float64]) -> list[float]:
    """A Z-up scene point in three.js's Y-up world: (x, y, z) → (x, z, −y)."""
    x, y, z = (float(v) for v in point)
    return [x, z, -y + 0.0]  # + 0.0: no -0.0 in what the page reports


def _point(value: npt.ArrayLike, what: str) -> npt.NDArray[np.float64]:
    point = np.asarray(value, dtype=np.float64).reshape(-1)
    if point.shape != (3,) or not np.all(np.isfinite(point)):
        raise ValueError(f"{what} must be three finite numbers, got {value!r}")
    return point


def from_three(point: Sequence[float]) -> list[float]:
    """A three.js Y-up point in the Z-up scene: (x, y, z) → (x, −z, y)."""
    x, y, z = (float(v) for v in point)
    return [x, -z + 0.0, y]


class Camera:
    """The camera's position and target in scene coordinates (metres, the fixed frame)."""

    def __init__(self, position: Sequence[float], target: Sequence[float] = (0.0, 0.0, 0.0)) -> None:
        self.position = np.array(position, dtype=np.float64)
        self.target = np.array(target, dtype=np.float64)

    def place(self, position: npt.ArrayLike | None, target: npt.ArrayLike | None) -> bool:
        """Set the position and/or the target; what is not given stays. True (it may have moved)."""
        if position is not None:
            self.position = _point(position, "camera position")
        if target is not None:
            self.target = _point(target, "camera target")
        return True

    def follow(self, target: npt.ArrayLike) -> bool:
        """Move the target to ``target`` and the camera with it (same offset); False if it did not move."""
        new = _point(target, "camera target")
        if np.array_equal(new, self.target):
            return False
        self.position = self.position + (new - self.target)
        self.target = new
        return True

    def position_command(self) -> bytes:
        """The meshcat command placing the camera (kept in the scene store for new pages)."""
        return wire.set_property(CAMERA, "position", to_three(self.position))

    def message(self, *, absolute: bool) -> dict[str, Any]:
        """The panel message for the page.

        ``absolute`` sets position and target; otherwise the page moves its camera along with
        the target, keeping whatever orbit and zoom its user chose.
        """
        message: dict[str, Any] = {"type": "camera", "target": to_three(self.target)}
        if absolute:
            message["position"] = to_three(self.position)
        return message


class CameraControls:
    """The :class:`Viewer`'s camera methods, and where it puts the robot in the scene.

    The viewer provides the lock, the scene store, the server and ``_send``.
    """

    _lock: threading.Lock
    _store: SceneStore
    _server: ViewerServer | None
    _camera: Camera | None

    def _send(self, commands: list[bytes]) -> None:
        raise NotImplementedError

    @property
    def camera(self) -> tuple[tuple[float, ...], tuple[float, ...]]:
        """The camera's (position, target) in scene coordinates (the fixed frame's, Z up)."""
        with self._lock:
            assert self._camera is not None
            return tuple(map(float, self._camera.position)), tuple(map(float, self._camera.target))

    def set_camera(self, position: npt.ArrayLike | None = None, target: npt.ArrayLike | None = None) -> None:
        """Put the camera at ``position`` looking at ``target`` (scene x, y, z; None keeps that part)."""
        self._update_camera(lambda cam: cam.place(position, target), absolute=True)

    def track(self, target: npt.ArrayLike) -> None:
        """Move the camera's target to ``target`` and the camera with it (keeping each page's orbit and zoom)."""
        self._update_camera(lambda cam: cam.follow(target), absolute=False)

    def _update_camera(self, change: Callable[[Camera], bool], *, absolute: bool) -> None:
        with self._lock:
            assert self._camera is not None
            if not change(self._camera):
                return
            self._store.properties[(CAMERA, "position")] = self._camera.position_command()
            message = self._camera.message(absolute=absolute)
        server = self._server
        if server is not None:
            server.call_soon(lambda: server.broadcast_text(message))

    def place_robot(self, pose: npt.ArrayLike) -> None:
        """Put the robot's root at ``pose`` (4×4) in the scene: rviz's fixed frame is then not the root."""
        path = wire.path_of(ROOT)
        command = wire.set_transform(path, np.asarray(pose, dtype=np.float64))
        with self._lock:
            if self._store.transforms.get(path) == command:
                return
            self._store.transforms[path] = command
        self._send([command])
