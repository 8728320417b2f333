"""robot_state_publisher's logic without a bus: a JointState in, the TransformStamped list for /tf out.

Follows ROS 2 Jazzy's robot_state_publisher (3.3.3):

- Moving joints (revolute, continuous, prismatic) go to /tf, each as T_parent_child with
  the joint state's stamp; fixed and planar joints go once to /tf_static (planar at its
  origin, as kdl_parser makes it fixed); floating joints are not published.
- Only joints named in the message are published, plus mimic joints whose master is
  (an explicit mimic value in the message wins). Names the robot lacks are ignored.
- ``publish_frequency`` caps the rate by stamps: a message is published only if its stamp
  is at least ``int(1000 / publish_frequency)`` ms after the oldest last-publish stamp of
  the joints it names (a joint never seen counts as 0, so a stamp of 0 never passes).
  ``ignore_timestamp`` publishes every message. 0 Hz means no cap.
- ``frame_prefix`` is prepended verbatim to every frame id, static ones included.

Mimic chains resolve whatever their joints' names (robot_state_publisher walks its mimic
map once in name order, so a chain resolves there only when each intermediate joint's name
sorts before its dependent's).

Where robot_state_publisher logs each bad message, this says it once per kind and joint,
and where it forwards a NaN/inf position into /tf (every tf2 listener then rejects that
transform), it leaves that transform out, once saying so: listeners see the same thing.
"""

from __future__ import annotations

import logging
import math
from collections.abc import Sequence
from itertools import repeat

import numpy as np
import numpy.typing as npt

from robotmodel.kinematics import (
    JointTransforms,
    KinematicModel,
    joint_transforms,
    static_transforms,
    variable_transforms,
)
from robotmodel.model import JointType
from robotmodel.msgs.builtin_interfaces import Time
from robotmodel.msgs.geometry_msgs import Quaternion, Transform, TransformStamped, Vector3
from robotmodel.msgs.sensor_msgs import JointState
from robotmodel.msgs.std_msgs import Header
from robotmodel.publishers._errors import PublisherError
from robotmodel.publishers._once import WarnOnce
from robotmodel.publishers._source import RobotSource, resolve
from robotmodel.publishers._tf_cdr import TFTemplate
from robotmodel.publishers._tf_ros1 import Ros1TFTemplate
from robotmodel.spatial import FloatArray

__all__ = ["RobotStateLogic", "check_publish_frequency"]

_LOG = logging.getLogger("robot_state_publisher")
#: A /tf byte layout for one wire's encoding.
Template = TFTemplate | Ros1TFTemplate
_NS = 1_000_000_000


def check_publish_frequency(hz: float) -> float:
    """``hz`` if robot_state_publisher accepts it (0 to 1000), else :class:`PublisherError` with its text."""
    value = float(hz)
    if not 0.0 <= value <= 1000.0:
        raise PublisherError("publish_frequency must be between 0 and 1000")
    return value


def _interval_ns(hz: float) -> int:
    # robot_state_publisher truncates the period to whole milliseconds; 1000/0 is no period at all.
    return int(1000.0 / hz) * 1_000_000 if hz > 0 else 0


