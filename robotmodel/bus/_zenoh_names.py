"""rmw_zenoh's names on the wire: topic key expressions, liveliness tokens, GIDs and QoS text.

- Topic key: ``<domain>/<topic without its leading '/'>/<pkg>::msg::dds_::<Type>_/RIHS01_<hex>``.
- Liveliness token (graph discovery), rmw_zenoh's 9 or 13 chunks::

      @ros2_lv/<domain>/<zid>/<node id>/<entity id>/<NN|MP|MS|SS|SC>/<enclave>/<namespace>/<node>
          [/<topic>/<dds type>/<type hash>/<qos>]

  with every '/' inside a chunk written '%' (so the root namespace is '%').
- GID: XXH3-128 of the whole token, low 64 bits then high 64 bits, little-endian.
- QoS text in a token: ``rel:dur:hist,depth:dl_s,dl_ns:ls_s,ls_ns:liv,lease_s,lease_ns``,
  leaving every field that equals rmw_zenoh's own default (RELIABLE, VOLATILE, KEEP_LAST,
  depth 42, infinite durations, AUTOMATIC liveliness) empty; enum fields are written as
  rmw's integer values. Reading it back accepts, per policy, exactly the integers rmw_zenoh's
  own tables hold (so a token rmw_zenoh ignores is ignored here too).

Only the zenoh wire uses this module (it is below the backend seam).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import xxhash

from robotmodel.bus._backend import Entity, EntityKind
from robotmodel.bus._names import dds_type_name, ros_type_name
from robotmodel.bus._qos import (
    DEFAULT_DEPTH,
    DURATION_INFINITE_NS,
    Durability,
    History,
    Liveliness,
    QoS,
    Reliability,
)
from robotmodel.errors import BusError

__all__ = [
    "ADMIN_SPACE",
    "TOKEN_KINDS",
    "Token",
    "demangle",
    "gid_of",
    "mangle",
    "qos_from_keyexpr",
    "qos_to_keyexpr",
    "topic_keyexpr",
]

ADMIN_SPACE = "@ros2_lv"
#: The entity kinds of rmw_zenoh's graph, by their token text.
TOKEN_KINDS: dict[EntityKind, str] = {
    EntityKind.NODE: "NN",
    EntityKind.PUBLISHER: "MP",
    EntityKind.SUBSCRIPTION: "MS",
    EntityKind.SERVICE: "SS",
    EntityKind.CLIENT: "SC",
}
_KIND_OF = {text: kind for kind, text in TOKEN_KINDS.items()}


def mangle(name: str) -> str:
    """rmw_zenoh's mangling: every '/' becomes '%' (a key expression chunk has no '/')."""
    return name.replace("/", "%")


def demangle(chunk: str) -> str:
    """Undo :func:`mangle`."""
    return chunk.replace("%", "/")


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
class Token:
    """One entity of the ROS graph as rmw_zenoh's liveliness token names it.

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
            TOKEN_KINDS[self.kind], mangle(self.enclave), mangle(self.namespace), mangle(self.node_name),
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

    def entity(self) -> Entity:
        """The graph's wire-neutral record of this entity."""
        return Entity(self.kind, self.node_name, self.namespace, self.enclave, self.topic, self.typename,
                      self.type_hash, self.qos, self.gid, f"{self.zid}/{self.node_id}")

    @classmethod
    def parse(cls, token: str) -> Token:
        """Read an rmw_zenoh liveliness token; raises BusError if it is not one."""
        parts = token.split("/")
        if len(parts) < 9 or parts[0] != ADMIN_SPACE or any(not p for p in parts):
            raise BusError(f"not an rmw_zenoh liveliness token: '{token}'")
        try:
            kind = _KIND_OF[parts[5]]
            domain_id = int(parts[1])
        except (KeyError, ValueError) as exc:
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


_BASE = QoS(DEFAULT_DEPTH, Reliability.RELIABLE, Durability.VOLATILE, History.KEEP_LAST)
_NS = 1_000_000_000


def _sec_nsec(ns: int) -> tuple[int, int]:
    # rmw_time_t splits a duration in whole seconds and the nanosecond rest.
    return divmod(ns, _NS)


def qos_to_keyexpr(qos: QoS) -> str:
    """rmw_zenoh's compact QoS text for a liveliness token (defaults left empty)."""
    q = qos.resolved()

    def field(value: int, default: int) -> str:
        return "" if value == default else str(int(value))

    dl_s, dl_ns = _sec_nsec(q.deadline_ns)
    ls_s, ls_ns = _sec_nsec(q.lifespan_ns)
    lv_s, lv_ns = _sec_nsec(q.liveliness_lease_ns)
    inf_s, inf_ns = _sec_nsec(DURATION_INFINITE_NS)
    return (
        f"{field(q.reliability, _BASE.reliability)}:{field(q.durability, _BASE.durability)}:"
        f"{field(q.history, _BASE.history)},{field(q.depth, _BASE.depth)}:"
        f"{field(dl_s, inf_s)},{field(dl_ns, inf_ns)}:{field(ls_s, inf_s)},{field(ls_ns, inf_ns)}:"
        f"{field(q.liveliness, _BASE.liveliness)},{field(lv_s, inf_s)},{field(lv_ns, inf_ns)}"
    )


def qos_from_keyexpr(text: str) -> QoS:
    """Parse rmw_zenoh's compact QoS text (empty fields are its defaults); raises BusError."""
    parts = text.split(":")
    groups = [p.split(",") for p in parts]
    if len(parts) < 6 or len(groups[2]) < 2 or len(groups[3]) < 2 or len(groups[4]) < 2 or len(groups[5]) < 3:
        raise BusError(f"invalid QoS text '{text}' in a liveliness token")
    inf_s, inf_ns = _sec_nsec(DURATION_INFINITE_NS)

    def num(s: str, default: int) -> int:
        if not s:
            return default
        if not s.isdigit():
            raise BusError(f"invalid QoS text '{text}' in a liveliness token")
        return int(s)

    def policy(s: str, default: int) -> int:
        # rmw_zenoh looks policies up by their exact decimal text ('01' is not 1).
        value = num(s, default)
        if s and s != str(value):
            raise BusError(f"invalid QoS text '{text}' in a liveliness token")
        return value

    def dur(s: str, ns: str) -> int:
        sec, nsec = num(s, inf_s), num(ns, inf_ns)
        return sec * _NS + nsec

    try:
        return QoS(
            depth=num(groups[2][1], DEFAULT_DEPTH),
            reliability=Reliability(policy(parts[0], Reliability.RELIABLE)),
            durability=Durability(policy(parts[1], Durability.VOLATILE)),
            history=History(policy(groups[2][0], History.KEEP_LAST)),
            deadline_ns=dur(groups[3][0], groups[3][1]),
            lifespan_ns=dur(groups[4][0], groups[4][1]),
            liveliness=Liveliness(policy(groups[5][0], Liveliness.AUTOMATIC)),
            liveliness_lease_ns=dur(groups[5][1], groups[5][2]),
        )
    except ValueError as exc:
        raise BusError(f"invalid QoS text '{text}' in a liveliness token: {exc}") from exc
