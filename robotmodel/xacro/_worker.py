"""Child-process side of xacro expansion (run as ``python -m robotmodel.xacro._worker``).

xacro 2.1.1 keeps global state, patches minidom for the whole process, calls
``sys.exit`` on errors and has no guard against runaway expansion. Running it in a
child process with an address-space limit contains all of that; the parent enforces
the wall-clock limit. The request arrives as JSON on stdin; the URDF text goes to
stdout, and on failure one JSON line ``{"error": ...}`` goes to stderr with exit 3.
"""

from __future__ import annotations

import json
import os
import re
import resource
import sys
from pathlib import Path
from typing import Any

from robotmodel.errors import RobotModelError, UntrustedInputError
from robotmodel.resources import find_package, resolve_uri, resolved_packages

EXIT_ERROR = 3


def _clean(message: str) -> str:
    """One line; drop xacro's ``<class '...'>:`` prefix and its doubled messages."""
    text = " ".join(message.split())
    text = re.sub(r"<class '[\w.]+'>: ", "", text)
    half = len(text) // 2
    if len(text) % 2 == 1 and text[:half] == text[half + 1 :]:
        text = text[:half]
    return text.strip()


class _Guard:
    """Package roots an untrusted input may read from."""

    def __init__(self, input_file: Path | None, package_paths: list[str]) -> None:
        self.roots: list[Path] = [Path(p).resolve() for p in package_paths]
        if input_file is not None:
            folder = input_file.resolve().parent
            own = next((a for a in [folder, *folder.parents] if (a / "package.xml").is_file()), folder)
            self.roots.append(own)

    def allow(self, root: Path) -> None:
        self.roots.append(root.resolve())

    def check(self, path: str, what: str) -> None:
        resolved = Path(path).resolve()
        if not any(resolved.is_relative_to(r) for r in self.roots):
            raise UntrustedInputError(
                f"untrusted input: {what} of '{path}' is outside the input's package roots "
                f"({', '.join(str(r) for r in self.roots)})"
            )


def _install_hooks(req: dict[str, Any]) -> None:
    import xacro
    from xacro import substitution_args as sa

    package_paths: list[str] = req["package_paths"]
    root_dir = req.get("root_dir")
    if root_dir:
        # xacro opens the top file and relative includes against --root-dir.
        xacro.root_dir = root_dir
    input_file = Path(root_dir or ".", req["path"]) if req.get("path") else None
    start = input_file if input_file is not None else Path(req.get("base_dir") or ".")
    untrusted: bool = req["untrusted"]
    guard = _Guard(input_file, package_paths)

    def find(pkg: str) -> str:
        found = find_package(pkg, start=start, package_paths=package_paths)
        if untrusted:
            guard.allow(found)
        return str(found)

    # xacro binds `find` in two places: the $(find) substitution and the eval dict.
    sa._eval_find = find
    sa._eval_dict["find"] = find
    xacro._global_symbols.setdefault("find", find)

    # xacro 2.1.1 never gives $(dirname) a file name; answer with the file being processed.
    original_dirname = sa._eval_dirname

    def dirname(filename: str | None = None) -> str:
        current = next((f for f in reversed(xacro.filestack or []) if f), None)
        if current is None:
            return str(original_dirname(filename))
        # No symlink resolution, as xacro; relative names are relative to --root-dir.
        return str(os.path.dirname(os.path.abspath(os.path.join(xacro.root_dir, current))))  # noqa: PTH100, PTH118, PTH120

    sa._eval_dirname = dirname

    original_abs = xacro.abs_filename_spec

    def abs_filename_spec(spec: str) -> str:
        if spec.startswith(("package://", "file://")):
            resolved = resolve_uri(spec, base_dir=start.parent if input_file else start,
                                   package_paths=package_paths)
            if untrusted and spec.startswith("package://"):
                guard.allow(resolved.parent)
            path = str(resolved)
        else:
            path = str(original_abs(spec))
        if untrusted:
            guard.check(path, "include/load_yaml")
        return path

    # get_include_files and load_yaml look the module global up at call time.
    xacro.abs_filename_spec = abs_filename_spec
    if untrusted:

        def refuse_env(*args: object, **kwargs: object) -> str:
            raise UntrustedInputError("untrusted input: $(env)/$(optenv) are refused")

        sa._eval_env = refuse_env
        sa._eval_optenv = refuse_env
        sa._eval_dict["env"] = refuse_env
        sa._eval_dict["optenv"] = refuse_env


def _location() -> str:
    import xacro

    macros = [m.body.getAttribute("name") for m in (xacro.macrostack or [])]
    files = [f or "string" for f in (xacro.filestack or [])]
    parts = []
    if macros:
        parts.append("in macro " + " <- ".join(reversed(macros)))
    if files:
        parts.append("in file " + " <- ".join(reversed(files)))
    return f" ({'; '.join(parts)})" if parts else ""


