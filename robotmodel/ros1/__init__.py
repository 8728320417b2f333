"""The ROS 1 wire: master and parameter server clients, the slave API, TCPROS, a node.

Pure Python on the project's dependencies: rosbags' ROS 1 Noetic type store for message
definitions, md5sums and serialization; the standard library's XML-RPC for the master and the
slave API; sockets and threads for TCPROS. :class:`Ros1Node` is what the bus's ROS 1 backend
wraps; the pieces are public for tests and tools that speak one API only.

Errors are :class:`robotmodel.errors.Ros1Error` (a :class:`BusError`) and its
:class:`robotmodel.errors.MasterError` (naming the master URI and the call).
"""

from __future__ import annotations

from robotmodel.errors import MasterError, Ros1Error
from robotmodel.ros1._address import NodeAddress, address_override, node_address
from robotmodel.ros1._handles import Ros1Publisher, Ros1Subscriber
from robotmodel.ros1._header import decode_header, encode_header
from robotmodel.ros1._master import DEFAULT_MASTER_URI, MasterClient, ParamClient, master_uri_from_env, xmlrpc_call
from robotmodel.ros1._msgs import Ros1Type, deserialize, message_type, serialize, typestore, wire_name
from robotmodel.ros1._names import resolve_name
from robotmodel.ros1._node import Ros1Node
from robotmodel.ros1._slave import SLAVE_METHODS, SlaveServer

__all__ = [
    "DEFAULT_MASTER_URI",
    "SLAVE_METHODS",
    "MasterClient",
    "MasterError",
    "NodeAddress",
    "ParamClient",
    "Ros1Error",
    "Ros1Node",
    "Ros1Publisher",
    "Ros1Subscriber",
    "Ros1Type",
    "SlaveServer",
    "address_override",
    "decode_header",
    "deserialize",
    "encode_header",
    "master_uri_from_env",
    "message_type",
    "node_address",
    "resolve_name",
    "serialize",
    "typestore",
    "wire_name",
    "xmlrpc_call",
]
