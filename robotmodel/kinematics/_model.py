"""The immutable kinematic model: joint-name mapping, mimic resolution and limits.

Everything is built from the typed description (the single source of truth). Poses come
from our own O(joints) tables; Pinocchio is built from the same description only when
asked for (Jacobians, ``pin_model``). Pinocchio stores a continuous joint as two
configuration values (cos θ, sin θ) and a floating joint as seven, so names map to its
``q`` through each joint's ``idx_q`` and ``nq``, never by list position. Mimic joints are
computed here (value = multiplier × master + offset, through chains, whatever the
document order) instead of with Pinocchio's ``mimic=True``, which fails when a master
comes later in the tree.
"""

from __future__ import annotations

import math
import os
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from functools import cached_property
from typing import Any

import numpy as np
import numpy.typing as npt

from robotmodel.errors import JointValueError, KinematicsError, UnknownJointError
from robotmodel.kinematics._fast import CycleTables, cross_matrix
from robotmodel.kinematics._joints import KIND_FIXED, JointTable
from robotmodel.kinematics._pin import PinocchioModel, free_or_planar, pinocchio_data_bytes
from robotmodel.kinematics._single import LinkTree
from robotmodel.model import JointType, RobotDescription, load
from robotmodel.spatial import FloatArray

__all__ = ["JointValues", "KinematicModel", "MimicRule"]

#: Joint values by name; floating joints take 7 numbers (x y z qx qy qz qw), planar 3 (x y θ).
JointValues = Mapping[str, float | Sequence[float]]

_ONE_DOF = (JointType.REVOLUTE, JointType.CONTINUOUS, JointType.PRISMATIC)


@dataclass(frozen=True, slots=True)
class MimicRule:
    """Resolved mimic: value = multiplier × value of ``master`` + offset, ``master`` independent."""

    joint: str
    master: str
    multiplier: float
    offset: float


def _resolve_mimics(desc: RobotDescription) -> dict[str, MimicRule]:
    by_name = {j.name: j for j in desc.joints}
    # Each joint's value as (master, multiplier, offset), memoized so that every chain is
    # walked once: O(joints) even for one long chain of mimics.
    resolved: dict[str, tuple[str, float, float]] = {}
    for joint in desc.joints:
        path: list[str] = []
        current = joint
        # Construction of the description rejected cycles; the bound keeps a bad one from looping.
        while current.name not in resolved:
            if len(path) > len(by_name):
                raise KinematicsError(f"mimic joints of robot '{desc.name}' form a cycle through [{joint.name}]")
            mimic = current.mimic
            if mimic is None or mimic.joint not in by_name:
                resolved[current.name] = (current.name, 1.0, 0.0)
                break
            path.append(current.name)
            current = by_name[mimic.joint]
        for name in reversed(path):
            mimic = by_name[name].mimic
            assert mimic is not None
            master, multiplier, offset = resolved[mimic.joint]
            resolved[name] = (master, mimic.multiplier * multiplier, mimic.multiplier * offset + mimic.offset)
    rules: dict[str, MimicRule] = {}
    for joint in desc.joints:
        if joint.mimic is None or joint.type not in _ONE_DOF or joint.mimic.joint not in by_name:
            continue
        master, multiplier, offset = resolved[joint.name]
        rules[joint.name] = MimicRule(joint.name, master, multiplier, offset)
    return rules


def _aligned_axis(axis: FloatArray) -> tuple[int, float] | None:
    """(index, sign) when the unit ``axis`` is exactly ±x, ±y or ±z."""
    nonzero = np.flatnonzero(axis)
    if nonzero.size == 1 and abs(axis[nonzero[0]]) == 1.0:
        return int(nonzero[0]), float(np.sign(axis[nonzero[0]]))
    return None


@dataclass(frozen=True)
class _Cycle:
    """The publishing cycle's fast path: every one-DoF joint, values from the variables."""

    independent: tuple[str, ...]
    joints: tuple[str, ...]
    parents: tuple[str, ...]
    children: tuple[str, ...]
    source: npt.NDArray[np.intp]
    multiplier: FloatArray
    offset: FloatArray
    has_mimics: bool
    explicit_mimic: dict[str, int]
    tables: CycleTables

    @classmethod
    def build(cls, model: KinematicModel) -> _Cycle:
        table = model.table
        rows = [i for i, j in enumerate(model.description.joints) if j.type in _ONE_DOF]
        return cls(
            independent=model.variables,
            joints=tuple(table.names[i] for i in rows),
            parents=tuple(table.parents[i] for i in rows),
            children=tuple(table.children[i] for i in rows),
            source=model._source[rows],
            multiplier=model._multiplier[rows],
            offset=model._offset[rows],
            # Without mimics the rows are exactly the variables, in the same order.
            has_mimics=len(rows) != len(model.variables),
            explicit_mimic={table.names[i]: k for k, i in enumerate(rows) if table.names[i] in model.mimics},
            tables=CycleTables.build(table, rows),
        )


