"""``ROS_DOMAIN_ID`` read the way rcl reads it, and the domain id rmw_zenoh then uses.

rcl parses the variable with C's ``strtoul(text, &end, 0)``, so its quirks are ROS's:
leading blanks and a sign are skipped, ``0x`` means hexadecimal and a leading ``0`` octal,
digits are read as far as they go and the rest is ignored, unless nothing but 0 was read.
A negative number wraps modulo 2**64, and SIZE_MAX is rcl's "default domain", which
rmw_zenoh turns into 0.
"""

from __future__ import annotations

import os

from robotmodel.errors import BusError

__all__ = ["default_domain_id", "parse_domain_id"]

_ULONG_MAX = 2**64 - 1
_C_SPACE = " \t\n\v\f\r"
_NOT_INTEGRAL = "ROS_DOMAIN_ID is not an integral number"


def _strtoul0(text: str) -> tuple[int, str]:
    """C's strtoul with base 0: the value and the unread rest; BusError where it sets ERANGE."""
    i = 0
    while i < len(text) and text[i] in _C_SPACE:
        i += 1
    negative = False
    if i < len(text) and text[i] in "+-":
        negative = text[i] == "-"
        i += 1
    base = 10
    if text[i:i + 2] in ("0x", "0X") and i + 2 < len(text) and text[i + 2] in "0123456789abcdefABCDEF":
        base, i = 16, i + 2
    elif text[i:i + 1] == "0":
        base = 8
    digits = "0123456789abcdef"[:base]
    j = i
    while j < len(text) and text[j].lower() in digits:
        j += 1
    if j == i:
        # No digits: strtoul reads nothing and points back at the start of the text.
        return 0, text
    value = int(text[i:j], base)
    if value > _ULONG_MAX:
        raise BusError("ROS_DOMAIN_ID is out of range")
    if negative:
        value = (-value) & _ULONG_MAX
    return value, text[j:]


def parse_domain_id(text: str) -> int:
    """The domain id a ROS 2 node on rmw_zenoh uses for this ``ROS_DOMAIN_ID`` text."""
    if text == "":
        return 0
    value, rest = _strtoul0(text)
    if value == 0 and rest:
        raise BusError(_NOT_INTEGRAL)
    return 0 if value == _ULONG_MAX else value


def default_domain_id() -> int:
    """``ROS_DOMAIN_ID`` from the environment as ROS 2 reads it (0 when unset or empty)."""
    return parse_domain_id(os.environ.get("ROS_DOMAIN_ID", ""))
