"""ROS names and their zenoh forms: topic key expressions, liveliness tokens and GIDs, as rmw_zenoh.

- Topic key: ``<domain>/<topic without its leading '/'>/<pkg>::msg::dds_::<Type>_/RIHS01_<hex>``.
- Liveliness token (graph discovery), rmw_zenoh's 9 or 13 chunks::

      @ros2_lv/<domain>/<zid>/<node id>/<entity id>/<NN|MP|MS|SS|SC>/<enclave>/<namespace>/<node>
          [/<topic>/<dds type>/<type hash>/<qos>]

  with every '/' inside a chunk written '%' (so the root namespace is '%').
- GID: XXH3-128 of the whole token, low 64 bits then high 64 bits, little-endian.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from enum import StrEnum

import xxhash

from robotmodel.bus._qos import QoS, qos_from_keyexpr, qos_to_keyexpr
from robotmodel.errors import BusError

__all__ = [
    "ADMIN_SPACE",
    "Entity",
    "EntityKind",
    "dds_type_name",
    "demangle",
    "gid_of",
    "mangle",
    "resolve_topic",
    "ros_type_name",
    "topic_keyexpr",
    "validate_namespace",
    "validate_node_name",
]

ADMIN_SPACE = "@ros2_lv"
_TOKEN = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")
_DDS_MARK = "dds_::"


class EntityKind(StrEnum):
    """The entity kinds of rmw_zenoh's graph, by their token text."""

    NODE = "NN"
    PUBLISHER = "MP"
    SUBSCRIPTION = "MS"
    SERVICE = "SS"
    CLIENT = "SC"


def mangle(name: str) -> str:
    """rmw_zenoh's mangling: every '/' becomes '%' (a key expression chunk has no '/')."""
    return name.replace("/", "%")


def demangle(chunk: str) -> str:
    """Undo :func:`mangle`."""
    return chunk.replace("%", "/")


def validate_node_name(name: str) -> str:
    """Return ``name`` if it is a valid ROS node name (letters, digits, '_', no leading digit)."""
    if not _TOKEN.fullmatch(name):
        raise BusError(f"invalid node name '{name}': must be letters, digits and '_', not starting with a digit")
    return name


def _check_fq(name: str, what: str) -> str:
    if not name.startswith("/"):
        raise BusError(f"invalid {what} '{name}': must be absolute")
    if name == "/":
        return name
    if name.endswith("/"):
        raise BusError(f"invalid {what} '{name}': must not end with '/'")
    for token in name[1:].split("/"):
        if not _TOKEN.fullmatch(token):
            raise BusError(
                f"invalid {what} '{name}': '{token}' must be letters, digits and '_', not starting with a digit"
            )
    return name


def validate_namespace(namespace: str) -> str:
    """Return the namespace made absolute ('' and 'ns' become '/' and '/ns'); raises BusError."""
    ns = namespace if namespace.startswith("/") else "/" + namespace
    return _check_fq(ns, "namespace")


def resolve_topic(name: str, namespace: str = "/", node_name: str = "") -> str:
    """Expand a topic name as rcl does: absolute kept, relative under the namespace, '~' the node."""
    if not name:
        raise BusError("invalid topic name '': must not be empty")
    ns = validate_namespace(namespace)
    if name == "~" or name.startswith("~/"):
        if not node_name:
            raise BusError(f"invalid topic name '{name}': '~' needs a node name")
        base = ns.rstrip("/") + "/" + node_name
        full = base + name[1:]
    elif name.startswith("/"):
        full = name
    else:
        full = ns.rstrip("/") + "/" + name
    if full == "/":
        raise BusError(f"invalid topic name '{name}'")
    return _check_fq(full, "topic name")


def dds_type_name(typename: str) -> str:
    """``pkg/msg/Name`` -> ``pkg::msg::dds_::Name_`` (the type chunk of keys and tokens)."""
    parts = typename.split("/")
    if len(parts) != 3 or not all(parts):
        raise BusError(f"invalid message type '{typename}': expected pkg/msg/Name")
    pkg, kind, name = parts
    return f"{pkg}::{kind}::dds_::{name}_"


