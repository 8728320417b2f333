"""The single exception tree of robotmodel.

Every error the library raises on purpose derives from :class:`RobotModelError`, so a
caller (and the CLI) can catch one class and print one line. The tree::

    RobotModelError
    ├── XacroError                  xacro expansion failed (file, line when known)
    │   └── UntrustedInputError     --untrusted refused $(env), an outside include, ...
    ├── ResourceError               a package or file a robot names could not be resolved
    │   ├── PackageNotFoundError    $(find pkg) / package:// names an unknown package
    │   └── RevisionError           a file at a git revision could not be read (diff --git)
    ├── URDFError                   the URDF is not a valid robot description
    │   └── URDFParseError          malformed XML or a malformed element
    ├── UnknownLinkError            a link name the robot does not have (every API)
    ├── KinematicsError             a kinematic model could not be built or evaluated
    │   └── JointValueError         unknown joint, wrong length, NaN/inf, out of limits
    │       └── UnknownJointError   a joint name the robot does not have (every API)
    ├── BusError                    the bus: a bad topic/node name or endpoint, a session that
    │   │                           would not open (see robotmodel.bus)
    │   └── Ros1Error               the ROS 1 wire (see robotmodel.ros1): an unknown message type,
    │       │                       a bad address or connection header
    │       └── MasterError         the ROS master refused a call ([code, statusMessage, value]
    │                               with code != 1) or could not be reached; names the master URI
    ├── MessageError                a message field its ROS type cannot carry, or bytes that
    │                               do not decode as the type (also a ValueError)
    ├── PublisherError              a state publisher's parameter out of range, e.g.
    │                               publish_frequency (ROS's text; also a ValueError)
    ├── ViewerError                 the viewer: no browser for a screenshot, a port in use, a
    │                               page that did not load (see robotmodel.viewer)
    ├── RecordingError              a recording that cannot be read (truncated, corrupt, empty,
    │                               wrong format, a topic of another type) or written; names
    │                               the file and what was read (see robotmodel.recording)
    ├── LaunchError                 a launch file that cannot be run: bad XML, an unknown
    │                               substitution, a missing include or arg (file:line first)
    ├── ConfigError                 a project config ([tool.robotmodel] in pyproject.toml or
    │                               robotmodel.toml) that cannot be used (file and key first)
    ├── CommandLineError            a ROS program's words refused with that program's text
    │   ├── RosArgsError            a --ros-args word rcl would refuse: remap, parameter, params
    │   │                           file, namespace (rcl's text; also a ValueError; robotmodel.rcl)
    │   ├── StaticArgsError         static_transform_publisher's words (ROS 2's text; robotmodel.tf_ros)
    │   └── EchoArgsError           tf2_echo's words (its text and exit code; robotmodel.tf_ros)
    ├── ROSException                rospy's root (see robotmodel.rospy)
    │   ├── ROSInterruptException   shutdown interrupted a sleep (also a KeyboardInterrupt, as rospy's)
    │   │   └── ROSTimeMovedBackwardsException  /clock went back during a sleep (.time: seconds)
    │   └── ROSInitException        init_node refused (called twice, a bad name)
    ├── RclpyError                  rclpy's errors (see robotmodel.rclpy; rclpy's texts)
    │   ├── NotInitializedException rclpy.init() not called, or the context shut down
    │   └── ParameterException      a parameter use rclpy refuses
    │       ├── ParameterNotDeclaredException, ParameterAlreadyDeclaredException,
    │       ├── ParameterUninitializedException, ParameterImmutableException,
    │       └── InvalidParameterValueException, InvalidParameterTypeException
    └── TransformException          tf2's root (see robotmodel.tf)
        ├── LookupException
        ├── ConnectivityException
        ├── ExtrapolationException  (.direction: ExtrapolationDirection forward/backward/no data)
        ├── InvalidArgumentException
        └── TimeoutException

Messages are built before raising and name the offending file, element, joint or
frame. The TF classes carry structured fields as well as tf2's text.
"""

from __future__ import annotations

import enum
from typing import Any

__all__ = [
    "BusError",
    "CommandLineError",
    "ConfigError",
    "ConnectivityException",
    "EchoArgsError",
    "ExtrapolationDirection",
    "ExtrapolationException",
    "InvalidArgumentException",
    "InvalidParameterTypeException",
    "InvalidParameterValueException",
    "JointValueError",
    "KinematicsError",
    "LaunchError",
    "LookupException",
    "MasterError",
    "MessageError",
    "NotInitializedException",
    "PackageNotFoundError",
    "ParameterAlreadyDeclaredException",
    "ParameterException",
    "ParameterImmutableException",
    "ParameterNotDeclaredException",
    "ParameterUninitializedException",
    "PublisherError",
    "ROSException",
    "ROSInitException",
    "ROSInterruptException",
    "ROSTimeMovedBackwardsException",
    "RclpyError",
    "RecordingError",
    "ResourceError",
    "RevisionError",
    "RobotModelError",
    "Ros1Error",
    "RosArgsError",
    "StaticArgsError",
    "TimeoutException",
    "TransformException",
    "URDFError",
    "URDFParseError",
    "UnknownJointError",
    "UnknownLinkError",
    "UntrustedInputError",
    "ViewerError",
    "XacroError",
]


