"""ROS launch files without ROS: the description-package subset of ROS 1 and ROS 2 launch XML, and ROS 2 Python.

A ROS 2 Python launch file (``*.launch.py``) runs as ``ros2 launch`` runs it, against
stand-ins of ``launch``, ``launch_ros`` and ``ament_index_python`` importable under those
names during the run only (:mod:`robotmodel.launch._pyload`); it yields the same
:class:`LaunchFile` as an XML file, so the same plan follows. :func:`run_launch` picks the
reader by the file's suffix (``show_args``: ``ros2 launch --show-args``).

- :func:`load_launch_file`: read a file (either dialect, told from its content: a ROS 1
  include named ``*.launch.xml`` is ROS 1) with ``name:=value`` arguments into its nodes and
  parameters (:class:`LaunchFile`); ``$(arg)``, ``$(var)``, ``$(find)``,
  ``$(find-pkg-share)``, ``$(eval)`` (a safe subset; ROS 1 args typed as roslaunch types
  them), ``$(env)``/``$(optenv)``, ``$(dirname)`` and xacro's ``$(command)`` are resolved,
  includes and groups followed. Each xacro description is expanded once while reading, as
  roslaunch and ros2 launch do, so a failing one is an error before anything starts.
- :func:`build_plan`: the ``robotmodel`` commands standing in for those nodes
  (:class:`LaunchPlan` of :class:`ProcessSpec`), other nodes listed as skipped; each with
  the node's name, namespace, parameters and remap rules as a ``--ros-args`` block.
- :func:`run_processes`: start them under one :class:`robotmodel.process.Supervisor`, stop
  them together on SIGINT/SIGTERM, reap them all.
- :func:`find_launch_file`: ``PKG FILE`` to a path, as ``roslaunch``/``ros2 launch`` do.
- :func:`run_launch`: all of it, as ``robotmodel launch`` runs it (``--dry-run`` too).
- :func:`standin_command`: the robotmodel command standing in for a ``ros2 run``/``rosrun``
  ``PACKAGE EXECUTABLE`` pair (:data:`STANDINS`, the table the launcher's node kinds use too).

Bad input raises :class:`robotmodel.errors.LaunchError` starting with ``FILE:LINE:``.
"""

from __future__ import annotations

from robotmodel.launch._executables import STANDINS, standin_command
from robotmodel.launch._files import load_launch_file
from robotmodel.launch._find import find_launch_file
from robotmodel.launch._kinds import build_plan
from robotmodel.launch._loader import LaunchFile
from robotmodel.launch._model import Dialect, LaunchPlan, NodeDecl, Param, ProcessSpec, XacroSource
from robotmodel.launch._run import run_launch, run_processes

__all__ = [
    "STANDINS",
    "Dialect",
    "LaunchFile",
    "LaunchPlan",
    "NodeDecl",
    "Param",
    "ProcessSpec",
    "XacroSource",
    "build_plan",
    "find_launch_file",
    "load_launch_file",
    "run_launch",
    "run_processes",
    "standin_command",
]
