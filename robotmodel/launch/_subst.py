"""Substitutions in launch attributes: ``$(name arg ...)``, nested, for both dialects.

ROS 1 (roslaunch): ``arg``, ``find``, ``env``, ``optenv``, ``anon``, ``dirname``, ``eval``.
ROS 2 (launch frontends): ``var``, ``find-pkg-share``, ``find-pkg-prefix``, ``find-exec``, ``env``,
``anon``, ``dirname``, ``filename``, ``eval``, ``command``, ``not``, ``and``, ``or``,
``equals``. ``$(command ...)`` runs nothing but xacro, expanded in-process.

ROS 2 groups an argument with spaces in single (or double) quotes; ROS 1 has no quoting,
and ``optenv``'s default is the rest of the words. ``$(eval ...)`` takes its text raw up to
the matching parenthesis: in ROS 1 launch args are its variables and ``arg()`` returns them,
typed as roslaunch's ``convert_value(value, 'auto')`` types them (``'false'`` is False,
``'0.5'`` is 0.5), beside ``find()``/``env()``/... and math's names; in ROS 2 the text is
substituted first, then evaluated with math's names. Either writes back Python's ``str()``.
"""

from __future__ import annotations

import hashlib
import math
import os
import shlex
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import Any

from robotmodel.errors import LaunchError, RobotModelError
from robotmodel.launch._eval import EvalError, safe_eval
from robotmodel.launch._model import Dialect, XacroSource
from robotmodel.launch._ptype import auto_value
from robotmodel.launch._syntax import Sub, SubstContext, parse

__all__ = ["Sub", "SubstContext", "expand_xacro", "parse", "parse_xacro_command", "resolve", "resolve_parts", "truth"]


def resolve(text: str, ctx: SubstContext) -> str:
    """``text`` with every substitution replaced by its value."""
    return resolve_parts(parse(text, ctx), ctx)


def resolve_parts(parts: Sequence[str | Sub], ctx: SubstContext) -> str:
    """Join already parsed parts, resolving their substitutions."""
    return "".join(p if isinstance(p, str) else _apply(p, ctx) for p in parts)


def truth(value: str, ctx: SubstContext, attr: str) -> bool:
    """A condition's value: true/1 or false/0 (any case); anything else is an error."""
    word = value.strip().lower()
    if word in ("true", "1"):
        return True
    if word in ("false", "0"):
        return False
    raise ctx.error(f"{attr}=\"{value}\": value must be true or false (or 1/0)")


def _apply(sub: Sub, ctx: SubstContext) -> str:
    table = _ROS1 if ctx.dialect is Dialect.ROS1 else _ROS2
    handler = table.get(sub.name)
    if handler is None:
        if ctx.dialect is Dialect.ROS2:
            raise ctx.error(f"Unknown substitution: {sub.name}")
        shown = f"{sub.name} {sub.raw}" if sub.raw else sub.name
        raise ctx.error(f"Unknown substitution command [{shown}]. Valid commands are {sorted(table)}")
    words = [resolve_parts(a, ctx) for a in sub.args]
    try:
        return handler(sub, words, ctx)
    except LaunchError:
        raise
    except RobotModelError as exc:
        raise ctx.error(f"$({sub.name} {sub.raw}): {' '.join(str(exc).splitlines())}") from None


def _count(sub: Sub, words: list[str], ctx: SubstContext, low: int, high: int) -> None:
    if not low <= len(words) <= high:
        want = str(low) if low == high else f"{low} to {high}"
        raise ctx.error(f"$({sub.name}) takes {want} argument(s), got {len(words)}: '$({sub.name} {sub.raw})'")


def _arg(sub: Sub, words: list[str], ctx: SubstContext) -> str:
    _count(sub, words, ctx, 1, 1)
    value = _lookup(words[0], ctx)
    if ctx.dialect is Dialect.ROS1 and "$(find " in value:
        # roslaunch resolves $(find) after $(arg), in the text the args produced: so
        # model:='$(find pkg)/urdf/x.urdf' on the command line works, as its tutorials show.
        parts = parse(value, ctx)
        value = "".join(p if isinstance(p, str) else _find(p, [resolve_parts(a, ctx) for a in p.args], ctx)
                        if p.name == "find" else f"$({p.name} {p.raw})" for p in parts)
    return value


def _lookup(name: str, ctx: SubstContext) -> str:
    if name not in ctx.args:
        if ctx.dialect is Dialect.ROS2:
            raise ctx.error(f"launch configuration '{name}' does not exist")
        raise ctx.error(f"arg '{name}' is not defined")
    value = ctx.args[name]
    if value is None:
        raise ctx.error(f"arg '{name}' is not set")
    return value


