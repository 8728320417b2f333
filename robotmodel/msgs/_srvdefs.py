"""ROS 2 service definitions known to robotmodel, registered in the shared typestore on first use.

A service ``pkg/srv/Name`` is two messages, ``pkg/srv/Name_Request`` and
``pkg/srv/Name_Response``. ROS 2 (Jazzy) also describes the service itself: a struct
``pkg/srv/Name`` of ``request_message``, ``response_message`` and ``event_message``
(``pkg/srv/Name_Event``: ``service_msgs/msg/ServiceEventInfo info``, ``Name_Request[<=1]
request``, ``Name_Response[<=1] response``), as rosidl_generator_type_description builds it,
whose RIHS01 hash names the service (rmw_zenoh puts it in the service's key expression).
:func:`register_service_types` registers all four in the typestore, so rosbags serializes
the messages and hashes the service as rosidl does.

Known services: rcl_interfaces' parameter services, std_srvs' Empty, Trigger and SetBool,
and example_interfaces' AddTwoInts; :func:`register_service` adds others.
"""

from __future__ import annotations

import threading
from typing import Any

from robotmodel.errors import BusError
from robotmodel.msgs._convert import typestore

__all__ = ["SERVICES", "check_service_name", "register_service", "register_service_types"]

# ServiceEventInfo's client_gid is char[16], which rosidl describes (and hashes) as uint8[16].
_SERVICE_EVENT_INFO = ("service_msgs/msg/ServiceEventInfo", """
uint8 REQUEST_SENT = 0
uint8 REQUEST_RECEIVED = 1
uint8 RESPONSE_SENT = 2
uint8 RESPONSE_RECEIVED = 3
uint8 event_type
builtin_interfaces/Time stamp
uint8[16] client_gid
int64 sequence_number
""")

#: Service type -> (request fields, response fields), in .msg syntax.
SERVICES: dict[str, tuple[str, str]] = {
    "rcl_interfaces/srv/ListParameters": ("uint64 DEPTH_RECURSIVE=0\nstring[] prefixes\nuint64 depth\n",
                                          "rcl_interfaces/ListParametersResult result\n"),
    "rcl_interfaces/srv/GetParameters": ("string[] names\n", "rcl_interfaces/ParameterValue[] values\n"),
    "rcl_interfaces/srv/SetParameters": ("rcl_interfaces/Parameter[] parameters\n",
                                         "rcl_interfaces/SetParametersResult[] results\n"),
    "rcl_interfaces/srv/SetParametersAtomically": ("rcl_interfaces/Parameter[] parameters\n",
                                                   "rcl_interfaces/SetParametersResult result\n"),
    "rcl_interfaces/srv/DescribeParameters": ("string[] names\n",
                                              "rcl_interfaces/ParameterDescriptor[] descriptors\n"),
    "rcl_interfaces/srv/GetParameterTypes": ("string[] names\n", "uint8[] types\n"),
    "std_srvs/srv/Empty": ("", ""),
    "std_srvs/srv/Trigger": ("", "bool success\nstring message\n"),
    "std_srvs/srv/SetBool": ("bool data\n", "bool success\nstring message\n"),
    "example_interfaces/srv/AddTwoInts": ("int64 a\nint64 b\n", "int64 sum\n"),
}
_lock = threading.Lock()
_EMPTY = "uint8 structure_needs_at_least_one_member\n"


def _unmsg(value: Any) -> Any:
    if isinstance(value, str):
        return value.replace("/srv/msg/", "/srv/")
    if isinstance(value, tuple):
        return tuple(_unmsg(v) for v in value)
    if isinstance(value, list):
        return [_unmsg(v) for v in value]
    return value


def register_service(typename: str, request: str, response: str) -> None:
    """Make ``pkg/srv/Name`` known from its request and response fields (.msg syntax)."""
    check_service_name(typename)
    with _lock:
        SERVICES[typename] = (request, response)


def check_service_name(typename: str) -> None:
    parts = typename.split("/")
    if len(parts) != 3 or parts[1] != "srv" or not all(parts):
        raise BusError(f"'{typename}' is not a service type name (expected 'pkg/srv/Name')")


def register_service_types(typename: str) -> None:
    """Register ``pkg/srv/Name`` and its request, response and event types (once)."""
    from rosbags.typesys import get_types_from_msg

    with _lock:
        found = SERVICES.get(typename)
    if found is None:
        raise BusError(f"unknown service type '{typename}' (robotmodel knows: {', '.join(sorted(SERVICES))})")
    store = typestore()
    if typename + "_Event" in store.fielddefs:
        return
    request, response = found
    types: dict[str, Any] = {}
    info = get_types_from_msg(_SERVICE_EVENT_INFO[1], _SERVICE_EVENT_INFO[0])
    if store.fielddefs.get(_SERVICE_EVENT_INFO[0]) != info[_SERVICE_EVENT_INFO[0]]:
        # rosbags' Jazzy store says char[16]: same bytes, another hash; rosidl's form replaces it.
        store.fielddefs[_SERVICE_EVENT_INFO[0]] = info[_SERVICE_EVENT_INFO[0]]
    short = typename.rsplit("/", 1)[1]
    texts = {
        # rosidl gives an empty message one member, which its type description (and so the hash) shows.
        "_Request": request or _EMPTY,
        "_Response": response or _EMPTY,
        "_Event": f"service_msgs/ServiceEventInfo info\n{short}_Request[<=1] request\n"
                  f"{short}_Response[<=1] response\n",
        "": f"{short}_Request request_message\n{short}_Response response_message\n{short}_Event event_message\n",
    }
    for suffix, text in texts.items():
        types.update(get_types_from_msg(text, typename + suffix))
    # rosbags' parser files every type under 'msg'; a service's types live under 'srv'.
    store.register({_unmsg(name): _unmsg(desc) for name, desc in types.items()})
