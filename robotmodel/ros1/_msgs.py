"""ROS 1 message support: type names, full definitions, md5sums and (de)serialization.

Built on rosbags' ``ROS1_NOETIC`` type store, which holds the message packages of a Noetic
install; ``tf2_msgs/TFMessage`` is not among them and is registered here from its definition.
ROS 1 names types ``pkg/Type`` on the wire; rosbags names them ``pkg/msg/Type``. Every function
here takes either form.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass
from typing import Any

from rosbags.serde import SerdeError
from rosbags.typesys import Stores, TypesysError, get_types_from_msg, get_typestore
from rosbags.typesys.store import Typestore

from robotmodel.errors import MessageError, Ros1Error
from robotmodel.msgs.turtlesim import POSE_DEFINITION

__all__ = ["ANY", "Ros1Type", "deserialize", "message_type", "serialize", "typestore", "wire_name"]

#: tf2_msgs/TFMessage as Noetic ships it and turtlesim's Pose (not in rosbags' ROS1_NOETIC store).
_EXTRA_DEFINITIONS = {"tf2_msgs/msg/TFMessage": "geometry_msgs/TransformStamped[] transforms\n",
                      "turtlesim/msg/Pose": POSE_DEFINITION}


@functools.cache
def typestore() -> Typestore:
    """The ROS 1 Noetic type store of rosbags, with ``tf2_msgs/msg/TFMessage`` registered (built once)."""
    store = get_typestore(Stores.ROS1_NOETIC)
    for name, text in _EXTRA_DEFINITIONS.items():
        store.register(get_types_from_msg(text, name))
    return store


def _store_name(typename: str) -> str:
    """``pkg/Type`` or ``pkg/msg/Type`` as rosbags names it (``pkg/msg/Type``)."""
    parts = typename.strip("/").split("/")
    if len(parts) == 2 and all(parts):
        return f"{parts[0]}/msg/{parts[1]}"
    if len(parts) == 3 and parts[1] == "msg" and parts[0] and parts[2]:
        return "/".join(parts)
    raise Ros1Error(f"'{typename}' is not a ROS message type name (expected pkg/Type)")


def wire_name(typename: str) -> str:
    """The ROS 1 form ``pkg/Type`` of ``pkg/Type`` or ``pkg/msg/Type``."""
    pkg, _, name = _store_name(typename).split("/")
    return f"{pkg}/{name}"


@dataclass(frozen=True)
class Ros1Type:
    """A ROS 1 message type as the connection header carries it.

    ``name`` is the wire form (``std_msgs/String``), ``definition`` the full text with every
    dependency (``message_definition``), ``md5sum`` ROS 1's hash of it.
    """

    name: str
    md5sum: str
    definition: str

    @property
    def store_name(self) -> str:
        """The type's name in rosbags' store (``std_msgs/msg/String``)."""
        return _store_name(self.name)


#: Any type (rospy's AnyMsg): md5sum ``*`` matches every publisher, which names its type in its header.
ANY = Ros1Type("*", "*", "")


@functools.cache
def message_type(typename: str) -> Ros1Type:
    """The :class:`Ros1Type` of ``typename`` (``"*"``: :data:`ANY`).

    Raises :class:`Ros1Error` for a type Noetic lacks.
    """
    if typename == "*":
        return ANY
    name = _store_name(typename)
    try:
        definition, md5sum = typestore().generate_msgdef(name, ros_version=1)
    except TypesysError:
        raise Ros1Error(f"unknown ROS 1 message type '{wire_name(typename)}'") from None
    return Ros1Type(wire_name(name), md5sum, definition)


def serialize(message: Any, typename: str) -> bytes:
    """ROS 1 bytes of ``message`` (a rosbags class of the store) as type ``typename``."""
    name = message_type(typename).store_name
    try:
        return bytes(typestore().serialize_ros1(message, name))
    except (SerdeError, TypeError, ValueError, AttributeError, KeyError, OverflowError) as exc:
        raise MessageError(f"cannot encode {wire_name(name)}: {exc}") from None


def deserialize(data: bytes | memoryview, typename: str) -> Any:
    """The message of type ``typename`` ROS 1 bytes ``data`` hold; :class:`MessageError` when they do not."""
    name = message_type(typename).store_name
    try:
        return typestore().deserialize_ros1(data, name)
    except (SerdeError, ValueError, UnicodeDecodeError, IndexError) as exc:
        raise MessageError(f"cannot decode {wire_name(name)}: {exc}") from None
