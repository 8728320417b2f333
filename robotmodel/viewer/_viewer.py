"""The :class:`Viewer`: a robot in meshcat's browser viewer, with sliders, frames and static export."""

from __future__ import annotations

import math
import threading
import time
import webbrowser
from collections.abc import Callable, Iterable, Mapping
from pathlib import Path
from typing import Any

import numpy as np
import numpy.typing as npt

from robotmodel.errors import UnknownLinkError
from robotmodel.kinematics import KinematicModel, joint_transforms, static_transforms
from robotmodel.model import JointType, RobotDescription
from robotmodel.viewer import _protocol as wire
from robotmodel.viewer._camera import CAMERA, Camera, CameraControls, from_three, to_three
from robotmodel.viewer._scene import ROOT, ProgressFn, build_scene, camera_position, frame_objects, origin_matrix
from robotmodel.viewer._server import SceneStore, ViewerServer, check_port
from robotmodel.viewer._sliders import SliderJoint, slider_joints
from robotmodel.viewer._static import static_page

__all__ = ["FramesSpec", "JointCallback", "Viewer"]

#: ``"all"``, ``"none"`` or link names.
FramesSpec = str | Iterable[str] | None
#: Called with every joint's position (sliders' values, mimics computed) when a slider moves.
JointCallback = Callable[[dict[str, float]], None]

#: Scene root of the frames drawn from /tf (beside the robot, not inside its tree).
TF_ROOT = "tf"


