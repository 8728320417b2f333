"""A ROS bus without ROS, with rclpy's shape: ROS 2 on DDS or rmw_zenoh, or ROS 1.

Processes using it talk to each other and to ROS nodes on the same wire: ROS 2 on DDS
(``"dds"``, the default, as a stock ROS 2), rmw_zenoh's key expressions, CDR payloads,
attachments and liveliness tokens (``"zenoh"``, Jazzy and later), or a ROS 1 master and
TCPROS (``"ros1"``). Nodes speak ROS through one backend seam (:mod:`robotmodel.bus._backend`,
its contract in the docstring), behind which each wire lives, with ``"inprocess"`` for one
process; :func:`default_wire` picks one from the environment as ROS does.

>>> from robotmodel.bus import Node, typestore
>>> String = typestore().types["std_msgs/msg/String"]   # any class with __msgtype__ works
>>> got = []
>>> with Node("demo", backend="inprocess", domain_id=7) as node:
...     sub = node.create_subscription(String, "/chatter", got.append, 10)
...     pub = node.create_publisher(String, "/chatter", 10)
...     pub.publish(String(data="hi"))
>>> [m.data for m in got]
['hi']

Topology (zenoh backend): peers on 127.0.0.1 only, meeting at the well-known port 7447
(``ROBOTMODEL_ZENOH_PORT``), or at ``connect=[...]`` endpoints, or as configured by
``ZENOH_SESSION_CONFIG_URI``; see :mod:`robotmodel.bus._config`. A session that finds no
router there starts ``robotmodel router`` detached, once (:func:`stop_router` ends it);
``robotmodel router`` also serves machines meeting. Topology (DDS backend): discovery on
loopback unless ``ROS_AUTOMATIC_DISCOVERY_RANGE`` or ``ROS_STATIC_PEERS`` widen it, as REP 2016
says (:mod:`robotmodel.bus._dds_qos`). ``ROS_DOMAIN_ID`` picks the domain.

Pieces: :class:`Node` (publishers, subscriptions, graph queries, parameters),
:class:`Context` (one session shared by nodes), :class:`Graph` and its :class:`Entity`
records, :class:`QoS` and tf2_ros's presets, the seam (:class:`Backend`,
:func:`open_backend`, :class:`Sample`, :class:`SampleInfo`, :class:`QoSEvent`), the zenoh
wire's helpers (:func:`topic_keyexpr`, :class:`Token` for liveliness tokens,
:class:`Attachment`), and :func:`codec_for` / :func:`register_codec` for message classes.
``Node(..., remappings=[...])`` takes ROS 2 remap rules (:class:`RemapRule`), as ``--ros-args -r`` gives them to rcl.
"""

from __future__ import annotations

from robotmodel.bus._attachment import ATTACHMENT_SIZE, Attachment
from robotmodel.bus._backend import (
    BACKENDS,
    ROS1,
    Backend,
    Entity,
    EntityKind,
    LocalParameters,
    MessageType,
    NodeHandle,
    ParameterStore,
    PublisherHandle,
    QoSEvent,
    Sample,
    SampleInfo,
    open_backend,
)
from robotmodel.bus._codec import (
    Codec,
    RosbagsCodec,
    TFRecords,
    codec_for,
    register_codec,
    register_encoding,
    typestore,
)
from robotmodel.bus._graph import Graph
from robotmodel.bus._names import dds_type_name, resolve_topic, ros_type_name
from robotmodel.bus._node import Context, Node, Publisher, RawMessage, Subscription, default_domain_id
from robotmodel.bus._qos import (
    QOS_DEFAULT,
    QOS_LATCHED,
    QOS_TF,
    QOS_TF_STATIC,
    QOS_TF_STATIC_LISTENER,
    Durability,
    History,
    QoS,
    Reliability,
    incompatible_policy,
)
from robotmodel.bus._remap import RemapKind, RemapRule, parse_rules, remap_topic
from robotmodel.bus._ros1clock import TopicClock, node_clock
from robotmodel.bus._ros1codec import ros1_codec
from robotmodel.bus._router import run_router, stop_router
from robotmodel.bus._select import default_wire
from robotmodel.bus._zenoh_names import Token, gid_of, mangle, qos_from_keyexpr, qos_to_keyexpr, topic_keyexpr
from robotmodel.errors import BusError

register_encoding(ROS1, ros1_codec)

__all__ = [
    "ATTACHMENT_SIZE",
    "BACKENDS",
    "QOS_DEFAULT",
    "QOS_LATCHED",
    "QOS_TF",
    "QOS_TF_STATIC",
    "QOS_TF_STATIC_LISTENER",
    "Attachment",
    "Backend",
    "BusError",
    "Codec",
    "Context",
    "Durability",
    "Entity",
    "EntityKind",
    "Graph",
    "History",
    "LocalParameters",
    "MessageType",
    "Node",
    "NodeHandle",
    "ParameterStore",
    "Publisher",
    "PublisherHandle",
    "QoS",
    "QoSEvent",
    "RawMessage",
    "Reliability",
    "RemapKind",
    "RemapRule",
    "RosbagsCodec",
    "Sample",
    "SampleInfo",
    "Subscription",
    "TFRecords",
    "Token",
    "TopicClock",
    "codec_for",
    "dds_type_name",
    "default_domain_id",
    "default_wire",
    "gid_of",
    "incompatible_policy",
    "mangle",
    "node_clock",
    "open_backend",
    "parse_rules",
    "qos_from_keyexpr",
    "qos_to_keyexpr",
    "register_codec",
    "remap_topic",
    "resolve_topic",
    "ros_type_name",
    "run_router",
    "stop_router",
    "topic_keyexpr",
    "typestore",
]
