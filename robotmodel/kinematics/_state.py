"""Mutable evaluation state (Pinocchio's ``data``): link poses and Jacobians for one configuration."""

from __future__ import annotations

from typing import Any, Literal

import numpy as np
import numpy.typing as npt
import pinocchio as pin

from robotmodel.errors import KinematicsError
from robotmodel.kinematics._model import JointValues, KinematicModel
from robotmodel.spatial import FloatArray, Transform

__all__ = ["KinematicState"]

_REFERENCE = {
    "local_world_aligned": pin.LOCAL_WORLD_ALIGNED,
    "world": pin.WORLD,
    "local": pin.LOCAL,
}


class KinematicState:
    """Poses of every link for one configuration of a :class:`KinematicModel`.

    Call :meth:`update` with joint values; then read ``T_root_link`` poses and Jacobians.
    """

    def __init__(self, model: KinematicModel) -> None:
        self.model = model
        self.data: Any = model.pin_model.createData()
        self.q: FloatArray = model.vector()
        self.update(self.q)

    def update(
        self, positions: JointValues | npt.ArrayLike | None = None, *, clamp: bool = False,
        extra: JointValues | None = None,
    ) -> KinematicState:
        """Set joint values (a name mapping or a vector over ``model.variables``) and run FK.

        Floating joints take ``x y z qx qy qz qw`` and planar ``x y θ``, by name in
        ``extra`` (or in ``positions`` when it is a mapping).
        """
        self.q = self.model.vector(positions, clamp=clamp)
        if extra is None and isinstance(positions, dict):
            extra = positions
        self._config = self.model.pin_configuration(self.q, extra)
        pin.framesForwardKinematics(self.model.pin_model, self.data, self._config)
        return self

    def _frame(self, link: str) -> int:
        try:
            frame: int = self.model._link_frames[self.model.link_names.index(link)]
        except ValueError:
            raise KinematicsError(f"robot '{self.model.description.name}' has no link '{link}'") from None
        return frame

    def link_matrix(self, link: str) -> FloatArray:
        """4x4 T_root_link."""
        result: FloatArray = self.data.oMf[self._frame(link)].homogeneous
        return result

    def link_pose(self, link: str) -> Transform:
        """T_root_link as translation + quaternion (x, y, z, w)."""
        return Transform.from_matrix(self.link_matrix(link))

    def link_matrices(self) -> FloatArray:
        """``(L, 4, 4)`` T_root_link for every link in ``model.link_names`` order."""
        poses = self.data.oMf
        return np.stack([poses[f].homogeneous for f in self.model._link_frames])

    def link_poses(self) -> dict[str, Transform]:
        """T_root_link of every link, by name."""
        return {n: Transform.from_matrix(m) for n, m in zip(self.model.link_names, self.link_matrices(),
                                                           strict=True)}

    def jacobian(
        self, link: str, reference: Literal["local_world_aligned", "world", "local"] = "local_world_aligned",
    ) -> FloatArray:
        """``(6, nv)`` Jacobian of ``link`` over ``model.variables`` (rows: linear xyz, angular xyz).

        ``local_world_aligned`` (default): velocity of the link origin, axes of the root
        frame; ``world``: spatial velocity at the root origin; ``local``: link axes.
        Mimic joints' columns are folded into their masters (chain rule).
        """
        model = self.model
        full = pin.computeFrameJacobian(model.pin_model, self.data, self._config, self._frame(link),
                                        _REFERENCE[reference])
        out = np.zeros((6, model.nv))
        pm = model.pin_model
        for name, jid in model._pin_joint.items():
            col = pm.idx_vs[jid]
            if pm.nvs[jid] != 1:
                continue
            j = model._joint_index[name]
            out += np.outer(full[:, col], model._expand[j])
        return out
