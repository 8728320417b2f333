"""launch's timers, event handlers and events (``launch.event_handlers``, ``launch.events``).

What launch would run later (``TimerAction``, the ``OnProcessStart``/``OnProcessExit`` handlers
of ``RegisterEventHandler``) runs after everything else, in launch's order (process starts,
then timers by period, then process exits): its processes start then, not at that moment,
and a note says so.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

from robotmodel.errors import LaunchError
from robotmodel.launch._pyactions import Action, visit
from robotmodel.launch._pyctx import Deferred, LaunchContext
from robotmodel.launch._pysubst import Substitution, normalize, perform_all

__all__ = [
    "EmitEvent",
    "OnExecutionComplete",
    "OnProcessExit",
    "OnProcessIO",
    "OnProcessStart",
    "OnShutdown",
    "RegisterEventHandler",
    "Shutdown",
    "ShutdownEvent",
    "TimerAction",
    "run_deferred",
]


class TimerAction(Action):
    """Actions launch runs ``period`` seconds later: here after the rest (ordering only)."""

    def __init__(self, *, period: Any, actions: Iterable[Any], **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.period, self.actions = period, list(actions)

    def execute(self, context: LaunchContext) -> None:
        """Defer them."""
        try:
            period = float(self.period) if not isinstance(self.period, Substitution | list) else float(
                perform_all(context, normalize(self.period)))
        except ValueError:
            raise LaunchError(f"{self.where()}: TimerAction period '{self.period}' is not a number") from None
        _defer(context, (1, period), self.actions, f"{self.where()}: TimerAction(period={period:g}): its actions "
               "run after the others (ordering only; no delay)")


class OnProcessStart:
    """Run ``on_start`` once ``target_action`` started: here after the rest (ordering only)."""

    def __init__(self, *, target_action: Any = None, on_start: Any = None, **kwargs: Any) -> None:
        del kwargs
        self.target_action, self.entities = target_action, on_start
        self.rank, self.what = 0, "OnProcessStart"


class OnProcessExit:
    """Run ``on_exit`` once ``target_action`` exited: here after the rest (ordering only)."""

    def __init__(self, *, target_action: Any = None, on_exit: Any = None, **kwargs: Any) -> None:
        del kwargs
        self.target_action, self.entities = target_action, on_exit
        self.rank, self.what = 2, "OnProcessExit"


class RegisterEventHandler(Action):
    """Register an event handler: its actions run after the rest, in launch's order (ordering only)."""

    def __init__(self, event_handler: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.event_handler = event_handler

    def execute(self, context: LaunchContext) -> None:
        """Defer its actions."""
        handler = self.event_handler
        if not isinstance(handler, OnProcessStart | OnProcessExit) or handler.rank < 0:
            context.notes.append(f"{self.where()}: {type(handler).__name__} event handler ignored")
            return
        entities = handler.entities
        if callable(entities):
            context.notes.append(f"{self.where()}: {handler.what} with a function ignored (no process events here)")
            return
        entities = list(entities) if isinstance(entities, Iterable) else [entities] if entities else []
        _defer(context, (handler.rank, 0.0), entities, f"{self.where()}: {handler.what}: its actions run after the "
               "others (ordering only; not when the target starts or exits)")


def _defer(context: LaunchContext, rank: tuple[int, float], entities: list[Any], note: str) -> None:
    context.notes.append(note)
    order = (rank[0], rank[1], len(context.deferred))
    context.deferred.append(Deferred(order, entities, context.frame.pushed(), context.file))


class ShutdownEvent:
    """launch.events.Shutdown: nothing to emit it to here."""

    def __init__(self, *, reason: str = "reason not given", due_to_sigint: bool = False) -> None:
        self.reason, self.due_to_sigint = reason, due_to_sigint


class EmitEvent(Action):
    """Emit an event: none has an effect here (the launcher ends on Ctrl-C or its processes' exits)."""

    def __init__(self, *, event: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.event = event


class Shutdown(EmitEvent):
    """Shut the launch down: no effect while reading (its place in an event handler is ordering only)."""

    def __init__(self, *, reason: str = "reason not given", **kwargs: Any) -> None:
        super().__init__(event=ShutdownEvent(reason=reason), **kwargs)


class OnExecutionComplete(OnProcessStart):
    """An action's completion: not an event here (the handler is noted and ignored)."""

    def __init__(self, **kwargs: Any) -> None:
        super().__init__()
        del kwargs
        self.rank, self.what = -1, "OnExecutionComplete"


class OnShutdown(OnExecutionComplete):
    """The launch's shutdown: not an event here (the handler is noted and ignored)."""


class OnProcessIO(OnExecutionComplete):
    """A process's output: not an event here (the handler is noted and ignored)."""


def run_deferred(context: LaunchContext) -> None:
    """Run what launch would run later, in its order, each in the scope it was registered in."""
    while context.deferred:
        item = min(context.deferred, key=lambda d: d.order)
        context.deferred.remove(item)
        saved, saved_file = context.frame, context.file
        context.frame, context.file = item.frame, item.file
        try:
            for entity in item.entities:
                visit(entity, context)
        finally:
            context.frame, context.file = saved, saved_file
