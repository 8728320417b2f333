"""The install layout: every library subpackage is listed, cli/, urdf/ and examples/ map into robotmodel."""

from __future__ import annotations

import ast
import importlib.metadata
import re
import sys
import tomllib

from conftest import REPO


def _config() -> dict[str, object]:
    with (REPO / "pyproject.toml").open("rb") as f:
        setuptools: dict[str, object] = tomllib.load(f)["tool"]["setuptools"]
    return setuptools


def test_every_library_subpackage_is_listed() -> None:
    on_disk = {"robotmodel"} | {
        "robotmodel." + ".".join(p.parent.relative_to(REPO / "robotmodel").parts)
        for p in (REPO / "robotmodel").rglob("__init__.py")
        if p.parent != REPO / "robotmodel"
    }
    listed = set(_config()["packages"])  # type: ignore[call-overload]
    assert on_disk <= listed, f"not in pyproject packages: {sorted(on_disk - listed)}"


def test_cli_and_models_install_under_robotmodel() -> None:
    mapping = _config()["package-dir"]
    assert mapping == {"robotmodel": "robotmodel", "robotmodel.cli": "cli", "robotmodel.robots": "urdf",
                       "robotmodel.examples": "examples"}
    import robotmodel.cli.main
    import robotmodel.robots

    assert robotmodel.cli.main.__file__.startswith(str(REPO / "cli"))
    assert robotmodel.robots.__file__.startswith(str(REPO / "urdf"))


def _declared(extra: str | None = None) -> set[str]:
    with (REPO / "pyproject.toml").open("rb") as f:
        project = tomllib.load(f)["project"]
    specs = project["dependencies"] if extra is None else project["optional-dependencies"][extra]
    return {re.split(r"[<>=!~\[; ]", spec, maxsplit=1)[0].lower().replace("_", "-") for spec in specs}


def _third_party_imports() -> dict[str, str]:
    """Top-level module -> first file importing it, for every import in the library and the CLI."""
    found: dict[str, str] = {}
    for folder in ("robotmodel", "cli"):
        for path in sorted((REPO / folder).rglob("*.py")):
            for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
                if isinstance(node, ast.Import):
                    names = [alias.name for alias in node.names]
                elif isinstance(node, ast.ImportFrom) and node.level == 0 and node.module:
                    names = [node.module]
                else:
                    continue
                for name in names:
                    top = name.split(".")[0]
                    if top not in sys.stdlib_module_names and top not in {"robotmodel", "__future__"}:
                        found.setdefault(top, str(path.relative_to(REPO)))
    return found


def test_every_imported_package_is_declared() -> None:
    distributions = importlib.metadata.packages_distributions()
    declared = _declared()
    missing = {}
    for module, where in _third_party_imports().items():
        names = {d.lower().replace("_", "-") for d in distributions.get(module, [module])}
        if module == "pinocchio":
            names.add("pin")  # a cmeel wheel: its module sits under cmeel.prefix, unmapped by importlib.metadata
        if not names & declared:
            missing[module] = (sorted(names), where)
    assert not missing, f"imported but not in [project] dependencies: {missing}"


def test_the_user_list_is_installed_by_pip_install() -> None:
    assert {"xacro", "yourdfpy", "pin", "trimesh", "meshcat", "numpy"} <= _declared()
    assert "pytest" in _declared("test")


def test_cli_is_thin_and_the_library_never_imports_it() -> None:
    """cli/ holds parsers and one library call per command: under 75 lines per command handler (issue
    18's bound, 1,500 lines for its 19 handlers; the CLI grows with its commands), no module over 150;
    nothing under robotmodel/ imports it (the library's programs are reachable without the CLI)."""
    texts = {p.name: p.read_text(encoding="utf-8") for p in sorted((REPO / "cli").glob("*.py"))}
    sizes = {name: len(text.splitlines()) for name, text in texts.items()}
    handlers = sum(text.count("set_defaults(func=") for text in texts.values())
    assert handlers >= 19
    assert sum(sizes.values()) < 75 * handlers, (handlers, sizes)
    assert {name: n for name, n in sizes.items() if n > 150} == {}
    importers = []
    for path in sorted((REPO / "robotmodel").rglob("*.py")):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            names = ([a.name for a in node.names] if isinstance(node, ast.Import)
                     else [node.module or ""] if isinstance(node, ast.ImportFrom) else [])
            if any(n == "robotmodel.cli" or n.startswith("robotmodel.cli.") for n in names):
                importers.append(str(path.relative_to(REPO)))
    assert importers == []
