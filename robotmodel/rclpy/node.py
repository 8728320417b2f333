"""rclpy.node: Node, rclpy's shape on robotmodel's bus.

A Node lives in a context (the default one unless given) and on its wire; its name,
namespace, remaps and parameter overrides come from the context's ``--ros-args`` (``-r``,
``-p``, ``--params-file``) as rcl reads them, then from the constructor's
``cli_args``/``parameter_overrides``. Every node declares ``use_sim_time`` (false): set
true, its clock follows ``/clock``. It serves the ROS 2 parameter services (unless
``start_parameter_services=False``), handled by the executor that spins it.
"""

from __future__ import annotations

import contextlib
import threading
from collections.abc import Callable, Sequence
from typing import Any, TypeVar

from robotmodel.bus import Node as BusNode
from robotmodel.errors import BusError
from robotmodel.msgs.rcl_interfaces.msg import ParameterDescriptor
from robotmodel.rcl import logger_name, node_params, take_ros_args
from robotmodel.rclpy._entities import Client, Publisher, Rate, Service, Subscription, Timer
from robotmodel.rclpy._param_services import serve_parameters
from robotmodel.rclpy._params import ParameterTable
from robotmodel.rclpy.callback_groups import CallbackGroup, MutuallyExclusiveCallbackGroup
from robotmodel.rclpy.clock import Clock, ROSClock
from robotmodel.rclpy.context import Context, get_default_context
from robotmodel.rclpy.exceptions import ParameterNotDeclaredException
from robotmodel.rclpy.logging import RcutilsLogger
from robotmodel.rclpy.parameter import Parameter
from robotmodel.rclpy.qos import QoSProfile, to_bus_qos

__all__ = ["Node"]

E = TypeVar("E")


