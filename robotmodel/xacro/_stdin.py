"""A robot document read whole from standard input (``-`` in place of a file, as the ROS tools take it)."""

from __future__ import annotations

import sys

from robotmodel.errors import URDFParseError

__all__ = ["read_stdin_document"]


def read_stdin_document() -> str:
    """Read a whole XML document from stdin; empty or non-XML input is a URDFParseError."""
    text = sys.stdin.read()
    if not text.lstrip("\ufeff \t\r\n").startswith("<"):
        raise URDFParseError("<stdin>: empty document or not XML")
    return text