def ros_type_name(dds_name: str) -> str:
    """``pkg::msg::dds_::Name_`` -> ``pkg/msg/Name``, as rmw_zenoh's graph cache demangles it.

    Text ending in '_' and holding ``dds_::``: the part before it with every '::' made '/',
    then the name without its final '_'. Other text is returned unchanged.
    """
    at = dds_name.find(_DDS_MARK)
    if not dds_name.endswith("_") or at < 0:
        return dds_name
    return dds_name[:at].replace("::", "/") + dds_name[at + len(_DDS_MARK):-1]


def topic_keyexpr(domain_id: int, topic: str, typename: str, type_hash: str) -> str:
    """The zenoh key of a topic: domain, topic without its outer slashes, DDS type, type hash."""
    return f"{domain_id}/{topic.strip('/')}/{dds_type_name(typename)}/{type_hash}"


def _id(text: str) -> int | str:
    # A plain decimal (no sign, no leading zero) as a number; anything else kept as text.
    return int(text) if text.isdecimal() and text.isascii() and str(int(text)) == text else text


def gid_of(token: str) -> bytes:
    """rmw_zenoh's 16-byte GID of an entity: XXH3-128 of its token, low then high half, LE."""
    return xxhash.xxh3_128_intdigest(token.encode()).to_bytes(16, "little")


@dataclass(frozen=True, slots=True)
class Entity:
    """One node, publisher, subscription, service or client of the ROS graph.

    ``namespace`` and ``enclave`` are ROS names ('/' for the root). For topic entities,
    ``topic`` is the fully qualified topic, ``typename`` the ROS type (``pkg/msg/Name``)
    and ``type_hash`` its RIHS01 text. ``token`` is the liveliness token an entity was read
    from (:meth:`parse`); its GID is the hash of that exact text, whoever wrote it.
    Node and entity ids are numbers in ours and in rmw_zenoh's tokens, but rmw_zenoh takes
    any non-empty text there, so a token's id that is not a plain decimal stays text.
    """

    domain_id: int
    zid: str
    node_id: int | str
    entity_id: int | str
    kind: EntityKind
    namespace: str
    node_name: str
    enclave: str = "/"
    topic: str = ""
    typename: str = ""
    type_hash: str = ""
    qos: QoS | None = None
    token: str = field(default="", compare=False, repr=False)

    @property
    def keyexpr(self) -> str:
        """The liveliness token of this entity, exactly as rmw_zenoh writes it."""
        chunks = [
            ADMIN_SPACE, str(self.domain_id), self.zid, str(self.node_id), str(self.entity_id),
            self.kind.value, mangle(self.enclave), mangle(self.namespace), mangle(self.node_name),
        ]
        if self.kind is not EntityKind.NODE:
            if self.qos is None:
                raise BusError(f"entity on '{self.topic}' has no QoS")
            chunks += [mangle(self.topic), mangle(dds_type_name(self.typename)), mangle(self.type_hash),
                       qos_to_keyexpr(self.qos)]
        return "/".join(chunks)

    @property
    def gid(self) -> bytes:
        """The entity's 16-byte GID (what its messages carry in their attachment)."""
        return gid_of(self.token or self.keyexpr)

    @property
    def node_fqn(self) -> str:
        """The node's fully qualified name, e.g. ``/ns/talker``."""
        return self.namespace.rstrip("/") + "/" + self.node_name

    @classmethod
    def parse(cls, token: str) -> Entity:
        """Read an rmw_zenoh liveliness token; raises BusError if it is not one."""
        parts = token.split("/")
        if len(parts) < 9 or parts[0] != ADMIN_SPACE or any(not p for p in parts):
            raise BusError(f"not an rmw_zenoh liveliness token: '{token}'")
        try:
            kind = EntityKind(parts[5])
            domain_id = int(parts[1])
        except ValueError as exc:
            raise BusError(f"not an rmw_zenoh liveliness token: '{token}'") from exc
        base = cls(domain_id, parts[2], _id(parts[3]), _id(parts[4]), kind, demangle(parts[7]), demangle(parts[8]),
                   demangle(parts[6]), token=token)
        if kind is EntityKind.NODE:
            return base
        if len(parts) < 13:
            raise BusError(f"liveliness token without topic fields: '{token}'")
        return cls(
            base.domain_id, base.zid, base.node_id, base.entity_id, kind, base.namespace, base.node_name,
            base.enclave, demangle(parts[9]), ros_type_name(demangle(parts[10])), demangle(parts[11]),
            qos_from_keyexpr(parts[12]), token,
        )
