"""Frame and broadcaster names written into YAML and graphviz text, whatever characters they hold.

tf2 writes names into ``allFramesAsYAML`` unquoted (keys) or in single quotes (values),
and any publisher chooses the names: a control character, a quote, ``true`` or ``1`` then
breaks or retypes the YAML. Names that read back as themselves are written as tf2 writes
them; any other goes in a double-quoted YAML scalar with escapes, which every YAML reader
reads back to the same string.
"""

from __future__ import annotations

import re

__all__ = ["dot_quoted", "yaml_key", "yaml_quoted"]

_PLAIN = re.compile(r"[A-Za-z_/][A-Za-z0-9_/.\-]*")
# Words a YAML 1.1 or 1.2 reader takes for a boolean or null rather than a string.
_TYPED_WORDS = frozenset({"true", "false", "yes", "no", "on", "off", "y", "n", "null"})
_SHORT_ESCAPES = {"\\": "\\\\", '"': '\\"', "\n": "\\n", "\t": "\\t", "\r": "\\r", "\0": "\\0"}


def _double_quoted(name: str) -> str:
    out = ['"']
    for ch in name:
        code = ord(ch)
        if ch in _SHORT_ESCAPES:
            out.append(_SHORT_ESCAPES[ch])
        elif 0x20 <= code < 0x7F:
            out.append(ch)
        elif code <= 0xFF:
            out.append(f"\\x{code:02x}")
        elif code <= 0xFFFF:
            out.append(f"\\u{code:04x}")
        else:
            out.append(f"\\U{code:08x}")
    out.append('"')
    return "".join(out)


def yaml_key(name: str) -> str:
    """``name`` as a YAML mapping key: bare when YAML reads it back as that string, else double-quoted."""
    if _PLAIN.fullmatch(name) and name.lower() not in _TYPED_WORDS:
        return name
    return _double_quoted(name)


def yaml_quoted(name: str) -> str:
    """``name`` as a YAML string value: single-quoted as tf2 writes it when that is safe, else double-quoted."""
    if all(0x20 <= ord(ch) < 0x7F for ch in name) and "'" not in name:
        return f"'{name}'"
    return _double_quoted(name)


def dot_quoted(name: str) -> str:
    r"""The inside of a graphviz double-quoted string showing ``name`` (unprintable characters as ``\xNN``).

    Distinct names stay distinct: a backslash in a name is doubled before unprintable
    characters become ``\xNN``, then the text is escaped for dot.
    """
    shown = "".join(ch if ch.isprintable() else f"\\x{ord(ch):02x}" if ord(ch) <= 0xFF else f"\\u{ord(ch):04x}"
                    for ch in name.replace("\\", "\\\\"))
    return shown.replace("\\", "\\\\").replace('"', '\\"')