def _find(sub: Sub, words: list[str], ctx: SubstContext) -> str:
    from robotmodel.errors import PackageNotFoundError
    from robotmodel.resources import find_package

    _count(sub, words, ctx, 1, 1)
    try:
        root = find_package(words[0], start=ctx.path, package_paths=ctx.package_paths)
    except PackageNotFoundError:
        if words[0] == "xacro":
            # Only ever the folder of the xacro program, which runs in-process here.
            return "[xacro]"
        raise
    ctx.found_packages[root] = None
    return str(root)


def _find_prefix(sub: Sub, words: list[str], ctx: SubstContext) -> str:
    share = Path(_find(sub, words, ctx))
    # An installed package's prefix is two levels above <prefix>/share/<pkg>; a source tree has none.
    return str(share.parent.parent) if share.parent.name == "share" else str(share)


def _find_exec(sub: Sub, words: list[str], ctx: SubstContext) -> str:
    import shutil

    _count(sub, words, ctx, 1, 1)
    found = shutil.which(words[0])
    if found is not None:
        return found
    if words[0] in _XACRO_PROGRAMS:
        return words[0]  # xacro runs in-process; only its name matters
    raise ctx.error(f"executable '{words[0]}' not found on the PATH")


def _env(sub: Sub, words: list[str], ctx: SubstContext) -> str:
    if ctx.dialect is Dialect.ROS1:
        _count(sub, words, ctx, 1, 1)
    else:
        _count(sub, words, ctx, 1, 2)
    value = os.environ.get(words[0])
    if value is not None:
        return value
    if len(words) == 2:
        return words[1]
    if ctx.dialect is Dialect.ROS2:
        raise ctx.error(f"environment variable '{words[0]}' does not exist")
    raise ctx.error(f"environment variable '{words[0]}' is not set")


def _optenv(sub: Sub, words: list[str], ctx: SubstContext) -> str:
    if not words:
        _count(sub, words, ctx, 1, 1)
    return os.environ.get(words[0], " ".join(words[1:]))


def _anon(sub: Sub, words: list[str], ctx: SubstContext) -> str:
    _count(sub, words, ctx, 1, 1)
    # Stable within one run, distinct between runs: the same name twice gives the same value.
    tag = hashlib.sha1(f"{os.getpid()}:{words[0]}".encode()).hexdigest()[:10]
    return f"{words[0]}_{tag}"


def _dirname(sub: Sub, words: list[str], ctx: SubstContext) -> str:
    _count(sub, words, ctx, 0, 0)
    return str(ctx.path.parent)


def _filename(sub: Sub, words: list[str], ctx: SubstContext) -> str:
    _count(sub, words, ctx, 0, 0)
    return str(ctx.path)


def _text(value: Any) -> str:
    return ("true" if value else "false") if isinstance(value, bool) else str(value)


def _eval1(sub: Sub, words: list[str], ctx: SubstContext) -> str:
    del words
    # As roslaunch's _eval: arg('x') and a bare x give the arg typed by convert_value(..., 'auto'),
    # so 'false' is False and '0.5' is 0.5. A bare name is looked up among the functions,
    # true/false and math's names first, then among the args.
    functions: dict[str, Callable[..., Any]] = {
        "arg": lambda n: auto_value(_lookup(str(n), ctx)),
        "find": lambda p: _find(Sub("find", (), p), [str(p)], ctx),
        "env": lambda v: _env(Sub("env", (), v), [str(v)], ctx),
        "optenv": lambda v, d="": os.environ.get(str(v), str(d)),
        "anon": lambda n: _anon(Sub("anon", (), n), [str(n)], ctx),
        "dirname": lambda: str(ctx.path.parent),
    }
    if "__" in sub.raw:
        raise ctx.error("$(eval ...) may not contain double underscore expressions")
    math_names = {k: v for k, v in vars(math).items() if not k.startswith("_")}
    names: dict[str, Any] = {k: auto_value(v) for k, v in ctx.args.items() if v is not None}
    names.update({"true": True, "false": False, "True": True, "False": False}, **math_names, **functions)
    callables = {k: v for k, v in math_names.items() if callable(v)} | functions
    try:
        result = safe_eval(sub.raw, names, callables)
    except EvalError as exc:
        raise ctx.error(f"$(eval {sub.raw}): {exc}") from None
    # roslaunch writes Python's str(): True/False, 6.283.
    return str(result)


