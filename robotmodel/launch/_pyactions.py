"""launch's description and actions (``launch``, ``launch.actions``, ``launch.event_handlers``).

They are visited in order, depth first, as launch's service visits what each action returns;
what launch would run later (timers, event handlers) is in :mod:`robotmodel.launch._pyevents`.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Iterable
from pathlib import Path
from typing import Any

from robotmodel.errors import LaunchError
from robotmodel.launch._pyconditions import Condition
from robotmodel.launch._pyctx import LaunchContext, user_site
from robotmodel.launch._pysubst import SubstitutionFailure, normalize, perform_all

__all__ = [
    "Action",
    "AppendEnvironmentVariable",
    "DeclareLaunchArgument",
    "ExecuteProcess",
    "GroupAction",
    "LaunchDescription",
    "LogInfo",
    "OpaqueFunction",
    "PopLaunchConfigurations",
    "PushLaunchConfigurations",
    "SetEnvironmentVariable",
    "SetLaunchConfiguration",
    "UnsetEnvironmentVariable",
    "UnsetLaunchConfiguration",
    "visit",
]


class Action:
    """Something a launch description does; ``condition`` decides whether it runs."""

    def __init__(self, *, condition: Condition | None = None, **kwargs: Any) -> None:
        del kwargs  # launch's other options (output, respawn, ...) change nothing here
        self.condition = condition
        self.site = user_site()

    def execute(self, context: LaunchContext) -> list[Any] | None:
        """Do it; returns entities to visit next."""
        del context
        return None

    def get_sub_entities(self) -> list[Any]:
        """The entities it would return, as far as known without running (for ``--show-args``)."""
        return []

    def where(self) -> str:
        """``FILE:LINE`` where the user's code made it."""
        path, line = self.site
        return f"{path}:{line}" if path is not None else "<launch>"


class LaunchDescription:
    """The entities a launch file returns, in order."""

    def __init__(self, initial_entities: Iterable[Any] | None = None, *, deprecated_reason: str | None = None) -> None:
        del deprecated_reason
        self.entities: list[Any] = list(initial_entities or [])

    def add_action(self, action: Any) -> None:
        """Append an action."""
        self.entities.append(action)

    def add_entity(self, entity: Any) -> None:
        """Append an entity."""
        self.entities.append(entity)

    def describe_sub_entities(self) -> list[Any]:
        """Its entities."""
        return self.entities

    def get_launch_arguments(self, conditional_inclusion: bool = False) -> list[DeclareLaunchArgument]:
        """The arguments it declares, includes known without running too; the first of each name (launch's rule)."""
        return [arg for arg, _ in self.get_launch_arguments_with_include_launch_description_actions(
            conditional_inclusion)]

    def get_launch_arguments_with_include_launch_description_actions(
            self, conditional_inclusion: bool = False) -> list[tuple[DeclareLaunchArgument, list[Any] | None]]:
        """Each declared argument with the includes it sits under (None: declared here), as launch finds them.

        The walk stops at a group that resets the configurations (``forwarding=False``): the
        arguments after it cannot be set from outside.
        """
        found: list[tuple[DeclareLaunchArgument, list[Any] | None]] = []

        def walk(entities: Iterable[Any], conditional: bool, includes: list[Any] | None, depth: int) -> bool:
            if depth > 32:
                return False
            for entity in entities:
                if isinstance(entity, DeclareLaunchArgument) and entity.name not in (e.name for e, _ in found):
                    entity.conditionally_included = conditional or entity.condition is not None
                    found.append((entity, includes))
                if isinstance(entity, _ResetLaunchConfigurations):
                    return True
                nested = includes
                if hasattr(entity, "launch_arguments") and isinstance(entity, Action):  # an include
                    nested = [*(includes or []), entity]
                if isinstance(entity, LaunchDescription):
                    stop = walk(entity.entities, conditional, nested, depth + 1)
                elif isinstance(entity, Action):
                    stop = walk(entity.get_sub_entities(), conditional or entity.condition is not None, nested,
                                depth + 1)
                else:
                    stop = False
                if stop:
                    return True
            return False

        walk(self.entities, conditional_inclusion, None, 0)
        return found


