"""joint_state_publisher's state and message, without a bus: values in, JointState out."""

from __future__ import annotations

import logging
import math
from collections.abc import Mapping

from robotmodel.errors import JointValueError
from robotmodel.msgs import stamp
from robotmodel.msgs.sensor_msgs import JointState
from robotmodel.msgs.std_msgs import Header
from robotmodel.publishers._jsp_joints import FreeJoint, JointLayout, read_layout
from robotmodel.publishers._once import WarnOnce

__all__ = ["JointStateLogic"]

_LOG = logging.getLogger("joint_state_publisher")


class JointStateLogic:
    """What joint_state_publisher keeps and publishes, driven by calls instead of a node.

    Free joints start at joint_state_publisher's default (``zeros``, else 0, else the
    middle of the limits when 0 lies outside them); :meth:`set` and :meth:`merge` (a
    ``source_list`` message) change them; :meth:`message` is the JointState to publish,
    mimic joints computed from their masters. Until :meth:`configure` has run there is
    nothing to publish.
    """

    def __init__(
        self,
        *,
        zeros: Mapping[str, float] | None = None,
        use_mimic_tags: bool = True,
        use_smallest_joint_limits: bool = True,
        publish_default_positions: bool = True,
        publish_default_velocities: bool = False,
        publish_default_efforts: bool = False,
        delta: float = 0.0,
        dependent_joints: Mapping[str, tuple[str, float, float]] | None = None,
        logger: logging.Logger | None = None,
    ) -> None:
        self.zeros = dict(zeros or {})
        self.dependent_joints = dict(dependent_joints or {})
        self.use_mimic_tags = use_mimic_tags
        self.use_smallest_joint_limits = use_smallest_joint_limits
        self.publish_default_positions = publish_default_positions
        self.publish_default_velocities = publish_default_velocities
        self.publish_default_efforts = publish_default_efforts
        self.delta = delta
        self.log = logger or _LOG
        self._warn = WarnOnce(self.log)
        self.layout: JointLayout | None = None
        self._position: dict[str, float] = {}
        self._velocity: dict[str, float] = {}
        self._effort: dict[str, float] = {}
        self._forward: dict[str, bool] = {}

    @property
    def configured(self) -> bool:
        """Whether a robot description has been read."""
        return self.layout is not None

    @property
    def free_joints(self) -> Mapping[str, FreeJoint]:
        """The joints that take values (no mimic joints), with limits and defaults, in message order."""
        return self.layout.free if self.layout else {}

    def configure(self, urdf: str) -> None:
        """Read a robot description (URDF text), resetting every value to its default, as a new one does.

        Raises :class:`robotmodel.errors.URDFError` (joint_state_publisher's texts) and
        leaves the previous robot in place when the description is unusable.
        """
        layout = read_layout(urdf, self.zeros, use_mimic_tags=self.use_mimic_tags,
                             use_smallest_joint_limits=self.use_smallest_joint_limits,
                             dependent_joints=self.dependent_joints)
        for name in layout.unresolved:
            self.log.warning("mimic joint '%s' of robot '%s' does not lead to a movable, non-mimic joint; "
                             "it is not published", name, layout.robot)
        for name in self.zeros:
            # A value for a mimic or fixed joint is ignored silently, as joint_state_publisher does;
            # a name the robot lacks is likely a typo worth a word.
            if name not in layout.every_joint:
                self.log.warning("zeros names joint '%s', which robot '%s' does not have; ignored",
                                 name, layout.robot)
        self.layout = layout
        free = layout.free
        self._position = {n: j.zero for n, j in free.items()} if self.publish_default_positions else {}
        self._velocity = dict.fromkeys(free, 0.0) if self.publish_default_velocities else {}
        self._effort = dict.fromkeys(free, 0.0) if self.publish_default_efforts else {}
        self._forward = dict.fromkeys(free, True)

    def set(self, values: Mapping[str, float] | None = None, /, **named: float) -> None:
        """Set free joints' positions: ``set(joint_a=0.3)`` or ``set({"joint/a": 0.3})``.

        Raises :class:`JointValueError` naming a joint that is not a free joint of the
        robot (mimic joints follow their master), or a value that is not finite.
        """
        given = {**(values or {}), **named}
        free = self.free_joints
        updates: dict[str, float] = {}
        for name, value in given.items():
            if name not in free:
                robot = self.layout.robot if self.layout else "(none yet)"
                raise JointValueError(
                    f"joint '{name}' is not a movable, non-mimic joint of robot '{robot}'", name)
            number = float(value)
            if not math.isfinite(number):
                raise JointValueError(f"joint '{name}': value {number} is not finite", name)
            updates[name] = number
        self._position.update(updates)

    def positions(self) -> dict[str, float]:
        """The free joints' current positions (those that have one)."""
        return dict(self._position)

    def merge(self, msg: JointState) -> None:
        """Take values from a ``source_list`` message: free joints only, each field if the message has it."""
        free = self.free_joints
        fields = ((msg.position, self._position), (msg.velocity, self._velocity), (msg.effort, self._effort))
        for i, name in enumerate(msg.name):
            if name not in free:
                continue
            for values, store in fields:
                if not values:
                    continue
                if i < len(values):
                    store[name] = float(values[i])
                else:
                    self._warn.once(("short", name), "a source JointState names '%s' but has only %d values "
                                    "in one of its arrays; that value is ignored", name, len(values))

    def step(self, delta: float) -> None:
        """Move every free joint by ``delta``, bouncing between its limits (continuous joints wrap)."""
        for name, joint in self.free_joints.items():
            if name not in self._position:
                continue
            forward = self._forward[name]
            value = self._position[name] + (delta if forward else -delta)
            if forward and value > joint.upper:
                value = joint.lower if joint.continuous else joint.upper
                self._forward[name] = joint.continuous
            elif not forward and value < joint.lower:
                value = joint.lower
                self._forward[name] = True
            self._position[name] = value

    def message(self, now_ns: int) -> JointState | None:
        """The JointState to publish now (None before a description, or when it would be empty)."""
        layout = self.layout
        if layout is None:
            return None
        if self.delta > 0:
            self.step(self.delta)
        names = list(layout.names)
        # An array is present if any joint has a value for it; mimic joints imply positions.
        has_position = bool(layout.dependent) or bool(self._position)
        columns = []
        if has_position:
            columns.append(("position", self._position, True))
        if self._velocity:
            columns.append(("velocity", self._velocity, True))
        if self._effort:
            columns.append(("effort", self._effort, False))
        arrays: dict[str, list[float]] = {"position": [], "velocity": [], "effort": []}
        dependent = layout.dependent
        for field, store, scaled in columns:
            out = arrays[field]
            for name in names:
                rule = dependent.get(name)
                if rule is None:
                    out.append(store.get(name, 0.0))
                elif rule.parent not in store:
                    out.append(0.0)
                elif field == "position":
                    out.append(store[rule.parent] * rule.factor + rule.offset)
                else:
                    out.append(store[rule.parent] * rule.factor if scaled else store[rule.parent])
        if not names:
            return None
        return JointState(header=Header(stamp=stamp(now_ns)), name=names, position=arrays["position"],
                          velocity=arrays["velocity"], effort=arrays["effort"])