def _eval2(sub: Sub, words: list[str], ctx: SubstContext) -> str:
    del words
    text = sub.raw
    if len(text) >= 2 and text[0] == text[-1] and text[0] in "'\"":
        text = text[1:-1]
    expr = resolve(text, ctx)
    names: dict[str, Any] = {k: v for k, v in vars(math).items() if not k.startswith("_")}
    names["math"] = math
    functions = {k: v for k, v in names.items() if callable(v)}
    try:
        result = safe_eval(expr, names, functions)
    except EvalError as exc:
        raise ctx.error(f"$(eval {sub.raw}): {exc}") from None
    return str(result)


def _command(sub: Sub, words: list[str], ctx: SubstContext) -> str:
    _count(sub, words, ctx, 1, 2)
    return expand_xacro(words[0], parse_xacro_command(words[0], ctx), ctx)


def expand_xacro(command: str, source: XacroSource, ctx: SubstContext, param: str = "") -> str:
    """The output of xacro for ``source`` (read from ``command``), expanded in-process.

    A failure raises LaunchError with xacro's error on one line, in the launch system's
    words: ROS 2's ``$(command)`` ("executed command failed"), roslaunch's ``<param
    command>`` of parameter ``param`` ("Cannot load command parameter").
    """
    from robotmodel.xacro import expand

    try:
        return expand(source.file, dict(source.mappings), package_paths=ctx.package_paths)
    except RobotModelError as exc:
        reason = " ".join(str(exc).splitlines())
    if ctx.dialect is Dialect.ROS2:
        raise ctx.error(f"executed command failed. Command: {command} Captured stderr output: {reason}")
    raise ctx.error(f"Invalid <param> tag: Cannot load command parameter [{param}]: command [{command}] failed: "
                    f"{reason}")


def _not(sub: Sub, words: list[str], ctx: SubstContext) -> str:
    _count(sub, words, ctx, 1, 1)
    return _text(not truth(words[0], ctx, "$(not)"))


def _and(sub: Sub, words: list[str], ctx: SubstContext) -> str:
    _count(sub, words, ctx, 2, 2)
    values = [truth(w, ctx, "$(and)") for w in words]  # both checked, as launch does
    return _text(all(values))


def _or(sub: Sub, words: list[str], ctx: SubstContext) -> str:
    _count(sub, words, ctx, 2, 2)
    values = [truth(w, ctx, "$(or)") for w in words]
    return _text(any(values))


def _equals(sub: Sub, words: list[str], ctx: SubstContext) -> str:
    _count(sub, words, ctx, 2, 2)
    return _text(words[0] == words[1])


Handler = Callable[[Sub, list[str], SubstContext], str]

_ROS1: dict[str, Handler] = {
    "arg": _arg, "find": _find, "env": _env, "optenv": _optenv, "anon": _anon, "dirname": _dirname,
    "eval": _eval1,
}
_ROS2: dict[str, Handler] = {
    "var": _arg, "find-pkg-share": _find, "find-pkg-prefix": _find_prefix, "find-exec": _find_exec, "env": _env,
    "anon": _anon,
    "dirname": _dirname, "filename": _filename, "eval": _eval2, "command": _command, "not": _not,
    "and": _and, "or": _or, "equals": _equals,
}

_XACRO_PROGRAMS = ("xacro", "xacro.py")


def parse_xacro_command(command: str, ctx: SubstContext) -> XacroSource:
    """``xacro [options] FILE [name:=value ...]`` (any path to xacro or xacro.py) as a XacroSource.

    Other programs are refused: launch files run nothing but xacro here.
    """
    try:
        words = shlex.split(command)
    except ValueError as exc:
        raise ctx.error(f"cannot split command '{command}': {exc}") from None
    if not words or Path(words[0]).name not in _XACRO_PROGRAMS:
        program = words[0] if words else ""
        raise ctx.error(f"command '{command}': only xacro commands are run, not '{program}'")
    files: list[str] = []
    mappings: list[tuple[str, str]] = []
    for word in words[1:]:
        if ":=" in word:
            name, _, value = word.partition(":=")
            mappings.append((name.strip(), value.strip()))
        elif word.startswith("-"):
            if word not in ("--inorder", "--legacy", "--xacro-ns", "--check-order"):
                raise ctx.error(f"command '{command}': xacro option '{word}' is not supported in launch files")
        else:
            files.append(word)
    if len(files) != 1:
        raise ctx.error(f"command '{command}': expected one xacro input file, got {len(files)}")
    path = Path(files[0])
    if not path.is_absolute():
        path = Path.cwd() / path
    if not path.is_file():
        raise ctx.error(f"command '{command}': no such file: {path}")
    return XacroSource(path, tuple(mappings))