class RobotStateLogic:
    """The transforms robot_state_publisher would publish, computed on call.

    ``description`` is a :class:`RobotDescription`, URDF text (kept byte for byte for
    /robot_description) or a .urdf/.xacro path. Times are integer nanoseconds;
    the caller passes "now" so that tests can drive the clock.
    """

    def __init__(
        self,
        description: RobotSource,
        *,
        publish_frequency: float = 20.0,
        frame_prefix: str = "",
        ignore_timestamp: bool = False,
        logger: logging.Logger | None = None,
    ) -> None:
        self.log = logger or _LOG
        self._warn = WarnOnce(self.log)
        self._publish_frequency = check_publish_frequency(publish_frequency)
        self._interval = _interval_ns(self._publish_frequency)
        self.ignore_timestamp = ignore_timestamp
        self._prefix = frame_prefix
        self._last_publish: dict[str, int] = {}
        # The fast path's last publish (names, stamp), written into _last_publish only when another
        # message comes: a joint set published again and again then costs nothing per joint.
        self._pending: tuple[tuple[str, ...], int] | None = None
        self._last_callback = 0
        self.setup(description)

    # -- parameters -------------------------------------------------------------------------------
    @property
    def publish_frequency(self) -> float:
        """The /tf rate cap in Hz (0 to 1000; 0: none)."""
        return self._publish_frequency

    @publish_frequency.setter
    def publish_frequency(self, hz: float) -> None:
        self._publish_frequency = check_publish_frequency(hz)
        self._interval = _interval_ns(self._publish_frequency)

    @property
    def frame_prefix(self) -> str:
        """Prepended verbatim to every published frame id (read on each publish, as RSP does)."""
        return self._prefix

    @frame_prefix.setter
    def frame_prefix(self, prefix: str) -> None:
        self._prefix = prefix
        self._frames = self._prefixed(self._moving)
        self._templates.clear()

    # -- the robot --------------------------------------------------------------------------------
    def setup(self, description: RobotSource) -> None:
        """Take a (new) robot; raises :class:`robotmodel.errors.URDFError` and keeps the old one if invalid."""
        desc, text = resolve(description)
        model = KinematicModel(desc)
        for joint in desc.joints:
            if joint.type in (JointType.PLANAR, JointType.FLOATING):
                # kdl_parser's words: it turns both into fixed joints (RSP then skips floating ones).
                self.log.warning("Converting unknown joint type of joint '%s' into a fixed joint", joint.name)
        self.description = desc
        self.description_text = text
        self.model = model
        self._known = {j.name for j in desc.joints}
        self._moving = joint_transforms(model, dict.fromkeys(model.variables, 0.0))
        self._plan_names: tuple[str, ...] | None = None
        self._plan: npt.NDArray[np.intp] | None = None
        self._frames = self._prefixed(self._moving)
        self._templates: dict[tuple[type[Template], tuple[str, ...]], Template] = {}
        self._static = static_transforms(model)
        self._warn.reset()

    def _prefixed(self, transforms: JointTransforms) -> dict[str, tuple[str, str]]:
        prefix = self._prefix
        return {j: (prefix + p, prefix + c)
                for j, p, c in zip(transforms.joints, transforms.parents, transforms.children, strict=True)}

    # -- output -----------------------------------------------------------------------------------
    def fixed_transforms(self, now_ns: int) -> list[TransformStamped]:
        """The /tf_static transforms (fixed and planar joints), stamped ``now_ns`` as RSP stamps them."""
        return self._stamped(self._static, now_ns, self._prefixed(self._static))

    def joint_state(self, msg: JointState, now_ns: int) -> list[TransformStamped] | None:
        """The /tf transforms for one joint state received at ``now_ns``; None if RSP would not publish."""
        found = self.joint_state_arrays(msg, now_ns)
        if found is None:
            return None
        return self.stamped(*found)

    def stamped(self, transforms: JointTransforms, stamp_ns: int) -> list[TransformStamped]:
        """Messages of what :meth:`joint_state_arrays` gives (frame ids prefixed)."""
        return self._stamped(transforms, stamp_ns, self._frames)

    def joint_state_arrays(self, msg: JointState, now_ns: int) -> tuple[JointTransforms, int] | None:
        """As :meth:`joint_state`, as arrays (frame ids without the prefix) and the stamp; see :meth:`encode_tf`."""
        stamp = msg.header.stamp
        return self._arrays(msg.name, msg.position, stamp.sec * _NS + stamp.nanosec, now_ns)

    def state_arrays(self, names: tuple[str, ...], positions: FloatArray, stamp_ns: int,
                     now_ns: int) -> tuple[JointTransforms, int] | None:
        """As :meth:`joint_state_arrays`, for a joint state given as its names, positions and stamp.

        The usual message (every variable named once, no unknown, repeated or mimic joint,
        finite values) takes a path without per-joint Python work: which names give which
        variable is worked out once per name tuple (pass the same tuple object again, as
        :class:`._jointstate_ros1.Ros1JointStateReader` does), and the per-joint last-publish stamps are written
        only when another name set comes. Any other message goes the general way; both give
        the same transforms, bit for bit.
        """
        if names is not self._plan_names:
            self._plan_names, self._plan = names, self._gather(names)
        plan = self._plan
        # A sum is finite when every value is (or, rarely, overflows: then the general path decides).
        if plan is None or len(positions) != len(names) or not math.isfinite(np.add.reduce(positions)):
            return self._arrays(names, positions.tolist(), stamp_ns, now_ns)
        if now_ns < self._last_callback:
            self.log.warning("Moved backwards in time, re-publishing joint transforms!")
            self._last_publish.clear()
            self._pending = None
        self._last_callback = now_ns
        pending = self._pending
        if pending is not None and pending[0] is not names:
            self._settle()
            pending = None
        if not self.ignore_timestamp:
            # Every name last published at the pending stamp, or as the dict says.
            oldest = pending[1] if pending is not None else min(map(self._last_publish.get, names, repeat(0)))
            if stamp_ns < min(oldest, now_ns) + self._interval:
                if stamp_ns == 0:
                    self._warn_zero_stamp()
                return None
        out = variable_transforms(self.model, positions[plan])
        self._pending = (names, stamp_ns)
        return out, stamp_ns

    def _settle(self) -> None:
        """Write the fast path's pending last-publish stamp into the per-joint record."""
        if self._pending is not None:
            names, stamp_ns = self._pending
            self._last_publish.update(zip(names, repeat(stamp_ns)))
            self._pending = None

    def _gather(self, names: tuple[str, ...]) -> npt.NDArray[np.intp] | None:
        """Where in ``names`` each variable's value is, if ``names`` is a usual message's; else None."""
        index = {name: i for i, name in enumerate(names)}
        model = self.model
        if (not names or len(index) != len(names) or not all(n in self._known for n in names)
                or any(n in model.mimics for n in names)):
            return None
        try:
            return np.array([index[v] for v in model.variables], dtype=np.intp)
        except KeyError:
            return None

    def _warn_zero_stamp(self) -> None:
        self._warn.once("zero-stamp", "joint states stamped 0 are never published (robot_state_publisher "
                        "throttles by stamp); stamp them, or set ignore_timestamp")

    def _arrays(self, names: Sequence[str], positions: Sequence[float], stamp_ns: int,
                now_ns: int) -> tuple[JointTransforms, int] | None:
        self._settle()
        if len(names) != len(positions):
            self._bad_lengths(names, positions)
            return None
        if now_ns < self._last_callback:
            self.log.warning("Moved backwards in time, re-publishing joint transforms!")
            self._last_publish.clear()
        self._last_callback = now_ns
        if not self.ignore_timestamp:
            last = self._last_publish
            oldest = min((last.get(n, 0) for n in names), default=now_ns)
            if stamp_ns < min(oldest, now_ns) + self._interval:
                if stamp_ns == 0:
                    self._warn_zero_stamp()
                return None
        # The first value of a repeated name wins, as std::map::insert keeps it.
        values = dict(zip(reversed(names), reversed(positions), strict=True))
        unknown = [n for n in values if n not in self._known]
        if unknown:
            self._say_unknown(unknown)
        if not all(map(math.isfinite, positions)):
            values = self._finite(values)
        out = joint_transforms(self.model, values)
        for name in names:
            self._last_publish[name] = stamp_ns
        return out, stamp_ns

    def encode_tf(self, transforms: JointTransforms, stamp_ns: int,
                  layout: type[Template] = TFTemplate) -> bytes | None:
        """The bytes of the TFMessage :meth:`joint_state` would give, built without message objects.

        ``layout`` is the wire's: :class:`TFTemplate` (CDR, the default) or
        :class:`Ros1TFTemplate` (ROS 1). None when the stamp does not fit the layout (ROS 1's
        unsigned seconds); the message path then names the error.
        """
        key = (layout, transforms.joints)
        template = self._templates.get(key)
        if template is None:
            if len(self._templates) >= 64:  # joint sets vary only with odd publishers; stay bounded
                self._templates.clear()
            frames = self._frames
            template = layout([frames[j][0] for j in transforms.joints], [frames[j][1] for j in transforms.joints])
            self._templates[key] = template
        return template.encode(stamp_ns, transforms.translations, transforms.rotations)

    def _finite(self, values: dict[str, float]) -> dict[str, float]:
        # Left out before the maths, so that mimic joints of a NaN master are left out too.
        kept = {}
        for name, value in values.items():
            if math.isfinite(value):
                kept[name] = value
            else:
                self._warn.once(("nan", name), "joint '%s' has a non-finite position (%s); its transform, and "
                                "those of joints mimicking it, are left out of /tf (tf2 listeners reject "
                                "non-finite transforms)", name, value)
        return kept

    def _stamped(self, transforms: JointTransforms, stamp_ns: int,
                 frames: dict[str, tuple[str, str]]) -> list[TransformStamped]:
        sec, nanosec = divmod(stamp_ns, _NS)
        return [
            TransformStamped(Header(Time(sec, nanosec), frames[joint][0]), frames[joint][1],
                             Transform(Vector3(*t), Quaternion(*r)))
            for joint, t, r in zip(transforms.joints, transforms.translations.tolist(),
                                   transforms.rotations.tolist(), strict=True)
        ]

    def _bad_lengths(self, names: Sequence[str], positions: Sequence[float]) -> None:
        if not positions:
            self._warn.once(("empty", names[0]),
                            'Robot state publisher ignored a JointState message about joint(s) "%s"(,...) '
                            "whose position member was empty.", names[0])
        else:
            self._warn.once("invalid", "Robot state publisher ignored an invalid JointState message",
                            level=logging.ERROR)

    def _say_unknown(self, unknown: list[str]) -> None:
        counts = self._warn.counts
        new = [n for n in unknown if ("unknown", n) not in counts]
        for name in unknown:
            counts["unknown", name] = counts.get(("unknown", name), 0) + 1
        if new:
            self.log.warning("joint_states names joint(s) that robot '%s' lacks, ignored: %s",
                             self.description.name, ", ".join(new))

