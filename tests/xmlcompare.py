"""Compare two XML documents as upstream xacro's tests do: structure equal, numbers within a tolerance."""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET


def _tokens_equal(a: str, b: str, tol: float) -> bool:
    ta, tb = a.split(), b.split()
    if len(ta) != len(tb):
        return False
    for x, y in zip(ta, tb, strict=True):
        if x == y:
            continue
        try:
            if not math.isclose(float(x), float(y), rel_tol=tol, abs_tol=tol):
                return False
        except ValueError:
            return False
    return True


def xml_diff(a: str, b: str, tol: float = 1e-9, ignore_attrs: tuple[str, ...] = ()) -> str | None:
    """None when equal, else a description of the first difference."""
    return _diff(ET.fromstring(a), ET.fromstring(b), "/", tol, ignore_attrs)


def _diff(a: ET.Element, b: ET.Element, path: str, tol: float, ignore: tuple[str, ...]) -> str | None:
    here = f"{path}{a.tag}[{a.get('name', '')}]"
    if a.tag != b.tag:
        return f"{here}: tag {a.tag} != {b.tag}"
    attrs_a = {k: v for k, v in a.attrib.items() if k not in ignore}
    attrs_b = {k: v for k, v in b.attrib.items() if k not in ignore}
    if attrs_a.keys() != attrs_b.keys():
        return f"{here}: attributes {sorted(attrs_a)} != {sorted(attrs_b)}"
    for key, value in attrs_a.items():
        if not _tokens_equal(value, attrs_b[key], tol):
            return f"{here}@{key}: {value!r} != {attrs_b[key]!r}"
    if not _tokens_equal(a.text or "", b.text or "", tol):
        return f"{here}: text {a.text!r} != {b.text!r}"
    kids_a = [c for c in a if isinstance(c.tag, str)]
    kids_b = [c for c in b if isinstance(c.tag, str)]
    if len(kids_a) != len(kids_b):
        return f"{here}: {len(kids_a)} children != {len(kids_b)}"
    for x, y in zip(kids_a, kids_b, strict=True):
        found = _diff(x, y, here + "/", tol, ignore)
        if found:
            return found
    return None