class Node:
    """rclpy's Node (see the module docstring)."""

    def __init__(self, node_name: str, *, context: Context | None = None, cli_args: Sequence[str] | None = None,
                 namespace: str | None = None, use_global_arguments: bool = True, enable_rosout: bool = True,
                 start_parameter_services: bool = True, parameter_overrides: Sequence[Parameter] | None = None,
                 allow_undeclared_parameters: bool = False,
                 automatically_declare_parameters_from_overrides: bool = False) -> None:
        del enable_rosout
        self._context = context or get_default_context()
        words = list(self._context.argv[1:]) if use_global_arguments else []
        if cli_args:
            words += ["--ros-args", *cli_args] if "--ros-args" not in cli_args else list(cli_args)
        ros, _rest = take_ros_args(words, node_name)
        name = ros.node_name or node_name
        ns = ros.namespace or namespace or "/"
        if not ns.startswith("/"):
            ns = "/" + ns
        self.bus_node = BusNode(name, ns, context=self._context.bus, remappings=ros.remaps)
        self._lock = threading.RLock()
        self._entities: list[Any] = []
        self._executors: set[Any] = set()
        self.executor: Any = None
        self.default_callback_group: CallbackGroup = MutuallyExclusiveCallbackGroup()
        self._logger = RcutilsLogger(logger_name(self.bus_node.namespace, self.bus_node.name))
        overrides: dict[str, Any] = dict(node_params(ros, self.bus_node.namespace, self.bus_node.name))
        for param in parameter_overrides or ():
            overrides[param.name] = param.value
        self._parameters = ParameterTable(overrides, allow_undeclared_parameters)
        self._clock = ROSClock()
        self._clock_sub: Any = None
        self._parameters.add_post_set(self._follow_sim_time)
        self.declare_parameter("use_sim_time", False)
        # Declared by every Jazzy node; robotmodel serves no ~/get_type_description, whatever its value.
        self.declare_parameter("start_type_description_service", True, ParameterDescriptor(
            description="If enabled, start the ~/get_type_description service.", read_only=True))
        if automatically_declare_parameters_from_overrides:
            for key, value in overrides.items():
                if not self.has_parameter(key):
                    self.declare_parameter(key, value)
        self._param_servers: list[Any] = []
        if start_parameter_services:
            # A wire without ROS 2 services (ROS 1) refuses them: the parameters stay node-local.
            with contextlib.suppress(BusError):
                self._param_servers = serve_parameters(self.bus_node, self._parameters, self._dispatch)
        self._context.on_shutdown(self.destroy_node)

    # -- identity --------------------------------------------------------------------------------
    @property
    def context(self) -> Context:
        """The node's context."""
        return self._context

    @property
    def handle(self) -> BusNode:
        """The bus node underneath."""
        return self.bus_node

    def get_name(self) -> str:
        """The node's name."""
        return self.bus_node.name

    def get_namespace(self) -> str:
        """The node's namespace."""
        return self.bus_node.namespace

    def get_fully_qualified_name(self) -> str:
        """``/namespace/name``."""
        return self.bus_node.fully_qualified_name

    def get_logger(self) -> RcutilsLogger:
        """The node's logger (named as rcl names it: ``ns.name``)."""
        return self._logger

    def get_clock(self) -> ROSClock:
        """The node's ROS clock (``/clock`` while use_sim_time is true)."""
        return self._clock

    # -- executor plumbing -----------------------------------------------------------------------
    def _notify(self) -> None:
        for executor in list(self._executors):
            executor._wake()

    def _waitables(self) -> list[Any]:
        with self._lock:
            return [e for e in self._entities if not isinstance(e, (Publisher, Rate))]

    def _forget(self, entity: Any) -> None:
        with self._lock:
            if entity in self._entities:
                self._entities.remove(entity)

    def _add(self, entity: E) -> E:
        with self._lock:
            self._entities.append(entity)
        self._notify()
        return entity

    def _dispatch(self, job: Callable[[], None]) -> None:
        # Parameter requests run in the executor (in the default group), as rclpy's services do.
        self._add(_Job(self, job))

    # -- publishers, subscriptions, timers -------------------------------------------------------
    def create_publisher(self, msg_type: Any, topic: str, qos_profile: QoSProfile | int, *,
                         callback_group: CallbackGroup | None = None, **_options: Any) -> Publisher:
        """A publisher of ``msg_type`` on ``topic``."""
        del callback_group
        inner = self.bus_node.create_publisher(msg_type, topic, to_bus_qos(qos_profile))
        return Publisher(self, inner, msg_type, qos_profile)

    def create_subscription(self, msg_type: Any, topic: str, callback: Callable[[Any], None],
                            qos_profile: QoSProfile | int, *, callback_group: CallbackGroup | None = None,
                            raw: bool = False, **_options: Any) -> Subscription:
        """Call ``callback(msg)`` (in the executor) for each message on ``topic``."""
        return self._add(Subscription(self, msg_type, topic, callback, to_bus_qos(qos_profile), callback_group,
                                      raw))

    def create_timer(self, timer_period_sec: float, callback: Callable[..., Any] | None,
                     callback_group: CallbackGroup | None = None, clock: Clock | None = None,
                     autostart: bool = True) -> Timer:
        """Call ``callback()`` every ``timer_period_sec`` of the node's clock, in the executor."""
        return self._add(Timer(self, timer_period_sec, callback, clock or self._clock, callback_group, autostart))

    def create_rate(self, frequency: float, clock: Clock | None = None) -> Rate:
        """A Rate at ``frequency`` Hz on the node's clock."""
        return Rate(self, frequency, clock or self._clock)

    def create_service(self, srv_type: Any, srv_name: str, callback: Callable[[Any, Any], Any], *,
                       qos_profile: Any = None, callback_group: CallbackGroup | None = None) -> Service:
        """Serve ``srv_name``: ``callback(request, response)`` returns the response, in the executor."""
        del qos_profile
        return self._add(Service(self, srv_type, srv_name, callback, callback_group))

    def create_client(self, srv_type: Any, srv_name: str, *, qos_profile: Any = None,
                      callback_group: CallbackGroup | None = None) -> Client:
        """A client of ``srv_name``."""
        del qos_profile
        return self._add(Client(self, srv_type, srv_name, callback_group))

    def destroy_publisher(self, publisher: Publisher) -> bool:
        """Withdraw a publisher."""
        publisher.destroy()
        return True

    def destroy_subscription(self, subscription: Subscription) -> bool:
        """Withdraw a subscription."""
        subscription.destroy()
        return True

    def destroy_timer(self, timer: Timer) -> bool:
        """Withdraw a timer."""
        timer.destroy()
        return True

    def destroy_service(self, service: Service) -> bool:
        """Withdraw a service."""
        service.destroy()
        return True

    def destroy_client(self, client: Client) -> bool:
        """Withdraw a client."""
        client.destroy()
        return True

    def destroy_rate(self, rate: Rate) -> bool:
        """Nothing to withdraw."""
        del rate
        return True

    # -- graph -----------------------------------------------------------------------------------
    def count_publishers(self, topic_name: str) -> int:
        """Publishers the graph shows on the topic."""
        return self.bus_node.count_publishers(topic_name)

    def count_subscribers(self, topic_name: str) -> int:
        """Subscriptions the graph shows on the topic."""
        return self.bus_node.count_subscribers(topic_name)

    def get_topic_names_and_types(self, no_demangle: bool = False) -> list[tuple[str, list[str]]]:
        """Every topic with its types."""
        del no_demangle
        return self.bus_node.get_topic_names_and_types()

    def get_node_names(self) -> list[str]:
        """Every node's name."""
        return [name for name, _ns in self.bus_node.get_node_names_and_namespaces()]

    def get_node_names_and_namespaces(self) -> list[tuple[str, str]]:
        """Every node as (name, namespace)."""
        return self.bus_node.get_node_names_and_namespaces()

    # -- parameters ------------------------------------------------------------------------------
    def declare_parameter(self, name: str, value: Any = None, descriptor: Any = None,
                          ignore_override: bool = False) -> Parameter:
        """Declare one parameter; the command line's override wins over ``value``."""
        return self._parameters.declare(name, value, descriptor, ignore_override)

    def declare_parameters(self, namespace: str, parameters: Sequence[tuple[Any, ...]],
                           ignore_override: bool = False) -> list[Parameter]:
        """Declare ``(name[, value[, descriptor]])`` tuples, each under ``namespace.``."""
        out = []
        for entry in parameters:
            name = f"{namespace}.{entry[0]}" if namespace else entry[0]
            value = entry[1] if len(entry) > 1 else None
            descriptor = entry[2] if len(entry) > 2 else None
            out.append(self.declare_parameter(name, value, descriptor, ignore_override))
        return out

    def undeclare_parameter(self, name: str) -> None:
        """Forget a parameter."""
        self._parameters.undeclare(name)

    def has_parameter(self, name: str) -> bool:
        """Whether ``name`` is declared."""
        return self._parameters.has(name)

    def get_parameter(self, name: str) -> Parameter:
        """A declared parameter (ParameterNotDeclaredException otherwise)."""
        return self._parameters.get(name)

    def get_parameter_or(self, name: str, alternative_value: Parameter | None = None) -> Parameter:
        """A declared parameter, or ``alternative_value`` (NOT_SET when None)."""
        if self._parameters.has(name):
            return self._parameters.get(name)
        return alternative_value if alternative_value is not None else Parameter(name, Parameter.Type.NOT_SET)

    def get_parameters(self, names: Sequence[str]) -> list[Parameter]:
        """Declared parameters, in order."""
        return [self.get_parameter(name) for name in names]

    def get_parameters_by_prefix(self, prefix: str) -> dict[str, Parameter]:
        """``{rest: parameter}`` for every parameter named ``prefix.rest``."""
        start = prefix + "." if prefix else ""
        return {n[len(start):]: self._parameters.get(n) for n in self._parameters.names() if n.startswith(start)}

    def set_parameters(self, parameter_list: Sequence[Parameter]) -> list[Any]:
        """Set each; one SetParametersResult per parameter."""
        if not self._parameters.allow_undeclared and \
                any(not self._parameters.has(param.name) for param in parameter_list):
            # rclpy's message names no parameter here (it lists an exhausted generator).
            raise ParameterNotDeclaredException([])
        return self._parameters.set(parameter_list)

    def set_parameters_atomically(self, parameter_list: Sequence[Parameter]) -> Any:
        """Set all or none."""
        return self._parameters.set_atomically(parameter_list)

    def describe_parameter(self, name: str) -> Any:
        """The descriptor of a declared parameter."""
        return self._parameters.descriptor(name)

    def describe_parameters(self, names: Sequence[str]) -> list[Any]:
        """The descriptors of declared parameters."""
        return [self._parameters.descriptor(name) for name in names]

    def set_descriptor(self, name: str, descriptor: Any, alternative_value: Any = None) -> Any:
        """Replace a parameter's descriptor."""
        del alternative_value
        return self._parameters.set_descriptor(name, descriptor)

    def add_on_set_parameters_callback(self, callback: Callable[[list[Parameter]], Any]) -> Any:
        """Ask ``callback(params) -> SetParametersResult`` before every set (it may refuse)."""
        return self._parameters.add_on_set(callback)

    def remove_on_set_parameters_callback(self, callback: Callable[[list[Parameter]], Any]) -> None:
        """Stop asking ``callback``."""
        self._parameters.remove_on_set(callback)

    def add_pre_set_parameters_callback(self, callback: Callable[[list[Parameter]], list[Parameter]]) -> Any:
        """Let ``callback(params) -> params`` change what is set."""
        return self._parameters.add_pre_set(callback)

    def add_post_set_parameters_callback(self, callback: Callable[[list[Parameter]], None]) -> Any:
        """Tell ``callback(params)`` what was set."""
        return self._parameters.add_post_set(callback)

    def _follow_sim_time(self, params: list[Parameter]) -> None:
        for param in params:
            if param.name == "use_sim_time":
                self._use_sim_time(bool(param.value))

    def _use_sim_time(self, enabled: bool) -> None:
        from robotmodel.msgs.rosgraph_msgs import Clock as ClockMsg

        if enabled and self._clock_sub is None:
            # /clock moves the clock on the bus's thread: timers and sleeps must not wait for a spin.
            def tick(msg: Any) -> None:
                self._clock.set_ros_time_override(msg.clock.sec * 1_000_000_000 + msg.clock.nanosec)
                self._notify()

            self._clock_sub = self.bus_node.create_subscription(ClockMsg, "/clock", tick, to_bus_qos(
                QoSProfile(depth=1, reliability=2)))
        elif not enabled and self._clock_sub is not None:
            self._clock_sub.close()
            self._clock_sub = None
        self._clock._set_ros_time_is_active(enabled)
        self._notify()

    # -- life ------------------------------------------------------------------------------------
    def destroy_node(self) -> None:
        """Withdraw everything the node made, then the node."""
        for executor in list(self._executors):
            executor.remove_node(self)
        with self._lock:
            self._entities.clear()
        self.bus_node.close()

    def __enter__(self) -> Node:
        return self

    def __exit__(self, *exc: object) -> None:
        self.destroy_node()


class _Job:
    """A one-off job waiting for the executor (a parameter request), in the node's default group."""

    def __init__(self, node: Node, job: Callable[[], None]) -> None:
        self._node = node
        self._job: Callable[[], None] | None = job
        self.callback_group = node.default_callback_group

    def ready(self) -> bool:
        return self._job is not None

    def take(self) -> Callable[[], None] | None:
        job, self._job = self._job, None
        self._node._forget(self)
        return job

    def due_in(self) -> float | None:
        return None

