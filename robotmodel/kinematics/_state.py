"""Mutable evaluation state: link poses and Jacobians for one configuration.

Poses come from our own O(joints) composition (``_single``), so any robot the
description accepts is served in bounded memory. Jacobians use Pinocchio, whose ``Data``
is created on the first Jacobian and only when its size is reasonable (see
:data:`robotmodel.kinematics.PINOCCHIO_DATA_LIMIT`).
"""

from __future__ import annotations

from typing import Any, Literal

import numpy as np
import numpy.typing as npt

from robotmodel.errors import KinematicsError, UnknownLinkError
from robotmodel.kinematics._model import JointValues, KinematicModel
from robotmodel.kinematics._single import compose_tree, free_motion
from robotmodel.model import JointType
from robotmodel.spatial import FloatArray, Transform

__all__ = ["KinematicState"]

_REFERENCES = ("local_world_aligned", "world", "local")


class KinematicState:
    """Poses of every link for one configuration of a :class:`KinematicModel`.

    Call :meth:`update` with joint values; then read ``T_root_link`` poses and Jacobians.
    """

    def __init__(self, model: KinematicModel) -> None:
        self.model = model
        self._data: Any = None
        self.q: FloatArray = model.vector()
        self.update(self.q)

    @property
    def data(self) -> Any:
        """Pinocchio's ``Data`` for this state, created on first use (KinematicsError above the limit)."""
        if self._data is None:
            self._data = self.model._pinocchio.create_data()
        return self._data

    def update(
        self, positions: JointValues | npt.ArrayLike | None = None, *, clamp: bool = False,
        extra: JointValues | None = None,
    ) -> KinematicState:
        """Set joint values (a name mapping or a vector over ``model.variables``) and run FK.

        Floating joints take ``x y z qx qy qz qw`` and planar ``x y θ``, by name in
        ``extra`` (or in ``positions`` when it is a mapping).
        """
        model = self.model
        q = model.vector(positions, clamp=clamp)
        if extra is None and isinstance(positions, dict):
            extra = positions
        values, free = model.configuration(q, extra)
        motions = {model._joint_index[name]: free_motion(model._types[name] is JointType.FLOATING, v)
                   for name, v in free.items()}
        self._rotations, self._translations = compose_tree(
            model.table, model._all_rows, values, motions, model._link_tree, model.description.name)
        self.q, self._extra = q, extra
        return self

    def _link(self, link: str) -> int:
        index = self.model._link_index.get(link)
        if index is None:
            raise UnknownLinkError(self.model.description.name, link)
        return index

    def link_matrix(self, link: str) -> FloatArray:
        """4x4 T_root_link."""
        i = self._link(link)
        out = np.eye(4)
        out[:3, :3] = self._rotations[i]
        out[:3, 3] = self._translations[i]
        return out

    def link_pose(self, link: str) -> Transform:
        """T_root_link as translation + quaternion (x, y, z, w)."""
        return Transform.from_matrix(self.link_matrix(link))

    def link_matrices(self) -> FloatArray:
        """``(L, 4, 4)`` T_root_link for every link in ``model.link_names`` order."""
        out = np.zeros((len(self._rotations), 4, 4))
        out[:, :3, :3] = self._rotations
        out[:, :3, 3] = self._translations
        out[:, 3, 3] = 1.0
        return out

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
        Mimic joints' columns are folded into their masters (chain rule). Uses Pinocchio:
        raises :class:`~robotmodel.errors.KinematicsError` when its Data would exceed
        ``PINOCCHIO_DATA_LIMIT``.
        """
        self._link(link)
        if reference not in _REFERENCES:
            raise KinematicsError(f"reference must be one of {', '.join(_REFERENCES)}, not {reference!r}")
        import pinocchio as pin

        model = self.model
        pinocchio = model._pinocchio
        data = self.data
        config = model.pin_configuration(self.q, self._extra)
        frame = {"local_world_aligned": pin.LOCAL_WORLD_ALIGNED, "world": pin.WORLD, "local": pin.LOCAL}[reference]
        # Pinocchio hands a 6x1 Jacobian back as a flat array.
        full = np.asarray(pin.computeFrameJacobian(pinocchio.model, data, config, pinocchio.link_frames[link],
                                                   frame)).reshape(6, -1)
        out = np.zeros((6, model.nv))
        pm = pinocchio.model
        for name, jid in pinocchio.joint_ids.items():
            if pm.nvs[jid] != 1:
                continue
            j = model._joint_index[name]
            if model._multiplier[j] != 0.0:
                out[:, model._source[j]] += full[:, pm.idx_vs[jid]] * model._multiplier[j]
        return out
