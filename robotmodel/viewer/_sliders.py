"""Which joints get a slider, and their ranges: joint_state_publisher_gui's rules."""

from __future__ import annotations

import math
from dataclasses import dataclass

from robotmodel.kinematics import KinematicModel
from robotmodel.model import Joint, JointType

__all__ = ["SliderJoint", "slider_joints"]


@dataclass(frozen=True, slots=True)
class SliderJoint:
    """One slider: a free joint with its range and its ``zero`` (the "Center" value)."""

    name: str
    min: float
    max: float
    zero: float


def _range(joint: Joint) -> tuple[float, float]:
    if joint.type is JointType.CONTINUOUS:
        return -math.pi, math.pi
    limit = joint.limit
    if limit is None or limit.lower is None or limit.upper is None:
        # joint_state_publisher refuses such a joint; a viewer still lets it move.
        return (-math.pi, math.pi) if joint.type is JointType.REVOLUTE else (-1.0, 1.0)
    lower, upper = limit.lower, limit.upper
    safety = joint.safety_controller
    if safety is not None:
        # use_smallest_joint_limits (on by default) narrows to the soft limits.
        lower, upper = max(lower, safety.soft_lower_limit), min(upper, safety.soft_upper_limit)
    return lower, upper


def slider_joints(model: KinematicModel) -> list[SliderJoint]:
    """Free joints (one-DoF, not mimic) whose range is not empty, in document order."""
    out = []
    for name in model.variables:
        lo, hi = _range(model.description.joint(name))
        if lo == hi:
            continue
        zero = (lo + hi) / 2.0 if lo > 0.0 or hi < 0.0 else 0.0
        out.append(SliderJoint(name, lo, hi, zero))
    return out