class DeclareLaunchArgument(Action):
    """An argument of the launch file: the configuration of that name, its default, description and choices."""

    def __init__(self, name: str, *, default_value: Any = None, description: str | None = None,
                 choices: list[str] | None = None, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.name = name
        self.default_value = None if default_value is None else normalize(default_value)
        if choices is not None and not choices:
            raise RuntimeError("Provided choices arg is empty. Use None to ignore the choice list.")
        if choices is not None and isinstance(default_value, str) and default_value not in choices:
            raise RuntimeError(f'Provided default_value "{default_value}" is not in provided choices "{choices}".')
        if description is None:
            self.description = "no description given" if choices is None else f"One of: {choices}"
        else:
            self.description = description
            if choices is not None:
                self.description += ("" if description.endswith(".") else ".") + f" Valid choices are: {choices}"
        self.choices = choices
        self.conditionally_included = False

    def execute(self, context: LaunchContext) -> None:
        """Set the default unless given; check the choices."""
        configs = context.launch_configurations
        if self.name not in configs:
            if self.default_value is None:
                raise LaunchError(f"{self.where()}: Required launch argument \"{self.name}\" "
                                  f"(description: \"{self.description}\") was not provided")
            configs[self.name] = perform_all(context, self.default_value)
        if self.choices is not None and configs[self.name] not in self.choices:
            raise LaunchError(f"{self.where()}: Argument \"{self.name}\" provided value \"{configs[self.name]}\" is "
                              f"not valid. Valid options are: {self.choices}")


class SetLaunchConfiguration(Action):
    """Set a launch configuration."""

    def __init__(self, name: Any, value: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.name, self.value = normalize(name), normalize(value)

    def execute(self, context: LaunchContext) -> None:
        """Set it."""
        context.launch_configurations[perform_all(context, self.name)] = perform_all(context, self.value)


class UnsetLaunchConfiguration(Action):
    """Remove a launch configuration."""

    def __init__(self, name: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.name = normalize(name)

    def execute(self, context: LaunchContext) -> None:
        """Remove it."""
        context.launch_configurations.pop(perform_all(context, self.name), None)


class PushLaunchConfigurations(Action):
    """Save the configurations (and the ROS scope) for a later pop."""

    def execute(self, context: LaunchContext) -> None:
        """Save them."""
        context.push()


class PopLaunchConfigurations(Action):
    """Restore the configurations saved by the matching push."""

    def execute(self, context: LaunchContext) -> None:
        """Restore them."""
        context.pop()


class _ResetLaunchConfigurations(Action):
    def __init__(self, keep: dict[Any, Any]) -> None:
        super().__init__()
        self.keep = keep

    def execute(self, context: LaunchContext) -> None:
        values = {perform_all(context, normalize(k)): perform_all(context, normalize(v)) for k, v in self.keep.items()}
        context.launch_configurations.clear()
        context.launch_configurations.update(values)


class GroupAction(Action):
    """Actions in a scope of their own (``scoped``); ``launch_configurations`` set first."""

    def __init__(self, actions: Iterable[Any], *, scoped: bool = True, forwarding: bool = True,
                 launch_configurations: dict[Any, Any] | None = None, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.actions = list(actions)
        self.scoped, self.forwarding = scoped, forwarding
        self.launch_configurations = dict(launch_configurations or {})

    def get_sub_entities(self) -> list[Any]:
        """Push, the configurations, the actions, pop (launch's order)."""
        sets = [SetLaunchConfiguration(k, v) for k, v in self.launch_configurations.items()]
        if not self.scoped:
            return [*sets, *self.actions]
        if self.forwarding:
            return [PushLaunchConfigurations(), *sets, *self.actions, PopLaunchConfigurations()]
        return [PushLaunchConfigurations(), _ResetLaunchConfigurations(self.launch_configurations), *self.actions,
                PopLaunchConfigurations()]

    def execute(self, context: LaunchContext) -> list[Any]:
        """Its sub-entities."""
        return self.get_sub_entities()


class OpaqueFunction(Action):
    """A function of the context returning more entities (the launch file's own code)."""

    def __init__(self, *, function: Callable[..., Any], args: Iterable[Any] | None = None,
                 kwargs: dict[str, Any] | None = None, **rest: Any) -> None:
        super().__init__(**rest)
        self.function, self.args, self.kwargs = function, list(args or []), dict(kwargs or {})

    def execute(self, context: LaunchContext) -> list[Any] | None:
        """Call it."""
        result = self.function(context, *self.args, **self.kwargs)
        return list(result) if result is not None else None


class LogInfo(Action):
    """A message for the console (as a note line)."""

    def __init__(self, *, msg: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.msg = normalize(msg)

    def execute(self, context: LaunchContext) -> None:
        """Note it."""
        context.notes.append(f"[launch.user] {perform_all(context, self.msg)}")


class SetEnvironmentVariable(Action):
    """Set a variable for ``EnvironmentVariable`` (the started commands keep the launcher's environment)."""

    def __init__(self, name: Any, value: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.name, self.value = normalize(name), normalize(value)

    def execute(self, context: LaunchContext) -> None:
        """Set it."""
        context.environment[perform_all(context, self.name)] = perform_all(context, self.value)


class AppendEnvironmentVariable(Action):
    """Append (or ``prepend``) to a variable for ``EnvironmentVariable``, joined by ``separator``."""

    def __init__(self, name: Any, value: Any, *, prepend: bool = False, separator: str = os.pathsep,
                 **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.name, self.value, self.prepend, self.separator = normalize(name), normalize(value), prepend, separator

    def execute(self, context: LaunchContext) -> None:
        """Extend it."""
        name, value = perform_all(context, self.name), perform_all(context, self.value)
        old = context.environment[name] if name in context.environment else os.environ.get(name)
        parts = [value, old] if self.prepend else [old, value]
        context.environment[name] = self.separator.join(p for p in parts if p)


class UnsetEnvironmentVariable(Action):
    """Unset a variable for ``EnvironmentVariable``."""

    def __init__(self, name: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.name = normalize(name)

    def execute(self, context: LaunchContext) -> None:
        """Unset it."""
        context.environment[perform_all(context, self.name)] = None


class ExecuteProcess(Action):
    """A process other than a node: listed as skipped."""

    def __init__(self, *, cmd: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.cmd = cmd

    def execute(self, context: LaunchContext) -> None:
        """List it."""
        words = self.cmd if isinstance(self.cmd, list | tuple) else [self.cmd]
        try:
            shown = " ".join(perform_all(context, normalize(w)) for w in words)
        except (SubstitutionFailure, LaunchError, TypeError):
            shown = " ".join(str(w) for w in words)
        context.skipped.append(f"ExecuteProcess {shown} ({self.where()}): not run")


def visit(entity: Any, context: LaunchContext) -> None:
    """Run ``entity`` and what it returns, depth first."""
    if isinstance(entity, LaunchDescription):
        for child in entity.entities:
            visit(child, context)
        return
    if not isinstance(entity, Action):
        context.notes.append(f"{context.file}: {type(entity).__name__} is not a launch action; ignored")
        return
    if entity.condition is not None and not entity.condition.evaluate(context):
        return
    for child in entity.execute(context) or []:
        visit(child, context)


def file_of(site: tuple[Path | None, int]) -> Path | None:
    """The file part of an action's site."""
    return site[0]