class Viewer(CameraControls):
    """A robot shown in meshcat's three.js viewer, served from 127.0.0.1 with a joint slider panel.

    ``serve=False`` builds the scene without a server (for :meth:`static_html` only).
    ``port=None`` tries 7000 and up; ``port=0`` takes any free port; a port outside 0..65535
    is a :class:`ViewerError`. Only the page's own origin may open its websocket; slider
    values a page sends are clamped to the sliders' ranges, as joint_state_publisher_gui's. Joint updates redraw
    at most ``max_rate`` times a second; updates in between coalesce to the latest.
    """

    def __init__(self, description: RobotDescription, *, serve: bool = True, port: int | None = None,
                 package_paths: Iterable[str] = (), cache_dir: Path | None = None,
                 progress: ProgressFn | None = None, collisions: bool = False, frames: FramesSpec = None,
                 max_rate: float = 30.0) -> None:
        if serve:
            check_port(port)  # before the scene is built: a bad port should not cost a mesh load
        self.publishing = False
        self.following = False
        self._build_options: dict[str, Any] = {"package_paths": list(package_paths), "cache_dir": cache_dir,
                                               "progress": progress}
        self._min_period = 1.0 / max_rate
        self._lock = threading.Lock()
        self._store = SceneStore()
        self._pending: tuple[dict[str, float], int | None] | None = None
        self._flush_scheduled = False
        self._last_flush = 0.0
        self._callbacks: list[JointCallback] = []
        self._frame_size = 0.1
        self._tf: dict[str, npt.NDArray[np.float64]] = {}
        self._collisions = collisions
        self._camera: Camera | None = None
        self._install(description, frames)
        self._server: ViewerServer | None = None
        if serve:
            self._server = ViewerServer(self._store, title=description.name, config=self._config,
                                        on_message=self._on_page_message, port=port)

    def _install(self, description: RobotDescription, frames: FramesSpec) -> list[bytes]:
        """Build ``description``'s scene and make it current; returns the commands that draw it."""
        model = KinematicModel(description)
        scene = build_scene(description, **self._build_options)
        with self._lock:
            self.description, self.model, self.scene = description, model, scene
            self.sliders: list[SliderJoint] = slider_joints(model)
            self._positions = {s.name: s.zero for s in self.sliders}
            self._positions.update({n: v for n, v in model.default_positions().items() if n not in self._positions})
            self._extra: dict[str, float] = {}
            self._pending = None  # positions queued for the previous robot
            self._sent: dict[str, npt.NDArray[np.float64]] = {}
            self._frames: list[str] = []
            self._frame_objects: set[str] = set()
            self._store.drop(wire.path_of(ROOT))
            self._fill_store()
            self._apply(self._positions)
            self._set_frames(frames)
            self._set_group_visibility("collision", self._collisions)
            return [wire.delete(wire.path_of(ROOT)), *self._store.commands()]

    def set_description(self, description: RobotDescription) -> None:
        """Show another robot (a new /robot_description, say): scene, sliders and pages are rebuilt."""
        names = {link.name for link in description.links}
        with self._lock:
            every = len(self._frames) == len(self.scene.link_paths)
            frames: FramesSpec = "all" if every else [n for n in self._frames if n in names]
        commands = self._install(description, frames)
        server = self._server
        if server is not None:
            server.title = description.name

            def redraw() -> None:
                server.broadcast_text({"type": "config", **self._config()})
                server.broadcast(commands)

            server.call_soon(redraw)

    # ----- building -------------------------------------------------------------------------------------------
    def _fill_store(self) -> None:
        store = self._store
        for path, command in self.scene.objects:
            store.objects[path] = command
        for (path, prop), command in self.scene.properties.items():
            store.properties[(path, prop)] = command
        store.transforms.update(self.scene.transforms)
        paths = self.scene.link_paths
        fixed = static_transforms(self.model)
        for child, matrix in zip(fixed.children, fixed.matrices(), strict=True):
            if child in paths:
                store.transforms[paths[child]] = wire.set_transform(paths[child], matrix)
        for joint in self.description.joints:
            if joint.type is JointType.FLOATING and joint.child in paths:
                store.transforms[paths[joint.child]] = wire.set_transform(paths[joint.child],
                                                                          origin_matrix(joint.origin))
        if self._camera is None:  # the first robot's default view; kept when the robot changes
            self._camera = Camera(from_three(camera_position(self.model)))
        store.properties[(CAMERA, "position")] = self._camera.position_command()

    def _config(self) -> dict[str, Any]:
        return {
            "robot": self.description.name,
            "joints": [{"name": s.name, "min": s.min, "max": s.max, "zero": s.zero,
                        "value": self._positions.get(s.name, s.zero)} for s in self.sliders],
            "mimics": [{"joint": r.joint, "master": r.master, "multiplier": r.multiplier, "offset": r.offset}
                       for r in self.model.mimics.values()],
            "collisions": self._collisions, "frames": list(self._frames),
            "publish": self.publishing, "follow": self.following,
            "camera": self._camera.message(absolute=True) if self._camera else None,
        }

    # ----- joint updates --------------------------------------------------------------------------------------
    @property
    def positions(self) -> dict[str, float]:
        """The latest position of every independent joint."""
        with self._lock:
            return dict(self._positions)

    def all_positions(self) -> dict[str, float]:
        """Every one-DoF joint's position, mimic joints computed (joint_state_publisher's message)."""
        with self._lock:
            positions = dict(self._positions)
        values = self.model.joint_values(np.array([positions[n] for n in self.model.variables]))
        names = [j.name for j in self.description.joints]
        out = {}
        for joint, value in zip(names, values, strict=True):
            if joint in positions or joint in self.model.mimics:
                out[joint] = float(value)
        return out

    def display(self, positions: Mapping[str, float] | npt.ArrayLike, *, token: int | None = None) -> None:
        """Show the robot at ``positions`` (joint name → value, or a vector in ``model.variables`` order).

        Joints not named keep their value. Values are drawn as given, not clamped (as
        robot_state_publisher does); an unknown name raises :class:`JointValueError`.
        """
        if isinstance(positions, Mapping):
            update = {str(k): float(v) for k, v in positions.items()}
            self.model.vector({k: v for k, v in update.items() if k in self.model.variables}, clamp=True)
            unknown = [k for k in update if k not in self.model.variables and k not in self.model.mimics]
            if unknown:
                self.model.vector({unknown[0]: 0.0})  # raises, naming the joint
        else:
            vector = np.asarray(positions, dtype=np.float64).reshape(-1)
            self.model.vector(vector, clamp=True)  # length and finiteness
            update = dict(zip(self.model.variables, (float(v) for v in vector), strict=True))
        with self._lock:
            self._positions.update({k: v for k, v in update.items() if k in self.model.variables})
            self._extra.update({k: v for k, v in update.items() if k in self.model.mimics})
            self._pending = (dict(self._positions), token)
            if self._server is None:
                self._apply(self._positions)
                return
        self._server.call_soon(self._schedule)

    def _schedule(self) -> None:
        if self._flush_scheduled:
            return
        delay = self._last_flush + self._min_period - time.monotonic()
        if delay <= 0:
            self._flush()
        else:
            self._flush_scheduled = True
            assert self._server is not None
            self._server.call_later(delay, self._flush)

    def _flush(self) -> None:
        self._flush_scheduled = False
        with self._lock:
            pending, self._pending = self._pending, None
            if pending is None:
                return
            commands = self._apply(pending[0])
        self._last_flush = time.monotonic()
        if self._server is not None:
            self._server.broadcast(commands, pending[1])
            if pending[1] is None:
                # Not from a slider (Python, or /joint_states): the sliders show it too.
                self._server.broadcast_text({"type": "positions", "positions": pending[0]})

    def _apply(self, positions: Mapping[str, float]) -> list[bytes]:
        """Update the stored joint transforms; returns the commands for those that changed."""
        full = dict(positions)
        full.update(self._extra)
        moved = joint_transforms(self.model, full)
        paths = self.scene.link_paths
        commands = []
        for child, matrix in zip(moved.children, moved.matrices(), strict=True):
            path = paths.get(child)
            if path is None:
                continue
            last = self._sent.get(path)
            if last is not None and np.array_equal(last, matrix):
                continue
            self._sent[path] = matrix
            command = wire.set_transform(path, matrix)
            self._store.transforms[path] = command
            commands.append(command)
        return commands

    def on_joints(self, callback: JointCallback) -> None:
        """Call ``callback(all_positions)`` whenever a page's slider moves (on the server's thread)."""
        self._callbacks.append(callback)

    def _slider_values(self, positions: dict[str, Any]) -> dict[str, float]:
        """A page's slider values, each clamped to its slider's range as joint_state_publisher_gui's are.

        Names without a slider (mimic or fixed-range joints, unknown names) and values that
        are not finite numbers are dropped: a page is any client of the socket.
        """
        ranges = {s.name: (s.min, s.max) for s in self.sliders}
        values = {}
        for name, value in positions.items():
            if name not in ranges or isinstance(value, bool) or not isinstance(value, int | float):
                continue
            try:
                number = float(value)
            except OverflowError:  # an integer past float's range: clamped like one past the limit
                number = math.inf if value > 0 else -math.inf
            if math.isnan(number):
                continue
            lo, hi = ranges[name]
            values[name] = min(max(number, lo), hi)
        return values

    def _on_page_message(self, message: dict[str, Any], sender: object = None) -> None:
        kind = message.get("type")
        if kind == "joints" and isinstance(message.get("positions"), dict):
            values = self._slider_values(message["positions"])
            token = message.get("token")
            self.display(values, token=token if isinstance(token, int) else None)
            if self._server is not None:
                # Other pages' sliders follow; the sender's are ahead of this echo already.
                self._server.broadcast_text({"type": "positions", "positions": values}, exclude=sender)
            for callback in self._callbacks:
                callback(self.all_positions())
        elif kind == "show":
            visible = bool(message.get("visible"))
            what = message.get("what")
            if what == "frames":
                self.show_frames("all" if visible else "none")
            elif what == "collisions":
                self.show_collisions(visible)
            elif what == "visuals":
                self.show_visuals(visible)

    # ----- visibility -----------------------------------------------------------------------------------------
    def _set_property_commands(self, items: list[tuple[str, bool]]) -> list[bytes]:
        commands = []
        for path, visible in items:
            command = wire.set_property(path, "visible", visible)
            self._store.properties[(path, "visible")] = command
            commands.append(command)
        return commands

    def _send(self, commands: list[bytes]) -> None:
        if self._server is not None:
            server = self._server
            server.call_soon(lambda: server.broadcast(commands))

    def _set_frames(self, frames: FramesSpec) -> list[bytes]:
        links = list(self.scene.link_paths)
        if frames is None or frames == "none":
            wanted: list[str] = []
        elif frames == "all":
            wanted = links
        else:
            names = [frames] if isinstance(frames, str) else list(frames)
            unknown = [n for n in names if n not in self.scene.link_paths]
            if unknown:
                raise UnknownLinkError(self.description.name, unknown[0])
            wanted = names
        self._frames = wanted
        chosen = set(wanted)
        commands = []
        for name in wanted:
            if name in self._frame_objects:
                continue
            self._frame_objects.add(name)
            commands += self._add_frame(self.scene.group(name, "frame"), name)
        shown = [n for n in links if n in self._frame_objects]
        return commands + self._set_property_commands([(self.scene.group(n, "frame"), n in chosen) for n in shown])

    def _add_frame(self, path: str, name: str) -> list[bytes]:
        """Store a named triad under ``path``; returns its commands (call under the lock)."""
        commands = []
        for sub, command, transform in frame_objects(path, name, self._frame_size):
            self._store.objects[sub] = command
            commands.append(command)
            if transform is not None:
                self._store.transforms[sub] = transform
                commands.append(transform)
        return commands

    def show_frames(self, frames: FramesSpec = "all") -> None:
        """Show axis triads with names: ``"all"``, ``"none"`` (or None), or an iterable of link names."""
        with self._lock:
            commands = self._set_frames(frames)
        self._send(commands)

    def _set_group_visibility(self, kind: str, visible: bool) -> list[bytes]:
        return self._set_property_commands([(self.scene.group(n, kind), visible) for n in self.scene.link_paths])

    def show_collisions(self, visible: bool = True) -> None:
        """Show or hide the collision geometry."""
        with self._lock:
            self._collisions = visible
            commands = self._set_group_visibility("collision", visible)
        self._send(commands)

    def show_visuals(self, visible: bool = True) -> None:
        """Show or hide the visual geometry."""
        with self._lock:
            commands = self._set_group_visibility("visual", visible)
        self._send(commands)

    def show_tf(self, poses: Mapping[str, npt.ArrayLike]) -> None:
        """Draw TF frames as named triads at world poses (frame name → 4×4 matrix); others are removed."""
        with self._lock:
            commands: list[bytes] = []
            for name in [n for n in self._tf if n not in poses]:
                path = wire.path_of(TF_ROOT, name)
                self._tf.pop(name)
                self._store.drop(path)
                commands.append(wire.delete(path))
            for name, pose in poses.items():
                path = wire.path_of(TF_ROOT, name)
                matrix = np.asarray(pose, dtype=np.float64)
                if name not in self._tf:
                    commands += self._add_frame(path, name)
                elif np.array_equal(self._tf[name], matrix):
                    continue
                self._tf[name] = matrix
                command = wire.set_transform(path, matrix)
                self._store.transforms[path] = command
                commands.append(command)
        if commands:
            self._send(commands)

    # ----- output ---------------------------------------------------------------------------------------------
    def commands(self) -> list[bytes]:
        """The current scene as packed meshcat commands (what a newly connected page receives)."""
        with self._lock:
            return self._store.commands()

    def static_html(self) -> str:
        """One self-contained HTML page of the current scene, viewable offline."""
        return static_page(f"{self.description.name} — robotmodel", self.commands(),
                           target=to_three(self.camera[1]))

    @property
    def url(self) -> str | None:
        """The page's address, None when not serving."""
        return self._server.url if self._server is not None else None

    @property
    def port(self) -> int | None:
        """The port served on, None when not serving."""
        return self._server.port if self._server is not None else None

    def open(self) -> None:
        """Open the page in the user's web browser."""
        if self.url:
            webbrowser.open(self.url, new=2)

    def _repr_html_(self) -> str:
        # Jupyter shows the live page inline.
        if self.url is None:
            return "<i>robotmodel Viewer (not serving)</i>"
        return (f'<div style="height: 500px; resize: vertical; overflow: hidden">'
                f'<iframe src="{self.url}" style="width: 100%; height: 100%; border: none"></iframe></div>')

    def close(self) -> None:
        """Stop the server (idempotent)."""
        if self._server is not None:
            self._server.close()

    def __enter__(self) -> Viewer:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()
