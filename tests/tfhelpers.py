"""Test helpers: build TransformStamped messages and independent 4x4 math."""

from __future__ import annotations

import math

import numpy as np

from robotmodel.tf import Time, TransformStamped

SEC = 1_000_000_000


def make(parent: str, child: str, xyz=(0.0, 0.0, 0.0), yaw: float = 0.0, sec: float = 0.0,
         quat=None) -> TransformStamped:
    t = TransformStamped()
    t.header.frame_id = parent
    t.child_frame_id = child
    t.header.stamp = Time(seconds=sec).to_msg()
    t.transform.translation.x, t.transform.translation.y, t.transform.translation.z = xyz
    q = quat if quat is not None else (0.0, 0.0, math.sin(yaw / 2), math.cos(yaw / 2))
    r = t.transform.rotation
    r.x, r.y, r.z, r.w = q
    return t


def matrix(xyz, yaw: float) -> np.ndarray:
    m = np.eye(4)
    m[:2, :2] = [[math.cos(yaw), -math.sin(yaw)], [math.sin(yaw), math.cos(yaw)]]
    m[:3, 3] = xyz
    return m


def msg_matrix(msg) -> np.ndarray:
    tr, q = msg.transform.translation, msg.transform.rotation
    x, y, z, w = q.x, q.y, q.z, q.w
    m = np.eye(4)
    m[:3, :3] = [[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                 [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                 [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]]
    m[:3, 3] = [tr.x, tr.y, tr.z]
    return m


def compose(transforms, root: str) -> dict[str, np.ndarray]:
    """Each child's pose in ``root`` from per-joint parent→child transforms (no robotmodel code)."""
    by_child = {t.child_frame_id: t for t in transforms}
    poses = {root: np.eye(4)}

    def pose(frame: str) -> np.ndarray:
        if frame not in poses:
            t = by_child[frame]
            poses[frame] = pose(t.header.frame_id) @ msg_matrix(t)
        return poses[frame]

    for child in by_child:
        pose(child)
    return poses
