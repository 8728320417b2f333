"""Recorded joint states turned into TF through the kinematics, as robot_state_publisher would publish them.

Every recorded state is converted (no publish-rate throttling: offline, each stamp is
worth keeping). Per state, as RSP: the first value of a repeated name wins, non-finite
positions are left out (with the joints mimicking them), unknown names are ignored;
fixed joints go in once as static transforms.
"""

from __future__ import annotations

import math
import os
from typing import TYPE_CHECKING, Any

import numpy as np

from robotmodel.errors import RecordingError, RobotModelError

if TYPE_CHECKING:
    from robotmodel.model import RobotDescription
    from robotmodel.tf import BufferCore

__all__ = ["JointStateTF"]

_NS = 1_000_000_000


class JointStateTF:
    """Collects joint states while a recording streams, then inserts their transforms into a buffer."""

    def __init__(self) -> None:
        self._states: list[tuple[int, tuple[str, ...], tuple[float, ...]]] = []
        self.skipped = 0

    def __len__(self) -> int:
        return len(self._states)

    def span(self) -> tuple[int, int]:
        """First and last stamp of the kept states (0, 0 when none)."""
        stamps = [s for s, _, _ in self._states]
        return (min(stamps), max(stamps)) if stamps else (0, 0)

    def add(self, msg: Any) -> None:
        """Keep one rosbags JointState message (header stamp, names, positions)."""
        names, positions = tuple(msg.name), tuple(float(v) for v in msg.position)
        if len(names) != len(positions):
            self.skipped += 1  # RSP ignores a state whose lengths differ
            return
        stamp = msg.header.stamp
        self._states.append((int(stamp.sec) * _NS + int(stamp.nanosec), names, positions))

    def insert_into(self, buffer: BufferCore, robot: RobotDescription | str | os.PathLike[str], authority: str,
                    where: str) -> tuple[int, int]:
        """Insert fixed joints as static and every state's joint transforms; (accepted, skipped) counts."""
        from robotmodel.kinematics import KinematicModel, joint_transforms, static_transforms

        desc = _description(robot, where)
        try:
            model = KinematicModel(desc)
        except RobotModelError as exc:
            raise RecordingError(f"{where}: cannot build the kinematics of robot '{desc.name}': {exc}") from None
        accepted, skipped = 0, self.skipped
        fixed = static_transforms(model)
        for parent, child, t, r in zip(fixed.parents, fixed.children, fixed.translations.tolist(),
                                       fixed.rotations.tolist(), strict=True):
            ok = buffer.insert(parent, child, 0, (*t, *r), authority, is_static=True)
            accepted, skipped = accepted + ok, skipped + (not ok)
        series: dict[tuple[str, str], tuple[list[int], list[list[float]]]] = {}
        known = set(model.variables) | {j.name for j in desc.joints}
        for stamp_ns, names, positions in self._states:
            values: dict[str, float] = {}
            for name, value in zip(reversed(names), reversed(positions), strict=True):
                values[name] = value
            values = {n: v for n, v in values.items() if n in known and math.isfinite(v)}
            if not values:
                continue
            out = joint_transforms(model, values)
            for parent, child, t, r in zip(out.parents, out.children, out.translations.tolist(),
                                           out.rotations.tolist(), strict=True):
                stamps, poses = series.setdefault((parent, child), ([], []))
                stamps.append(stamp_ns)
                poses.append(t + r)
        for (parent, child), (stamps, poses) in series.items():
            stamp_arr = np.asarray(stamps, dtype=np.int64)
            order = np.argsort(stamp_arr, kind="stable")
            got = buffer.insert_many(parent, child, stamp_arr[order], np.asarray(poses)[order], authority)
            accepted += got
            skipped += len(stamps) - got
        return accepted, skipped


def _description(robot: RobotDescription | str | os.PathLike[str], where: str) -> RobotDescription:
    from robotmodel.model import RobotDescription, load

    if isinstance(robot, RobotDescription):
        return robot
    try:
        return load(robot)
    except RobotModelError as exc:
        raise RecordingError(f"{where}: the robot for its joint states: {' '.join(str(exc).split())}") from None
