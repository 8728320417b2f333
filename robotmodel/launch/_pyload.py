"""Running a ROS 2 Python launch file (``*.launch.py``) into the nodes it declares.

The file is the user's own code and runs as ``ros2 launch`` runs it: the top file is
included with the command line's ``name:=value`` arguments as its launch arguments (so a
missing required argument gets launch's text), each action visited in order. It imports
``launch``, ``launch_ros``, ``launch_xml``, ``launch_yaml`` and ``ament_index_python``
under their own names, which resolve to robotmodel's stand-ins during the run only
(:mod:`robotmodel.launch._pyimport`). The result is a :class:`LaunchFile`, as the XML
launcher reads one, so the same mapping decides what starts and what is skipped.

An exception the file's code raises ends the run with one line naming the launch file's
line it came through, in ``ros2 launch``'s words.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from pathlib import Path

from robotmodel.errors import LaunchError
from robotmodel.launch._loader import LaunchFile
from robotmodel.launch._pysources import error_site, error_text

__all__ = ["load_python_launch", "show_arguments"]


def load_python_launch(path: Path, args: Mapping[str, str], package_paths: Sequence[Path] = ()) -> LaunchFile:
    """Run Python launch file ``path`` with command-line ``args``; the nodes it declares, skips and notes."""
    from robotmodel.launch._pyctx import LaunchContext
    from robotmodel.launch._pysources import run_python

    path = path.resolve()
    context = LaunchContext(path, package_paths)
    run_python(context, path, args)
    return LaunchFile(context.nodes, {}, context.skipped, context.notes, tuple(context.found))


def show_arguments(path: Path, package_paths: Sequence[Path] = ()) -> str:
    """``ros2 launch --show-args``'s text for Python launch file ``path`` (its code runs, nothing starts)."""
    from robotmodel.launch._pyctx import LaunchContext, using
    from robotmodel.launch._pyimport import standins
    from robotmodel.launch._pysources import load_python_file

    path = path.resolve()
    context = LaunchContext(path, package_paths)
    with standins(), using(context):
        try:
            arguments = load_python_file(path).get_launch_arguments()
        except LaunchError:
            raise
        except (Exception, SystemExit) as exc:
            raise LaunchError(f"{error_site(exc, path)}: Caught exception when trying to load file of format [py]: "
                              f"{error_text(exc)}") from None
    lines = ["Arguments (pass arguments as '<name>:=<value>'):"]
    conditional = False
    for argument in arguments:
        mark = "*" if argument.conditionally_included else ""
        conditional = conditional or argument.conditionally_included
        lines.append(f"\n    '{argument.name}':{mark}\n        {argument.description}")
        if argument.default_value is not None:
            lines[-1] += f"\n        (default: {' + '.join(s.describe() for s in argument.default_value)})"
    if not arguments:
        lines.append("\n  No arguments.")
    elif conditional:
        lines.append("\n* argument(s) which are only used if specific conditions occur")
    return "\n".join(lines) + "\n"
