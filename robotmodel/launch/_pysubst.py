"""launch's substitutions, as description files use them (``launch.substitutions``).

Each has launch's ``perform(context)`` and ``describe()`` (what ``--show-args`` prints for a
default). ``Command`` runs only xacro, expanded in-process once per distinct command line,
as the XML launcher's ``$(command)`` does; the run remembers which text came from which
xacro command, so a node handed that text gets the xacro file instead (it expands it itself).
"""

from __future__ import annotations

import os
import shutil
from collections.abc import Iterable
from typing import Any

from robotmodel.launch._pyctx import LaunchContext

__all__ = [
    "Command",
    "EnvironmentVariable",
    "FindExecutable",
    "LaunchConfiguration",
    "PathJoinSubstitution",
    "PythonExpression",
    "SomeSubstitutionsType",
    "Substitution",
    "SubstitutionFailure",
    "TextSubstitution",
    "ThisLaunchFile",
    "ThisLaunchFileDir",
    "normalize",
    "normalize_to_list_of_substitutions",
    "perform_all",
    "perform_substitutions",
]


class SubstitutionFailure(RuntimeError):
    """launch's error for a substitution that cannot be performed."""


class Substitution:
    """A value known only when the launch runs."""

    def perform(self, context: LaunchContext) -> str:
        """The value in ``context``."""
        raise NotImplementedError

    def describe(self) -> str:
        """What ``--show-args`` prints for it."""
        return type(self).__name__ + "()"

    def __str__(self) -> str:
        return self.describe()

    def __truediv__(self, other: Any) -> PathJoinSubstitution:
        return PathJoinSubstitution([self, other])


#: launch's type of what a substitution argument accepts (text, a substitution, or a list of them).
SomeSubstitutionsType = Any


def normalize(value: Any) -> list[Substitution]:
    """Launch's ``normalize_to_list_of_substitutions``: text, a substitution, or an iterable of them."""
    if isinstance(value, Substitution):
        return [value]
    if isinstance(value, str | os.PathLike):
        return [TextSubstitution(text=os.fspath(value))]
    if isinstance(value, Iterable):
        out: list[Substitution] = []
        for item in value:
            if isinstance(item, Substitution):
                out.append(item)
            elif isinstance(item, str | os.PathLike):
                out.append(TextSubstitution(text=os.fspath(item)))
            else:
                raise TypeError(f"Failed to normalize given item of type '{type(item).__name__}', when only "
                                "'str' or 'launch.Substitution' were expected.")
        return out
    raise TypeError(f"Failed to normalize given item of type '{type(value).__name__}', when only "
                    "'str' or 'launch.Substitution' were expected.")


def perform_all(context: LaunchContext, substitutions: Iterable[Substitution]) -> str:
    """Launch's ``perform_substitutions``: each performed, joined."""
    return "".join(s.perform(context) for s in substitutions)


def _describe(subs: Iterable[Substitution]) -> str:
    return " + ".join(s.describe() for s in subs)


class TextSubstitution(Substitution):
    """Literal text."""

    def __init__(self, *, text: str) -> None:
        self.text = text

    def perform(self, context: LaunchContext) -> str:
        """The text."""
        return self.text

    def describe(self) -> str:
        """``'text'``."""
        return f"'{self.text}'"


class LaunchConfiguration(Substitution):
    """The value of a launch configuration (``default`` when unset; else an error)."""

    def __init__(self, variable_name: Any, *, default: Any = None) -> None:
        self.variable_name = normalize(variable_name)
        self.default = None if default is None else normalize(default)

    def perform(self, context: LaunchContext) -> str:
        """The configuration's value."""
        name = perform_all(context, self.variable_name)
        if name in context.launch_configurations:
            return context.launch_configurations[name]
        if self.default is not None:
            return perform_all(context, self.default)
        raise SubstitutionFailure(f"launch configuration '{name}' does not exist")

    def describe(self) -> str:
        """``LaunchConfig('name')``."""
        return f"LaunchConfig({_describe(self.variable_name)})"


