"""Pinocchio, built from the typed description only when a caller needs it (Jacobians, ``pin_model``).

Poses never need Pinocchio (see ``_single``); its ``Data`` grows as about 64·nv³ bytes
(the kinematic Hessian tensors, measured with pin 3: 68 MiB at nv = 100, 1.7 GiB at 300),
so it is created only below :data:`PINOCCHIO_DATA_LIMIT`, and a larger request is a
:class:`KinematicsError` naming the limit instead of an allocation without bound.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Sequence
from typing import Any

import numpy as np

from robotmodel.errors import JointValueError, KinematicsError
from robotmodel.model import JointType, Link, RobotDescription, to_urdf
from robotmodel.spatial import FloatArray

__all__ = ["PINOCCHIO_DATA_LIMIT", "PinocchioModel", "free_or_planar", "pinocchio_data_bytes", "pinocchio_nv"]

#: Largest Pinocchio ``Data`` (bytes) the library will create; 256 MiB is nv ≈ 160.
PINOCCHIO_DATA_LIMIT = 256 * 2**20

_NV = {JointType.FLOATING: 6, JointType.PLANAR: 3, JointType.FIXED: 0}


def pinocchio_nv(desc: RobotDescription) -> int:
    """Pinocchio's velocity dimension for ``desc`` (mimic joints count: we resolve them ourselves)."""
    return sum(_NV.get(j.type, 1) for j in desc.joints)


def pinocchio_data_bytes(desc: RobotDescription) -> int:
    """Estimated size of Pinocchio's ``Data`` for ``desc``: 64·nv³ bytes plus 1 MiB per 100 joints."""
    nv = pinocchio_nv(desc)
    return 64 * nv**3 + 10_000 * len(desc.joints)


def free_or_planar(name: str, jtype: JointType, value: float | Sequence[float]) -> FloatArray:
    """A floating joint's ``x y z qx qy qz qw`` (quaternion normalized) or a planar one's ``x y θ``."""
    try:
        v = np.asarray(value, dtype=np.float64).reshape(-1)
    except (TypeError, ValueError):
        v = np.zeros(0)
    want = 7 if jtype is JointType.FLOATING else 3
    if v.shape[0] != want or not np.all(np.isfinite(v)):
        form = "x y z qx qy qz qw" if want == 7 else "x y theta"
        raise JointValueError(f"joint '{name}' ({jtype.value}) takes {want} finite numbers: {form}", name)
    if want == 7:
        scale = float(np.max(np.abs(v[3:])))
        if scale == 0.0:
            raise JointValueError(f"joint '{name}': zero quaternion", name)
        quat = v[3:] / scale
        return np.concatenate([v[:3], quat / np.linalg.norm(quat)])
    return v


class PinocchioModel:
    """Pinocchio's model of a description: joint ids, link frames, and a size-checked ``Data``.

    Built from ``to_urdf`` of the description with unit axes (computed without
    underflow by the caller) and without visuals, collisions or materials, which
    kinematics does not need and which would only make urdfdom print warnings.
    """

    def __init__(self, desc: RobotDescription, unit_axes: dict[str, tuple[float, float, float]]) -> None:
        import pinocchio as pin

        self._pin = pin
        self.description = desc
        lean = dataclasses.replace(
            desc,
            links=tuple(Link(link.name, inertial=link.inertial) for link in desc.links),
            joints=tuple(dataclasses.replace(j, axis=unit_axes[j.name]) if j.name in unit_axes else j
                         for j in desc.joints),
            materials=(),
        )
        try:
            self.model: Any = pin.buildModelFromXML(to_urdf(lean))
        except (ValueError, RuntimeError) as exc:
            raise KinematicsError(f"Pinocchio could not build robot '{desc.name}': {exc}") from None
        model = self.model
        self.joint_ids: dict[str, int] = {}
        for joint in desc.joints:
            if joint.type is not JointType.FIXED:
                jid = model.getJointId(joint.name)
                if jid >= model.njoints:
                    raise KinematicsError(f"joint [{joint.name}] is missing from Pinocchio's model")
                self.joint_ids[joint.name] = jid
        self.link_frames = {link.name: model.getFrameId(link.name, pin.BODY) for link in desc.links}

    def create_data(self) -> Any:
        """A new ``Data``, or :class:`KinematicsError` when it would exceed :data:`PINOCCHIO_DATA_LIMIT`."""
        size = pinocchio_data_bytes(self.description)
        if size > PINOCCHIO_DATA_LIMIT:
            raise KinematicsError(
                f"robot '{self.description.name}' has {pinocchio_nv(self.description)} degrees of freedom: "
                f"Pinocchio's Data would take about {size / 2**20:,.0f} MiB (it grows as nv³), above the "
                f"{PINOCCHIO_DATA_LIMIT / 2**20:.0f} MiB limit (robotmodel.kinematics.PINOCCHIO_DATA_LIMIT); "
                "poses are still available")
        return self.model.createData()

    def configuration(self, values: FloatArray, types: dict[str, JointType], row: dict[str, int],
                      free: dict[str, FloatArray]) -> FloatArray:
        """Pinocchio's ``q`` from every joint's value (``values`` by table ``row``) and free joints' values."""
        model = self.model
        config: FloatArray = self._pin.neutral(model)
        for name, jid in self.joint_ids.items():
            idx, nq = model.idx_qs[jid], model.nqs[jid]
            jtype = types[name]
            if jtype is JointType.FLOATING or jtype is JointType.PLANAR:
                if name in free:
                    v = free[name]
                    config[idx:idx + nq] = v if nq == 7 else [v[0], v[1], math.cos(v[2]), math.sin(v[2])]
                continue
            value = values[row[name]]
            if nq == 2:
                config[idx], config[idx + 1] = math.cos(value), math.sin(value)
            else:
                config[idx] = value
        return config
