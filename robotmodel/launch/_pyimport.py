"""The names a Python launch file imports (``launch``, ``launch_ros``, ``ament_index_python``, ...), during a run only.

:func:`standins` puts a finder first on ``sys.meta_path`` for the ``with`` block: the launch
file's ``from launch.actions import Node`` gets robotmodel's stand-ins under the real module
paths, while nothing named ``launch`` is installed into site-packages, and a real ROS install
on the path is shadowed for the run only. Afterwards the finder goes and every module it made
is dropped from ``sys.modules`` (what was there before is put back).
"""

from __future__ import annotations

import sys
from collections.abc import Iterator
from contextlib import contextmanager
from importlib.abc import Loader, MetaPathFinder
from importlib.machinery import ModuleSpec
from types import ModuleType
from typing import Any

__all__ = ["MODULES", "standins"]

_A = "robotmodel.launch._pyactions"
_E = "robotmodel.launch._pyevents"
_S = "robotmodel.launch._pysubst"
_R = "robotmodel.launch._pyros"
_D = "robotmodel.launch._pysources"
_C = "robotmodel.launch._pyctx"
_K = "robotmodel.launch._pyconditions"
_B = "robotmodel.launch._pybool"
_F = "robotmodel.launch._pyfind"
_M = "robotmodel.launch._ament"

# module name -> ((implementing module, names), ...): each name exported under the real path
# ("Name=attr": the implementation's ``attr`` under the name ``Name``).
MODULES: dict[str, tuple[tuple[str, tuple[str, ...]], ...]] = {
    "launch": ((_A, ("Action", "LaunchDescription")), (_K, ("Condition",)), (_C, ("LaunchContext",)),
               (_S, ("SomeSubstitutionsType", "Substitution")), (_D, ("LaunchDescriptionSource",))),
    "launch.action": ((_A, ("Action",)),),
    "launch.condition": ((_K, ("Condition",)),),
    "launch.substitution": ((_S, ("Substitution",)),),
    "launch.launch_context": ((_C, ("LaunchContext",)),),
    "launch.launch_description": ((_A, ("LaunchDescription",)),),
    "launch.launch_description_source": ((_D, ("LaunchDescriptionSource",)),),
    "launch.actions": ((_A, ("AppendEnvironmentVariable", "DeclareLaunchArgument", "ExecuteProcess",
                             "GroupAction", "LogInfo", "OpaqueFunction", "PopLaunchConfigurations",
                             "PushLaunchConfigurations", "SetEnvironmentVariable", "SetLaunchConfiguration",
                             "UnsetEnvironmentVariable", "UnsetLaunchConfiguration")),
                       (_E, ("EmitEvent", "RegisterEventHandler", "Shutdown", "TimerAction")),
                       (_D, ("IncludeLaunchDescription",))),
    "launch.substitutions": ((_S, ("Command", "EnvironmentVariable", "FindExecutable", "LaunchConfiguration",
                                   "PathJoinSubstitution", "PythonExpression", "SubstitutionFailure",
                                   "TextSubstitution", "ThisLaunchFile", "ThisLaunchFileDir")),
                             (_B, ("AndSubstitution", "EqualsSubstitution", "IfElseSubstitution",
                                   "NotEqualsSubstitution", "NotSubstitution", "OrSubstitution"))),
    "launch.conditions": ((_K, ("IfCondition", "InvalidConditionExpressionError", "LaunchConfigurationEquals",
                                "LaunchConfigurationNotEquals", "UnlessCondition",
                                "evaluate_condition_expression")),),
    "launch.launch_description_sources": ((_D, ("AnyLaunchDescriptionSource", "FrontendLaunchDescriptionSource",
                                                "PythonLaunchDescriptionSource")),),
    "launch.event_handlers": ((_E, ("OnExecutionComplete", "OnProcessExit", "OnProcessIO", "OnProcessStart",
                                    "OnShutdown")),),
    "launch.events": ((_E, ("Shutdown=ShutdownEvent",)),),
    "launch.some_substitutions_type": ((_S, ("SomeSubstitutionsType",)),),
    "launch.utilities": ((_S, ("normalize_to_list_of_substitutions", "perform_substitutions")),),
    "launch_ros": (),
    "launch_ros.actions": ((_R, ("ComposableNodeContainer", "LifecycleNode", "LoadComposableNodes", "Node",
                                 "PushROSNamespace", "PushRosNamespace", "SetParameter", "SetRemap",
                                 "SetUseSimTime")),),
    "launch_ros.substitutions": ((_F, ("FindPackage", "FindPackagePrefix", "FindPackageShare")),),
    "launch_ros.parameter_descriptions": ((_R, ("ParameterFile", "ParameterValue")),),
    "launch_ros.descriptions": ((_R, ("ComposableNode", "ParameterFile", "ParameterValue")),),
    "launch_xml": (),
    "launch_xml.launch_description_sources": ((_D, ("XMLLaunchDescriptionSource",)),),
    "launch_yaml": (),
    "launch_yaml.launch_description_sources": ((_D, ("YAMLLaunchDescriptionSource",)),),
    "ament_index_python": ((_M, ("PackageNotFoundError", "get_package_prefix", "get_package_share_directory",
                                 "get_package_share_path")),),
    "ament_index_python.packages": ((_M, ("PackageNotFoundError", "get_package_prefix",
                                          "get_package_share_directory", "get_package_share_path")),),
}
_ROOTS = frozenset(name.split(".", 1)[0] for name in MODULES)


class _Finder(MetaPathFinder, Loader):
    def find_spec(self, fullname: str, path: Any = None, target: Any = None) -> ModuleSpec | None:
        if fullname not in MODULES:
            return None
        return ModuleSpec(fullname, self, is_package=True)

    def create_module(self, spec: ModuleSpec) -> ModuleType | None:
        return None

    def exec_module(self, module: ModuleType) -> None:
        import importlib

        module.__path__ = []
        module.__doc__ = f"robotmodel's stand-in of {module.__name__} (robotmodel launch)"
        for source, names in MODULES[module.__name__]:
            implementation = importlib.import_module(source)
            for entry in names:
                name, _, attribute = entry.partition("=")
                setattr(module, name, getattr(implementation, attribute or name))
        # The real packages import their submodules, so `import launch` then `launch.actions.X` works.
        prefix = module.__name__ + "."
        for child in MODULES:
            if child.startswith(prefix) and "." not in child[len(prefix):]:
                setattr(module, child[len(prefix):], importlib.import_module(child))


def _ours(name: str) -> bool:
    return name.split(".", 1)[0] in _ROOTS


@contextmanager
def standins() -> Iterator[None]:
    """The stand-in modules importable under their real names for the ``with`` block."""
    saved = {name: sys.modules.pop(name) for name in list(sys.modules) if _ours(name)}
    finder = _Finder()
    sys.meta_path.insert(0, finder)
    try:
        yield
    finally:
        sys.meta_path.remove(finder)
        for name in [n for n in sys.modules if _ours(n)]:
            del sys.modules[name]
        sys.modules.update(saved)
