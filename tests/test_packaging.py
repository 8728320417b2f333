"""The install layout: every library subpackage is listed, cli/ and urdf/ map into robotmodel."""

from __future__ import annotations

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
    assert mapping == {"robotmodel": "robotmodel", "robotmodel.cli": "cli", "robotmodel.robots": "urdf"}
    import robotmodel.cli.main
    import robotmodel.robots

    assert robotmodel.cli.main.__file__.startswith(str(REPO / "cli"))
    assert robotmodel.robots.__file__.startswith(str(REPO / "urdf"))
