"""ROS 2 service types on the bus: :class:`ServiceType` (request and response types, the service's RIHS01 hash).

The definitions and their registration in the typestore live in :mod:`robotmodel.msgs._srvdefs`.
"""

from __future__ import annotations

from functools import cache

from robotmodel.bus._backend import MessageType, ServiceType
from robotmodel.bus._codec import typestore
from robotmodel.msgs._srvdefs import check_service_name, register_service_types
from robotmodel.msgs._srvdefs import register_service as _register_service

__all__ = ["register_service", "service_type"]


def register_service(typename: str, request: str, response: str) -> None:
    """Make ``pkg/srv/Name`` known from its request and response fields (.msg syntax)."""
    _register_service(typename, request, response)
    service_type.cache_clear()


@cache
def service_type(typename: str) -> ServiceType:
    """The :class:`ServiceType` of ``pkg/srv/Name`` (its types registered in the typestore)."""
    check_service_name(typename)
    register_service_types(typename)
    store = typestore()
    req, resp = typename + "_Request", typename + "_Response"
    return ServiceType(typename, MessageType(req, str(store.hash_rihs01(req))),
                       MessageType(resp, str(store.hash_rihs01(resp))), str(store.hash_rihs01(typename)))
