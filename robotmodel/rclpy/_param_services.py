"""The ROS 2 parameter services of a node, serving a :class:`ParameterTable` on the bus.

Six services under the node's name, as rclcpp and rclpy offer them:
``~/describe_parameters``, ``~/get_parameter_types``, ``~/get_parameters``,
``~/list_parameters``, ``~/set_parameters``, ``~/set_parameters_atomically``, of the
rcl_interfaces types, so ``ros2 param`` and rclpy's ``AsyncParameterClient`` read and
change the node's parameters. Answers follow rclpy's: ``get_parameters``, ``get_parameter_types``
and ``describe_parameters`` answer nothing when a name is undeclared; ``list_parameters``
names them in declaration order; a set that raises (an
undeclared name) answers "unsuccessful" with the error's text.

``dispatch(job)`` decides where each request is handled: an rclpy stand-in node hands it to
its executor (a node that is not spun does not answer, as in ROS); robot_state_publisher
runs it on the bus's thread.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from robotmodel.errors import RobotModelError
from robotmodel.msgs._dynamic import service_class
from robotmodel.msgs.rcl_interfaces.msg import ListParametersResult, SetParametersResult
from robotmodel.rclpy._params import ParameterTable
from robotmodel.rclpy.parameter import Parameter

if TYPE_CHECKING:
    from robotmodel.bus import Node as BusNode

__all__ = ["SERVICES", "serve_parameters"]

Dispatch = Callable[[Callable[[], None]], None]
#: Service name suffix -> its rcl_interfaces type.
SERVICES = {
    "describe_parameters": "rcl_interfaces/srv/DescribeParameters",
    "get_parameter_types": "rcl_interfaces/srv/GetParameterTypes",
    "get_parameters": "rcl_interfaces/srv/GetParameters",
    "list_parameters": "rcl_interfaces/srv/ListParameters",
    "set_parameters": "rcl_interfaces/srv/SetParameters",
    "set_parameters_atomically": "rcl_interfaces/srv/SetParametersAtomically",
}


def _params(msgs: list[Any]) -> list[Parameter]:
    return [Parameter.from_parameter_msg(m) for m in msgs]


def _handlers(table: ParameterTable) -> dict[str, Callable[[Any, Any], None]]:
    def describe(req: Any, resp: Any) -> None:
        try:
            resp.descriptors = [table.descriptor(name) for name in req.names]
        except RobotModelError:
            resp.descriptors = []

    def types(req: Any, resp: Any) -> None:
        try:
            resp.types = [int(table.get(name).type_) for name in req.names]
        except RobotModelError:
            resp.types = []

    def get(req: Any, resp: Any) -> None:
        try:
            resp.values = [table.get(name).get_parameter_value() for name in req.names]
        except RobotModelError:
            resp.values = []

    def listing(req: Any, resp: Any) -> None:
        names, prefixes = table.list(req.prefixes, int(req.depth))
        resp.result = ListParametersResult(names=names, prefixes=prefixes)

    def set_each(req: Any, resp: Any) -> None:
        results = []
        for param in _params(req.parameters):
            try:
                results.append(table.set_atomically([param]))
            except RobotModelError as exc:
                results.append(SetParametersResult(successful=False, reason=str(exc)))
        resp.results = results

    def set_all(req: Any, resp: Any) -> None:
        try:
            resp.result = table.set_atomically(_params(req.parameters))
        except RobotModelError as exc:
            resp.result = SetParametersResult(successful=False, reason=str(exc))

    return {"describe_parameters": describe, "get_parameter_types": types, "get_parameters": get,
            "list_parameters": listing, "set_parameters": set_each, "set_parameters_atomically": set_all}


def serve_parameters(node: BusNode, table: ParameterTable, dispatch: Dispatch | None = None) -> list[Any]:
    """Declare the six services of ``node`` (a bus node) over ``table``; returns the servers."""
    servers = []
    handlers = _handlers(table)
    for suffix, srv_type in SERVICES.items():
        cls = service_class(srv_type)
        handler = handlers[suffix]

        def on_request(request: Any, respond: Callable[[Any], None], _rid: Any,
                       handler: Callable[[Any, Any], None] = handler, cls: Any = cls) -> None:
            def job() -> None:
                response = cls.Response()
                handler(request, response)
                respond(response)

            if dispatch is None:
                job()
            else:
                dispatch(job)

        servers.append(node.create_service(srv_type, "~/" + suffix, on_request, request_type=cls.Request,
                                           response_type=cls.Response))
    return servers