def _banner(doc: Any, name: str) -> None:
    """Put xacro's four banner comments before the document, naming ``name`` as xacro names a file."""
    from xml.dom.minidom import Comment

    rule = " " + "=" * 83 + " "
    shown = re.sub(r"-+", "-", name)  # "--" may not appear in an XML comment
    lines = [rule, f" |    This document was autogenerated by xacro from {shown:<30} | ",
             f" |    EDITING THIS FILE BY HAND IS NOT RECOMMENDED  {'':<30} | ", rule]
    first = doc.firstChild
    for line in lines:
        doc.insertBefore(Comment(line), first)


def _expand(req: dict[str, Any]) -> str:
    import xml.parsers.expat

    import xacro

    mappings = dict(req["args"])
    verbosity = int(req.get("verbosity", 1))
    try:
        if req.get("path"):
            doc = xacro.process_file(req["path"], mappings=mappings, verbosity=verbosity)
        else:
            xacro.init_stacks(None)
            doc = xacro.parse(req["text"])
            xacro.process_doc(doc, mappings=mappings, verbosity=verbosity)
            if req.get("banner"):
                _banner(doc, str(req["banner"]))
        if req.get("deps"):
            # xacro prints a set; keep each file once, in the order it was first used.
            return json.dumps(list(dict.fromkeys(xacro.all_includes)))
        return str(doc.toprettyxml(indent="  "))
    except xml.parsers.expat.ExpatError as exc:
        raise _Failure(f"XML parsing error: {exc}{_location()}") from None
    except RecursionError:
        raise _Failure(
            f"runaway recursion (a macro or property that refers to itself?){_location()}"
        ) from None
    except MemoryError:
        raise _Failure(f"expansion exceeded the memory limit{_location()}") from None
    except RobotModelError as exc:
        raise _Failure(f"{_clean(str(exc))}{_location()}", exc) from None
    except Exception as exc:
        # xacro wraps errors (XacroException.exc); a runaway shows only in the wrapped cause.
        if _caused_by(exc, MemoryError):
            raise _Failure(f"expansion exceeded the memory limit{_location()}") from None
        if _caused_by(exc, RecursionError):
            raise _Failure(
                f"runaway recursion (a macro or property that refers to itself?){_location()}"
            ) from None
        ours = _find_cause(exc, RobotModelError)
        if isinstance(ours, RobotModelError):
            raise _Failure(f"{_clean(str(ours))}{_location()}", ours) from None
        raise _Failure(f"{_clean(str(exc) or repr(exc))}{_location()}") from None


class _Failure(Exception):
    def __init__(self, message: str, cause: RobotModelError | None = None) -> None:
        super().__init__(message)
        self.kind = type(cause).__name__ if cause is not None else "XacroError"
        self.package = getattr(cause, "package", None)
        self.searched = getattr(cause, "searched", None)


def _find_cause(exc: BaseException, kind: type[BaseException]) -> BaseException | None:
    seen: set[int] = set()
    current: BaseException | None = exc
    while current is not None and id(current) not in seen:
        if isinstance(current, kind):
            return current
        seen.add(id(current))
        wrapped = getattr(current, "exc", None)
        nxt = wrapped if isinstance(wrapped, BaseException) else None
        current = nxt or current.__cause__ or current.__context__
    return None


def _caused_by(exc: BaseException, kind: type[BaseException]) -> bool:
    return _find_cause(exc, kind) is not None


def main() -> int:
    """Read one request from stdin, expand it, write the URDF to stdout."""
    req = json.load(sys.stdin)
    limit = int(req["memory_bytes"])
    resource.setrlimit(resource.RLIMIT_AS, (limit, limit))
    if req.get("cwd"):
        os.chdir(req["cwd"])
    try:
        _install_hooks(req)
        out = _expand(req)
    except _Failure as exc:
        _report_packages()
        reply = {"error": str(exc), "kind": exc.kind, "package": exc.package, "searched": exc.searched}
        sys.stderr.write(json.dumps(reply) + "\n")
        return EXIT_ERROR
    except MemoryError:
        sys.stderr.write(json.dumps({"error": "expansion exceeded the memory limit"}) + "\n")
        return EXIT_ERROR
    _report_packages()
    sys.stdout.write(out)
    return 0


def _report_packages() -> None:
    """Tell the parent which copy of each package was used (for --verbose)."""
    found = [[name, str(p.folder), p.how] for name, p in resolved_packages().items()]
    if found:
        sys.stderr.write(json.dumps({"packages": found}) + "\n")


if __name__ == "__main__":
    sys.exit(main())
