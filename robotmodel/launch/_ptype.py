"""ROS 1 ``<param type=...>``: the value roslaunch would store, as the text of a ``-p`` value.

roslaunch converts by ``type``: ``str``/``string`` keep the text as written, ``int``,
``double``/``float`` convert the stripped text, ``bool``/``boolean`` take true/1/false/0 in
any case, ``yaml`` parses it; with no type (or ``auto``) the stripped text is guessed as
roslaunch's ``convert_value(text, 'auto')`` guesses (:func:`auto_value`, which ``$(eval)``
uses for the args too). rcl reads a ``-p`` value as YAML, so the result is written as YAML
that reads back as the same type (strings quoted when needed).
"""

from __future__ import annotations

import yaml

__all__ = ["auto_value", "ros1_param_text"]


def ros1_param_text(text: str, ptype: str | None) -> str:
    """``text`` converted as roslaunch converts a ``<param>`` of type ``ptype``, as a ``-p`` value.

    Raises ``ValueError`` (roslaunch's wording) when the text is not of the type.
    """
    return _yaml_text(_convert(text, (ptype or "auto").lower()))


def auto_value(text: str) -> object:
    """``text`` typed as roslaunch's ``convert_value(text, 'auto')`` types it.

    A float when the text holds a '.', else an int (unless it holds '_', which Python
    would drop but roslaunch keeps as text); failing both, true/false in any case as a bool;
    else the text itself. So ``1e3`` and ``inf`` stay text, as in roslaunch.
    """
    try:
        if "." in text:
            return float(text)
        if "_" not in text:
            return int(text)
    except ValueError:
        pass
    word = text.lower()
    if word in ("true", "false"):
        return word == "true"
    return text


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
    # roslaunch strips a value attribute before it guesses its type.
    return auto_value(value)


def _yaml_text(value: object) -> str:
    if isinstance(value, str) and (value == "" or _rcl_types_plain(value)):
        return "'" + value.replace("'", "''") + "'"
    return str(yaml.safe_dump(value, default_flow_style=True, width=2**31)).strip().removesuffix("...").strip()


def _rcl_types_plain(text: str) -> bool:
    """Whether rcl would read ``text`` unquoted as other than a string (it must then be quoted).

    rcl takes y/n, yes/no, on/off as bools and ``1e3``, ``08``, ``0x10``, ``inf`` as numbers,
    where PyYAML's YAML 1.1 would write them plain; quoting a string needlessly is harmless.
    """
    if text.strip().lower() in ("y", "n", "yes", "no", "on", "off", "true", "false"):
        return True
    for read in (float, lambda t: int(t, 0), float.fromhex):
        try:
            read(text)
        except ValueError:
            continue
        return True
    return False
