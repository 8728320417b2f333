"""ROS 1 ``<rosparam command="load">``: YAML (inline or from ``file``) flattened into parameters."""

from __future__ import annotations

from pathlib import Path

import yaml

from robotmodel.launch._model import Param
from robotmodel.launch._subst import SubstContext

__all__ = ["read_rosparam_file", "rosparam_params"]


def rosparam_params(text: str, base: str, ctx: SubstContext) -> list[Param]:
    """The parameters of YAML ``text`` under ``base`` (``a/b``), nested maps as dotted names.

    Leaf values are kept as flow YAML (``[a, b]``, ``0.5``), as the other parameters' text.
    """
    try:
        data = yaml.safe_load(text) if text.strip() else None
    except yaml.YAMLError as exc:
        raise ctx.error(f"<rosparam>: invalid YAML: {' '.join(str(exc).splitlines())}") from None
    out: list[Param] = []

    def flatten(prefix: str, value: object) -> None:
        if isinstance(value, dict) and value:
            for key, item in value.items():
                flatten(f"{prefix}/{key}" if prefix else str(key), item)
        elif prefix:
            out.append(Param(prefix.replace("/", "."), value=yaml.safe_dump(value, default_flow_style=True)
                             .strip().removesuffix("...").strip(), file=ctx.path, line=ctx.line))

    flatten(base, data)
    return out


def read_rosparam_file(path: Path, ctx: SubstContext) -> str:
    """The text of a ``<rosparam file=...>``; roslaunch's error when it is missing."""
    try:
        return path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError):
        raise ctx.error(f"<rosparam>: file does not exist [{path}]") from None
