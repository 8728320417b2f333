"""rclpy.parameter_client: AsyncParameterClient, another node's parameters through its services.

Each call sends one request to the remote node's parameter service and returns the
:class:`~robotmodel.rclpy.task.Future` of its response (spin the local node to complete it),
as rclpy's. Parameters go as :class:`~robotmodel.rclpy.parameter.Parameter` objects.
"""

from __future__ import annotations

import time
from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

from robotmodel.msgs.rcl_interfaces.srv import (
    DescribeParameters,
    GetParameters,
    GetParameterTypes,
    ListParameters,
    SetParameters,
    SetParametersAtomically,
)
from robotmodel.rclpy.parameter import Parameter
from robotmodel.rclpy.task import Future

if TYPE_CHECKING:
    from robotmodel.rclpy._entities import Client
    from robotmodel.rclpy.node import Node

__all__ = ["AsyncParameterClient"]


class AsyncParameterClient:
    """Clients of ``remote_node_name``'s six parameter services."""

    def __init__(self, node: Node, remote_node_name: str, qos_profile: Any = None,
                 callback_group: Any = None) -> None:
        del qos_profile
        base = remote_node_name if remote_node_name.startswith("/") else \
            node.get_namespace().rstrip("/") + "/" + remote_node_name
        self.remote_node_name = remote_node_name

        def client(srv: Any, suffix: str) -> Client:
            return node.create_client(srv, f"{base}/{suffix}", callback_group=callback_group)

        self._list = client(ListParameters, "list_parameters")
        self._get = client(GetParameters, "get_parameters")
        self._set = client(SetParameters, "set_parameters")
        self._set_atomically = client(SetParametersAtomically, "set_parameters_atomically")
        self._describe = client(DescribeParameters, "describe_parameters")
        self._types = client(GetParameterTypes, "get_parameter_types")
        self._clients = [self._list, self._get, self._set, self._set_atomically, self._describe, self._types]

    def services_are_ready(self) -> bool:
        """Whether all six services are known."""
        return all(c.service_is_ready() for c in self._clients)

    def wait_for_services(self, timeout_sec: float | None = None) -> bool:
        """Wait until all six are known; False at the timeout."""
        end = None if timeout_sec is None else time.monotonic() + timeout_sec
        for c in self._clients:
            left = None if end is None else max(0.0, end - time.monotonic())
            if not c.wait_for_service(left):
                return False
        return True

    def list_parameters(self, prefixes: Sequence[str] | None = None, depth: int | None = None) -> Future:
        """The remote parameters' names (under ``prefixes``, to ``depth`` dots)."""
        return self._list.call_async(ListParameters.Request(prefixes=list(prefixes or []), depth=depth or 0))

    def get_parameters(self, names: Sequence[str]) -> Future:
        """The values of ``names`` (rcl_interfaces ParameterValue messages)."""
        return self._get.call_async(GetParameters.Request(names=list(names)))

    def set_parameters(self, parameters: Sequence[Parameter]) -> Future:
        """Set each; one SetParametersResult per parameter."""
        return self._set.call_async(SetParameters.Request(parameters=[p.to_parameter_msg() for p in parameters]))

    def set_parameters_atomically(self, parameters: Sequence[Parameter]) -> Future:
        """Set all or none."""
        return self._set_atomically.call_async(
            SetParametersAtomically.Request(parameters=[p.to_parameter_msg() for p in parameters]))

    def describe_parameters(self, names: Sequence[str]) -> Future:
        """The descriptors of ``names``."""
        return self._describe.call_async(DescribeParameters.Request(names=list(names)))

    def get_parameter_types(self, names: Sequence[str]) -> Future:
        """The types of ``names``."""
        return self._types.call_async(GetParameterTypes.Request(names=list(names)))

    def destroy(self) -> None:
        """Withdraw the six clients."""
        for c in self._clients:
            c.destroy()
