"""ROS 1 ``<param type=...>``: the value roslaunch would store, as the text of a ``-p`` value.

roslaunch converts by ``type``: ``str``/``string`` keep the text as written, ``int``,
``double``/``float`` convert the stripped text, ``bool``/``boolean`` take true/1/false/0 in
any case, ``yaml`` parses it; with no type (or ``auto``) it tries int, then float, then
true/false in any case, and keeps text otherwise. rcl reads a ``-p`` value as YAML, so the
result is written as YAML that reads back as the same type (strings quoted when needed).
"""

from __future__ import annotations

import yaml

__all__ = ["ros1_param_text"]


def ros1_param_text(text: str, ptype: str | None) -> str:
    """``text`` converted as roslaunch converts a ``<param>`` of type ``ptype``, as a ``-p`` value.

    Raises ``ValueError`` (roslaunch's wording) when the text is not of the type.
    """
    return _yaml_text(_convert(text, (ptype or "auto").lower()))


def _convert(text: str, ptype: str) -> object:
    if ptype in ("str", "string"):
        return text
    value = text.strip()
    try:
        if ptype == "int":
            return int(value)
        if ptype in ("double", "float"):
            return float(value)
    except ValueError:
        raise ValueError(f"'{text}' is not a '{ptype}' type") from None
    if ptype in ("bool", "boolean"):
        word = value.lower()
        if word in ("true", "1"):
            return True
        if word in ("false", "0"):
            return False
        raise ValueError(f"'{text}' is not a '{ptype}' type")
    if ptype == "yaml":
        try:
            return yaml.safe_load(value)
        except yaml.YAMLError as exc:
            raise ValueError(f"'{text}' is not a '{ptype}' type: {' '.join(str(exc).splitlines())}") from None
    if ptype != "auto":
        raise ValueError(f"unknown type '{ptype}'")
    for convert in (int, float):
        try:
            return convert(value)
        except ValueError:
            pass
    word = value.lower()
    if word in ("true", "false"):
        return word == "true"
    return text


def _yaml_text(value: object) -> str:
    if isinstance(value, str) and value == "":
        return "''"
    return str(yaml.safe_dump(value, default_flow_style=True, width=2**31)).strip().removesuffix("...").strip()
