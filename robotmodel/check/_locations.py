"""Place a finding in the files a user edits: the URDF line, or the xacro file and line of the element.

xacro expansion loses line numbers, so an element is found again by its name in the source
texts: the entry file first, then (only when needed, as it costs one more expansion) the files
it includes. In order of preference:

1. the element written out, ``<link name="base_link">``;
2. a macro call given that exact name, ``<xacro:segment name="base_link" .../>``;
3. a name template that yields it, ``<link name="${prefix}base_link">``, when exactly one
   template matches with the most literal text (``${prefix}`` alone identifies nothing);
4. a macro call named by the end of the name after a separator, ``<xacro:link name="link7">``
   for ``fr3_link7`` (the longest such, when it is the only one).

Otherwise the finding is placed on the entry file without a line. Comments are ignored.
"""

from __future__ import annotations

import os
import re
from collections.abc import Callable, Iterator, Sequence
from pathlib import Path
from typing import NamedTuple

__all__ = ["Location", "SourceIndex", "display_path", "element_of", "error_location"]

_COMMENT = re.compile(r"<!--.*?-->", re.DOTALL)
_PLACEHOLDER = re.compile(r"\$\{[^}]*\}|\$\([^)]*\)")
# xacro's own directives are not macro calls.
_DIRECTIVES = "macro|property|arg|include|if|unless|element|attribute|insert_block|call"
_CALL_NAME = re.compile(
    rf"<xacro:(?!(?:{_DIRECTIVES})\b)[\w.-]+\b[^>]*?\sname\s*=\s*(\"[^\"]*\"|'[^']*')")
_ELEMENT = re.compile(r"^(link|joint|material) \[(.*)\]$")
_IN_MESSAGE = (
    (re.compile(r"\b(joint|link|material) '([^']+)' is not unique"), None),
    (re.compile(r"\b[Jj]oint \[([^\]]+)\]"), "joint"),
    (re.compile(r"\b[Ll]ink \[([^\]]+)\]"), "link"),
)
_XACRO_FILES = re.compile(r"\bin file ([^;)]+?)(?: <- [^;)]*)?\)")
_XML_LINE = re.compile(r"\bline (\d+), column \d+")
_UNKNOWN_MACRO = re.compile(r"\bunknown macro name: (xacro:[\w.-]+)")


class Location(NamedTuple):
    """Where a finding points: a file as the user names it, and a 1-based line when known."""

    file: str
    line: int | None


def display_path(path: str | os.PathLike[str]) -> str:
    """``path`` relative to the working directory when it lies below it (as CI annotations want)."""
    p = Path(os.path.normpath(path))
    if p.is_absolute():
        try:
            return p.relative_to(Path.cwd()).as_posix()
        except ValueError:
            return p.as_posix()
    return p.as_posix()


def element_of(element: str) -> tuple[str, str] | None:
    """``("link", "base")`` for a finding's element ``link [base]``; None for others."""
    match = _ELEMENT.match(element)
    return (match.group(1), match.group(2)) if match else None


def _blank_comments(text: str) -> str:
    # Same length and same newlines, so offsets still give the right line.
    return _COMMENT.sub(lambda m: re.sub(r"[^\n]", " ", m.group(0)), text)


def _line(text: str, offset: int) -> int:
    return text.count("\n", 0, offset) + 1


def _start(tag: str) -> str:
    """A start tag of the element ``tag``; a joint must have a type (a transmission's <joint> has none)."""
    return rf"<{tag}\b(?=[^>]*\stype\s*=)" if tag == "joint" else rf"<{tag}\b"


def _quoted(value: str) -> str:
    return rf"(?:\"{re.escape(value)}\"|'{re.escape(value)}')"