class RobotModelError(Exception):
    """Root of every error robotmodel raises on purpose."""


class XacroError(RobotModelError):
    """xacro expansion failed; the message names the file and, when known, the line."""


class ResourceError(RobotModelError):
    """A package, URI or file a robot description names could not be resolved."""


class PackageNotFoundError(ResourceError):
    """A ROS package named by ``$(find pkg)`` or ``package://pkg`` was not found."""

    def __init__(self, package: str, searched: list[str]) -> None:
        self.package = package
        self.searched = searched
        where = ", ".join(searched) if searched else "nowhere (no search roots)"
        super().__init__(f"package '{package}' not found; searched: {where}. Name the folder holding it with "
                         "--package-path DIR (package_paths=[DIR] in Python) or ROS_PACKAGE_PATH")


class RevisionError(ResourceError):
    """A file at a git revision could not be read: not in a repository, an unknown revision, a path absent there."""


class UntrustedInputError(XacroError):
    """In untrusted mode, the input asked for something that is refused."""


class URDFError(RobotModelError):
    """The robot description is not valid (names the element at fault)."""


class URDFParseError(URDFError):
    """The URDF XML is malformed, or one of its elements is."""


class UnknownLinkError(RobotModelError, LookupError):
    """A link name that the robot does not have, from every API that takes a link name."""

    def __init__(self, robot: str, link: str) -> None:
        self.robot = robot
        self.link = link
        super().__init__(f"robot '{robot}' has no link '{link}'")


class KinematicsError(RobotModelError):
    """A kinematic model could not be built or evaluated."""


class JointValueError(KinematicsError):
    """A joint value is unknown, non-finite, of the wrong size, or out of limits."""

    def __init__(self, message: str, joint: str | None = None) -> None:
        self.joint = joint
        super().__init__(message)


class PublisherError(RobotModelError, ValueError):
    """A state publisher was given a parameter outside its range (ROS's text where ROS has one)."""


class ViewerError(RobotModelError):
    """The viewer could not do what was asked: no browser found, a port in use, a page that did not load."""


class RecordingError(RobotModelError):
    """A recording could not be read or written; the text names the file and what was read before."""


class LaunchError(RobotModelError):
    """A launch file cannot be run; the text starts with ``FILE:LINE:`` of the element at fault."""


class ConfigError(RobotModelError):
    """A project config (``[tool.robotmodel]`` or ``robotmodel.toml``) cannot be used; names the file and key."""


class CommandLineError(RobotModelError):
    """The words of a ROS program's command line are refused; the text is that program's own (one line)."""


class RosArgsError(CommandLineError, ValueError):
    """A ROS argument or namespace that rcl (or rclpy) would refuse; the text is one line, rcl's."""


class StaticArgsError(CommandLineError):
    """static_transform_publisher's words do not form a valid command line; ``str()`` is ROS 2's error text."""


class EchoArgsError(CommandLineError):
    """A bad tf2_echo command line: ``str()`` is the text to print, ``code`` the exit code tf2_echo uses.

    ``to_stdout``: tf2_echo prints this one (its usage) on stdout rather than stderr.
    """

    def __init__(self, message: str, code: int, to_stdout: bool = False) -> None:
        super().__init__(message)
        self.code = code
        self.to_stdout = to_stdout


class BusError(RobotModelError):
    """The bus could not do what was asked.

    A bad topic or node name, a bad QoS text, a zenoh session that would not open, or an
    endpoint that is not a zenoh locator; the message names it.
    """


class Ros1Error(BusError):
    """The ROS 1 wire could not do what was asked; the text names the node, topic, peer or type."""


class MasterError(Ros1Error):
    """The ROS master answered a call with a failure code, or could not be reached.

    ``master_uri`` and ``method`` name the call; ``code`` is ROS's status code (``-1`` caller
    error, ``0`` failure) or None when the master was unreachable.
    """

    def __init__(self, message: str, *, master_uri: str, method: str, code: int | None = None) -> None:
        super().__init__(message)
        self.master_uri = master_uri
        self.method = method
        self.code = code


class MessageError(RobotModelError, ValueError):
    """A message cannot be encoded (a field out of its ROS type's range) or decoded.

    The text names the message type and the field path, e.g.
    ``tf2_msgs/msg/TFMessage.transforms[0].header.stamp.sec``.
    """


class UnknownJointError(JointValueError, LookupError):
    """A joint name that the robot does not have, from every API that takes a joint name."""


