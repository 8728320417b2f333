"""A ROS 2 bus without ROS: zenoh in rmw_zenoh's wire format, with rclpy's shape.

Processes using it talk to each other and to ROS 2 nodes running rmw_zenoh (Jazzy and
later): the same key expressions, CDR payloads, attachments and liveliness tokens.

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
``ZENOH_SESSION_CONFIG_URI``; see :mod:`robotmodel.bus._config`. ``robotmodel router``
runs a zenoh router for machines to meet. ``ROS_DOMAIN_ID`` picks the domain.

Pieces: :class:`Node` (publishers, subscriptions, graph queries), :class:`Context` (one
session shared by nodes), :class:`QoS` and tf2_ros's presets, the wire helpers
(:func:`topic_keyexpr`, :class:`Entity` for liveliness tokens, :class:`Attachment`), and
:func:`codec_for` / :func:`register_codec` for message classes. ``Node(..., remappings=[...])``
takes ROS 2 remap rules (:class:`RemapRule`), as ``--ros-args -r`` gives them to rcl.
"""

from __future__ import annotations

from robotmodel.bus._attachment import ATTACHMENT_SIZE, Attachment
from robotmodel.bus._backend import Backend, RawSample
from robotmodel.bus._codec import Codec, RosbagsCodec, TFRecords, codec_for, register_codec, typestore
from robotmodel.bus._graph import Graph
from robotmodel.bus._names import (
    Entity,
    EntityKind,
    dds_type_name,
    gid_of,
    mangle,
    resolve_topic,
    ros_type_name,
    topic_keyexpr,
)
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
    qos_from_keyexpr,
    qos_to_keyexpr,
)
from robotmodel.bus._remap import RemapKind, RemapRule, parse_rules, remap_topic
from robotmodel.errors import BusError

__all__ = [
    "ATTACHMENT_SIZE",
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
    "Node",
    "Publisher",
    "QoS",
    "RawMessage",
    "RawSample",
    "Reliability",
    "RemapKind",
    "RemapRule",
    "RosbagsCodec",
    "Subscription",
    "TFRecords",
    "codec_for",
    "dds_type_name",
    "default_domain_id",
    "gid_of",
    "mangle",
    "parse_rules",
    "qos_from_keyexpr",
    "qos_to_keyexpr",
    "register_codec",
    "remap_topic",
    "resolve_topic",
    "ros_type_name",
    "topic_keyexpr",
    "typestore",
]