class SourceIndex:
    """The source texts of one checked document, searched for the elements findings name.

    ``entry`` is the file the user checks (its name is kept as given); ``includes`` returns
    the files it includes and is called at most once, only when the entry alone does not
    place a finding.
    """

    def __init__(self, entry: str, includes: Callable[[], Sequence[str]] | None = None) -> None:
        self.entry = entry
        self._includes = includes
        self._texts: list[tuple[str, str]] = []
        self._loaded_includes = includes is None
        self._add(entry)

    def _add(self, path: str) -> None:
        if not Path(path).is_file():
            return  # a pipe (a shell's <(...)) can be read once, and that read is the load's
        try:
            text = Path(path).read_text(encoding="utf-8", errors="replace")
        except OSError:
            return
        self._texts.append((display_path(path), _blank_comments(text)))

    def _sources(self, *, with_includes: bool) -> list[tuple[str, str]]:
        if with_includes and not self._loaded_includes:
            self._loaded_includes = True
            assert self._includes is not None
            seen = {os.path.realpath(self.entry)}
            for path in self._includes():
                real = os.path.realpath(path)
                if real not in seen:
                    seen.add(real)
                    self._add(path)
        return self._texts

    def _first(self, pattern: re.Pattern[str], *, with_includes: bool) -> Location | None:
        for name, text in self._sources(with_includes=with_includes):
            match = pattern.search(text)
            if match is not None:
                return Location(name, _line(text, match.start()))
        return None

    def locate(self, tag: str, name: str) -> Location:
        """Where the ``tag`` element named ``name`` is written or made (see the module's order)."""
        written = re.compile(rf"{_start(tag)}[^>]*?\sname\s*=\s*{_quoted(name)}")
        called = re.compile(rf"<xacro:(?!(?:{_DIRECTIVES})\b)[\w.-]+\b[^>]*?\sname\s*=\s*{_quoted(name)}")
        for with_includes in (False, True):
            for pattern in (written, called):
                found = self._first(pattern, with_includes=with_includes)
                if found is not None:
                    return found
        return self._template(tag, name) or self._prefixed_call(name) or Location(display_path(self.entry), None)

    def _prefixed_call(self, name: str) -> Location | None:
        """A macro call named by the end of ``name`` after a separator: ``name="link7"`` for ``fr3_link7``."""
        best: list[Location] = []
        best_len = 0
        for file, text in self._sources(with_includes=True):
            for match in _CALL_NAME.finditer(text):
                value = match.group(1)[1:-1]
                if (not value or _PLACEHOLDER.search(value) or len(value) >= len(name)
                        or not name.endswith(value) or name[-len(value) - 1].isalnum()):
                    continue
                here = Location(file, _line(text, match.start()))
                if len(value) > best_len:
                    best, best_len = [here], len(value)
                elif len(value) == best_len:
                    best.append(here)
        return best[0] if len(set(best)) == 1 else None

    def first_use(self, tag: str) -> Location:
        """The first ``<tag`` written in the entry file (e.g. a call of an unknown macro), else the file."""
        return self._first(re.compile(rf"<{re.escape(tag)}\b"), with_includes=False) or Location(
            display_path(self.entry), None)

    def locate_value(self, attribute: str, value: str) -> Location | None:
        """The first place ``attribute="value"`` is written, e.g. a mesh's ``filename``; None if nowhere."""
        pattern = re.compile(rf"\s{re.escape(attribute)}\s*=\s*{_quoted(value)}")
        for with_includes in (False, True):
            found = self._first(pattern, with_includes=with_includes)
            if found is not None:
                return found
        return None

    def _templates(self, tag: str) -> Iterator[tuple[str, int, str]]:
        element = re.compile(rf"{_start(tag)}[^>]*?\sname\s*=\s*(\"[^\"]*\"|'[^']*')")
        for file, text in self._sources(with_includes=True):
            for pattern in (element, _CALL_NAME):
                for match in pattern.finditer(text):
                    value = match.group(1)[1:-1]
                    if _PLACEHOLDER.search(value):
                        yield file, _line(text, match.start()), value

    def _template(self, tag: str, name: str) -> Location | None:
        best: list[Location] = []
        best_score = 0
        for file, line, template in self._templates(tag):
            pieces = _PLACEHOLDER.split(template)
            regex = ".*?".join(re.escape(p) for p in pieces)
            if re.fullmatch(regex, name, re.DOTALL) is None:
                continue
            score = sum(len(p) for p in pieces)
            if score > best_score:
                best, best_score = [Location(file, line)], score
            elif score == best_score and score > 0:
                best.append(Location(file, line))
        return best[0] if len(set(best)) == 1 else None


def error_location(message: str, index: SourceIndex) -> Location:
    """Where the error ``message`` (from loading ``index.entry``) points.

    URDF errors start with ``FILE:LINE:`` when the parser placed them; xacro errors end with
    ``(in file A <- B)`` (A the innermost; an unknown macro is placed at its first call there)
    and XML errors carry ``line N, column M``; failing those, an element the message names is
    looked up as for findings.
    """
    entry = index.entry
    for prefix in (f"{entry}:", f"{display_path(entry)}:"):
        if message.startswith(prefix):
            head = message[len(prefix):].split(":", 1)[0]
            if head.isdigit():
                return Location(display_path(entry), int(head))
    files = _XACRO_FILES.search(message)
    line = _XML_LINE.search(message)
    if files is not None:
        inner = files.group(1).strip()
        if inner != "string":
            if line is None and (macro := _UNKNOWN_MACRO.search(message)) is not None:
                return SourceIndex(inner).first_use(macro.group(1))
            return Location(display_path(inner), int(line.group(1)) if line else None)
    for pattern, tag in _IN_MESSAGE:
        match = pattern.search(message)
        if match is None:
            continue
        if tag is None:
            return index.locate(match.group(1), match.group(2))
        return index.locate(tag, match.group(1))
    return Location(display_path(entry), None)