class KinematicModel:
    """An immutable robot model for kinematics; evaluation state lives in :class:`KinematicState`.

    ``variables`` are the independent one-DoF joints (revolute, continuous, prismatic,
    not mimicking another) in document order: the order of every joint vector.
    """

    def __init__(self, description: RobotDescription) -> None:
        self.description = description
        self.root = description.root
        self.mimics = _resolve_mimics(description)
        self.variables: tuple[str, ...] = tuple(
            j.name for j in description.joints if j.type in _ONE_DOF and j.name not in self.mimics
        )
        self.link_names: tuple[str, ...] = tuple(link.name for link in description.links)
        self.table = JointTable.from_description(description)
        self._joint_index = {name: i for i, name in enumerate(self.table.names)}
        self._variable_index = {name: i for i, name in enumerate(self.variables)}
        self._types = {j.name: j.type for j in description.joints}
        lower, upper = [], []
        for name in self.variables:
            joint = description.joint(name)
            lim = joint.limit
            bounded = joint.type is not JointType.CONTINUOUS and lim is not None
            lower.append(lim.lower if bounded and lim and lim.lower is not None else -math.inf)
            upper.append(lim.upper if bounded and lim and lim.upper is not None else math.inf)
        self.lower: FloatArray = np.array(lower)
        self.upper: FloatArray = np.array(upper)
        # Every joint's value is multiplier × variable[source] + offset: one gather, O(joints)
        # memory (a dense joints × variables map is 72 MB on a 3,000-joint chain).
        joints = len(self.table.names)
        self._source = np.zeros(joints, dtype=np.intp)
        self._multiplier = np.zeros(joints)
        self._offset = np.zeros(joints)
        for name, i in self._variable_index.items():
            self._source[self._joint_index[name]] = i
            self._multiplier[self._joint_index[name]] = 1.0
        for rule in self.mimics.values():
            if rule.master in self._variable_index:
                row = self._joint_index[rule.joint]
                self._source[row] = self._variable_index[rule.master]
                self._multiplier[row] = rule.multiplier
                self._offset[row] = rule.offset

        self._cycle = _Cycle.build(self)
        self._link_index = {name: i for i, name in enumerate(self.link_names)}
        # Batch FK walks joints parents-first: (joint row, parent link, child link).
        self._walk_rows = [
            (self._joint_index[j.name], self._link_index[j.parent], self._link_index[j.child])
            for _, j in description.walk()
        ]
        self._cross = [cross_matrix(axis) for axis in self.table.axis]
        self._aligned: list[tuple[int, float] | None] = [_aligned_axis(axis) for axis in self.table.axis]
        self._origin_identity = [bool(np.array_equal(r, np.eye(3))) for r in self.table.origin_rotation]

    @cached_property
    def _all_rows(self) -> CycleTables:
        """The publishing cycle's constants for every joint (fixed ones give their origin)."""
        return CycleTables.build(self.table, list(range(len(self.table.names))))

    @cached_property
    def _link_tree(self) -> LinkTree:
        return LinkTree.build(self._link_index[self.root], len(self.link_names), self._walk_rows)

    @cached_property
    def _pinocchio(self) -> PinocchioModel:
        unit = {name: (float(a[0]), float(a[1]), float(a[2]))
                for name, kind, a in zip(self.table.names, self.table.kinds, self.table.axis, strict=True)
                if kind != KIND_FIXED}
        return PinocchioModel(self.description, unit)

    @property
    def pin_model(self) -> Any:
        """Pinocchio's model of the description, built on first use."""
        return self._pinocchio.model

    @property
    def pinocchio_data_bytes(self) -> int:
        """Estimated size of Pinocchio's Data for this robot (see ``PINOCCHIO_DATA_LIMIT``)."""
        return pinocchio_data_bytes(self.description)

    @classmethod
    def load(cls, source: str | os.PathLike[str], args: Mapping[str, str] | None = None) -> KinematicModel:
        """Load a URDF/xacro file (see :func:`robotmodel.load`) and build its model."""
        return cls(load(source, args))

    @property
    def nv(self) -> int:
        """Number of independent joint variables."""
        return len(self.variables)

    def default_positions(self) -> dict[str, float]:
        """joint_state_publisher's defaults: 0, or the middle of the limits when 0 is outside them."""
        out = {}
        for name, lo, hi in zip(self.variables, self.lower, self.upper, strict=True):
            out[name] = 0.0 if lo <= 0.0 <= hi else float((lo + hi) / 2.0)
        return out

    def vector(
        self, positions: JointValues | npt.ArrayLike | None = None, *, clamp: bool = False
    ) -> FloatArray:
        """Validate joint values and return the variable vector (unset joints take their default).

        Raises :class:`JointValueError` naming the joint for unknown names, a wrong length,
        NaN/inf, or a value outside the limits (unless ``clamp``, which clamps instead).
        """
        if positions is None or isinstance(positions, Mapping):
            defaults = self.default_positions()
            q = np.array([defaults[n] for n in self.variables])
            for name, value in (positions or {}).items():
                if name in self._variable_index:
                    q[self._variable_index[name]] = self._scalar(name, value)
                elif name in self._joint_index:
                    continue  # mimic, floating, planar and fixed joints are handled elsewhere
                else:
                    raise UnknownJointError(
                        f"unknown joint '{name}' for robot '{self.description.name}' "
                        f"(its joints: {', '.join(self.variables)})", name)
        else:
            try:
                q = np.asarray(positions, dtype=np.float64).reshape(-1)
            except (TypeError, ValueError):
                raise JointValueError(f"expected {self.nv} joint values ({', '.join(self.variables)}), "
                                      f"got {positions!r}") from None
            if q.shape[0] != self.nv:
                raise JointValueError(f"expected {self.nv} joint values ({', '.join(self.variables)}), "
                                      f"got {q.shape[0]}")
            bad = np.flatnonzero(~np.isfinite(q))
            if bad.size:
                name = self.variables[bad[0]]
                raise JointValueError(f"joint '{name}': value {q[bad[0]]} is not finite", name)
        return self._limit(q, clamp)

    def _scalar(self, name: str, value: float | Sequence[float]) -> float:
        try:
            number = float(value)  # type: ignore[arg-type]
        except (TypeError, ValueError):
            raise JointValueError(f"joint '{name}': expected one number, got {value!r}", name) from None
        if not math.isfinite(number):
            raise JointValueError(f"joint '{name}': value {number} is not finite", name)
        return number

    def _limit(self, q: FloatArray, clamp: bool) -> FloatArray:
        # A hair of tolerance: values written out and read back in text must stay valid.
        tol = 1e-12
        outside = (q < self.lower - tol) | (q > self.upper + tol)
        if not outside.any():
            return q
        if clamp:
            return np.clip(q, self.lower, self.upper)
        i = int(np.flatnonzero(outside)[0])
        name = self.variables[i]
        raise JointValueError(
            f"joint '{name}': value {q[i]:g} is outside its limits [{self.lower[i]:g}, {self.upper[i]:g}] "
            "(clamp=True, or --clamp, clamps instead)", name)

    def joint_values(self, q: npt.ArrayLike) -> FloatArray:
        """Every joint's value (document order, mimics computed) from variable vectors ``(..., nv)``."""
        values = np.asarray(q, dtype=np.float64)
        if self.nv == 0:
            return np.broadcast_to(self._offset, (*values.shape[:-1], len(self._offset))).copy()
        # A mimic multiplier can overflow; callers that need finite values use check_finite.
        with np.errstate(over="ignore", invalid="ignore"):
            out: FloatArray = values[..., self._source] * self._multiplier + self._offset
        return out

    def configuration(self, q: FloatArray, extra: JointValues | None = None
                      ) -> tuple[FloatArray, dict[str, FloatArray]]:
        """Every joint's value from variable vector ``q`` and the floating/planar values in ``extra``.

        An explicit mimic value in ``extra`` wins over its master's, as in RSP.
        """
        values = self.joint_values(q)
        free: dict[str, FloatArray] = {}
        for name, value in (extra or {}).items():
            jtype = self._types.get(name)
            if jtype is None:
                raise UnknownJointError(f"unknown joint '{name}' for robot '{self.description.name}'", name)
            if jtype is JointType.FLOATING or jtype is JointType.PLANAR:
                free[name] = free_or_planar(name, jtype, value)
            elif name in self.mimics:
                values[self._joint_index[name]] = self._scalar(name, value)
        self.check_finite(values)
        return values, free

    def check_finite(self, values: FloatArray) -> None:
        """Raise :class:`JointValueError` naming the first joint whose value ``(..., J)`` is NaN or infinite.

        Only a mimic can get there from finite variables: its multiplier × master overflowed.
        """
        if np.isfinite(values).all():
            return
        row = int(np.flatnonzero(~np.isfinite(values).reshape(-1, values.shape[-1]).all(axis=0))[0])
        name = self.table.names[row]
        rule = self.mimics.get(name)
        how = f" ({rule.multiplier:g} × {rule.master} + {rule.offset:g})" if rule else ""
        raise JointValueError(f"joint '{name}': its value{how} is not finite", name)

    def pin_configuration(self, q: FloatArray, extra: JointValues | None = None) -> FloatArray:
        """Pinocchio's ``q`` for variable vector ``q`` (floating/planar values from ``extra``)."""
        values, free = self.configuration(q, extra)
        return self._pinocchio.configuration(values, self._types, self._joint_index, free)
