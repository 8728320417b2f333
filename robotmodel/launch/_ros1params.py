"""roslaunch's parameters on the ROS 1 parameter server: what a launch file sets, set before its nodes start.

On the ROS 1 wire (:func:`robotmodel.rcl.ros1_wire`) ``robotmodel launch`` does what roslaunch
does: every ``<param>`` (global, and each node's own as ``/NODE/name``) goes to the master's
parameter server before any node starts, a xacro command's output and a ``textfile`` as their
text, typed values as roslaunch types them (``type=`` or its guess); the nodes then read
robot_description there themselves (searched up their namespace).
"""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from pathlib import Path
from typing import Any

from robotmodel.launch._loader import LaunchFile, join_ns
from robotmodel.launch._model import Param

__all__ = ["server_params", "set_on_server"]


def _value(param: Param, package_paths: Sequence[Path]) -> Any:
    import yaml

    if param.xacro is not None:
        from robotmodel.model import load, to_urdf

        desc = load(param.xacro.file, dict(param.xacro.mappings), package_paths=package_paths)
        return desc.source_text or to_urdf(desc)
    if param.textfile is not None:
        return param.textfile.read_text(encoding="utf-8")
    if param.typed is not None:
        return yaml.safe_load(param.typed)
    return param.value or ""


def server_params(launch: LaunchFile, package_paths: Sequence[Path] = ()) -> Iterator[tuple[str, Any]]:
    """(full name, value) of each parameter the launch file sets, in roslaunch's order: globals, then nodes'."""
    for name, param in launch.params.items():
        yield name, _value(param, package_paths)
    for node in launch.nodes:
        for name, param in node.params.items():
            yield join_ns(node.full_name, name.replace(".", "/")), _value(param, package_paths)


def set_on_server(launch: LaunchFile, package_paths: Sequence[Path] = (), master_uri: str | None = None) -> int:
    """Set every parameter of ``launch`` on the master (``ROS_MASTER_URI``'s by default); returns how many."""
    from robotmodel.ros1 import ParamClient, master_uri_from_env

    client = ParamClient(master_uri or master_uri_from_env(), "/roslaunch")
    count = 0
    for name, value in server_params(launch, package_paths):
        client.set_param(name, value)
        count += 1
    return count