class TransformException(RobotModelError):
    """Root of tf2's exceptions (tf2.TransformException), with structured context.

    ``target_frame``/``source_frame`` name the lookup, ``time_ns`` the requested time,
    ``earliest_ns``/``latest_ns`` the data available, when they apply (else None).
    """

    def __init__(
        self,
        message: str,
        *,
        target_frame: str | None = None,
        source_frame: str | None = None,
        time_ns: int | None = None,
        earliest_ns: int | None = None,
        latest_ns: int | None = None,
    ) -> None:
        super().__init__(message)
        self.target_frame = target_frame
        self.source_frame = source_frame
        self.time_ns = time_ns
        self.earliest_ns = earliest_ns
        self.latest_ns = latest_ns


class LookupException(TransformException):
    """A frame does not exist in the buffer (or the tree has a loop)."""


class ConnectivityException(TransformException):
    """The frames exist but are not connected in one tree."""


class ExtrapolationDirection(enum.Enum):
    """Which of tf2's extrapolation cases an :class:`ExtrapolationException` reports.

    tf2 (Iron and later) raises Forward-, Backward- and NoDataForExtrapolationException;
    tf2_py surfaces all three as ExtrapolationException, so the case travels here.
    """

    FORWARD = "forward"  #: "Lookup would require extrapolation into the future. ..."
    BACKWARD = "backward"  #: "Lookup would require extrapolation into the past. ..."
    NO_DATA = "no_data"  #: "Lookup would require extrapolation at time ..., but only time ... is in the buffer"


class ExtrapolationException(TransformException):
    """The requested time is outside the buffered data; ``direction`` says which way."""

    def __init__(self, message: str, *, direction: ExtrapolationDirection | None = None, **context: Any) -> None:
        super().__init__(message, **context)
        self.direction = direction


class InvalidArgumentException(TransformException):
    """An argument is malformed (empty frame, leading '/', NaN, ...)."""


class TimeoutException(TransformException):
    """A lookup with a timeout expired before the transform became available."""


class RclpyError(RobotModelError):
    """rclpy's errors (robotmodel.rclpy raises these where rclpy raises its own, with its texts)."""


class NotInitializedException(RclpyError):
    """rclpy.init() has not been called (or the context is shut down)."""

    def __init__(self, *args: Any) -> None:
        super().__init__("rclpy.init() has not been called", *args)


class ParameterException(RclpyError):
    """Base of the parameter errors (rclpy's)."""

    def __init__(self, error_msg: str, parameters: Any, *args: Any) -> None:
        super().__init__(f"{error_msg}: {parameters}", *args)
        self.parameters = parameters


class ParameterNotDeclaredException(ParameterException):
    """A parameter used before it was declared."""

    def __init__(self, parameters: Any, *args: Any) -> None:
        super().__init__("Invalid access to undeclared parameter(s)", parameters, *args)


class ParameterAlreadyDeclaredException(ParameterException):
    """A parameter declared twice."""

    def __init__(self, parameters: Any, *args: Any) -> None:
        super().__init__("Parameter(s) already declared", parameters, *args)


class ParameterUninitializedException(ParameterException):
    """A statically typed parameter read before it got a value."""

    def __init__(self, parameter_name: str, *args: Any) -> None:
        super().__init__(f"The parameter '{parameter_name}' is not initialized", parameter_name, *args)


class InvalidParameterValueException(ParameterException):
    """A value a descriptor's rules or a set-parameters callback refused."""

    def __init__(self, parameter: str, value: Any, reason: str, *args: Any) -> None:
        super().__init__(f"Invalid parameter value ({value}) for parameter. Reason: {reason}", parameter, *args)
        self.reason = reason


class InvalidParameterTypeException(ParameterException):
    """A value of another type than the parameter's (static typing)."""

    def __init__(self, desired_parameter: Any, expected_type: str, *args: Any) -> None:
        super().__init__(f"Trying to set parameter '{desired_parameter.name}' to '{desired_parameter.value}' of type "
                         f"'{desired_parameter.type_.name}', expecting type '{expected_type}'",
                         desired_parameter.name, *args)


class ParameterImmutableException(ParameterException):
    """A read-only parameter set after its declaration."""

    def __init__(self, parameter_name: str, *args: Any) -> None:
        super().__init__(f"Attempted to modify read-only parameter '{parameter_name}'", parameter_name, *args)


class ROSException(RobotModelError):
    """rospy's exception root (robotmodel.rospy raises these where rospy raises its own)."""


class ROSInterruptException(ROSException, KeyboardInterrupt):
    """Shutdown interrupted a sleep (``rospy.sleep``, ``Rate.sleep``), as rospy's: also a KeyboardInterrupt."""


class ROSTimeMovedBackwardsException(ROSInterruptException):
    """The simulated time (``/clock``) moved backwards during a sleep; ``time`` is by how much, in seconds."""

    def __init__(self, time: float) -> None:
        super().__init__("ROS time moved backwards")
        self.time = time


class ROSInitException(ROSException):
    """``init_node`` could not initialize the node (rospy's text)."""