class EnvironmentVariable(Substitution):
    """An environment variable (``default_value`` when unset; None: an error)."""

    def __init__(self, name: Any, *, default_value: Any = "") -> None:
        self.name = normalize(name)
        self.default_value = None if default_value is None else normalize(default_value)

    def perform(self, context: LaunchContext) -> str:
        """The variable's value."""
        name = perform_all(context, self.name)
        value = context.environment[name] if name in context.environment else os.environ.get(name)
        if value is not None:
            return value
        if self.default_value is None:
            raise SubstitutionFailure(f"environment variable '{name}' does not exist")
        return perform_all(context, self.default_value)

    def describe(self) -> str:
        """``EnvVar('name')``."""
        return f"EnvVar({_describe(self.name)})"


class FindExecutable(Substitution):
    """The path of program ``name`` on the PATH (xacro runs in-process, so its name is enough)."""

    def __init__(self, *, name: Any) -> None:
        self.name = normalize(name)

    def perform(self, context: LaunchContext) -> str:
        """The program's path."""
        name = perform_all(context, self.name)
        found = shutil.which(name)
        if found is not None:
            return found
        if name in ("xacro", "xacro.py"):
            return name
        raise SubstitutionFailure(f"executable '{name}' not found on the PATH")

    def describe(self) -> str:
        """``FindExec('name')``."""
        return f"FindExec({_describe(self.name)})"


class Command(Substitution):
    """The output of a command: here only xacro's, expanded in-process (launch's error text on failure)."""

    def __init__(self, command: Any, *, on_stderr: Any = "fail") -> None:
        self.command = normalize(command)
        self.on_stderr = on_stderr

    def perform(self, context: LaunchContext) -> str:
        """Xacro's output."""
        from robotmodel.launch._subst import expand_xacro, parse_xacro_command

        text = perform_all(context, self.command)
        ctx = context.subst()
        source = parse_xacro_command(text, ctx)
        for output, known in context.xacro_outputs.items():
            if known == source:
                return output
        output = expand_xacro(text, source, ctx)
        context.xacro_outputs[output] = source
        return output

    def describe(self) -> str:
        """``Command(...)``."""
        return f"Command({_describe(self.command)})"


class PathJoinSubstitution(Substitution):
    """Path components joined with ``os.path.join``."""

    def __init__(self, substitutions: Any) -> None:
        self.substitutions = normalize(substitutions)

    def perform(self, context: LaunchContext) -> str:
        """The joined path."""
        return os.path.join(*(s.perform(context) for s in self.substitutions))  # noqa: PTH118

    def describe(self) -> str:
        """``PathJoin('...')``."""
        return f"PathJoin('{_describe(self.substitutions)}')"


class PythonExpression(Substitution):
    """A Python expression evaluated after substitution (``math``'s names in scope, as launch has them)."""

    def __init__(self, expression: Any, python_modules: Any = ("math",)) -> None:
        self.expression = normalize(expression)
        self.python_modules = normalize(list(python_modules) if isinstance(python_modules, tuple) else python_modules)

    def perform(self, context: LaunchContext) -> str:
        """``str(eval(expression))``; the launch file's own code, evaluated as ``ros2 launch`` does."""
        import importlib

        scope: dict[str, Any] = {}
        for sub in self.python_modules:
            module = importlib.import_module(sub.perform(context))
            if module.__name__ == "math":
                scope.update(vars(module))
            scope[module.__name__] = module
        text = perform_all(context, self.expression)
        return str(eval(text, {}, scope))

    def describe(self) -> str:
        """``PythonExpr(...)``."""
        return f"PythonExpr({_describe(self.expression)}, [{', '.join(s.describe() for s in self.python_modules)}])"


class ThisLaunchFileDir(Substitution):
    """The folder of the launch file being read."""

    def perform(self, context: LaunchContext) -> str:
        """The folder."""
        return str(context.file.parent)


class ThisLaunchFile(Substitution):
    """The path of the launch file being read."""

    def perform(self, context: LaunchContext) -> str:
        """The path."""
        return str(context.file)


def _text(value: Any) -> Any:
    if isinstance(value, bool):
        return str(value).lower()
    if isinstance(value, int | float):
        return str(value)
    return value


def normalize_to_list_of_substitutions(subs: Any) -> list[Substitution]:
    """launch.utilities' name for :func:`normalize`."""
    return normalize(subs)


def perform_substitutions(context: LaunchContext, subs: Any) -> str:
    """launch.utilities' name for :func:`perform_all`."""
    return perform_all(context, subs)
