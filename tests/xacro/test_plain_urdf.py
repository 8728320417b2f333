"""The plain-URDF rule: a document that is not xacro is parsed as check_urdf reads it, without xacro.

Rule: a document with a ``xacro:`` element or attribute is xacro; else one holding ``$(`` or ``${``
is xacro, except a ``*.urdf`` file not declaring the xacro namespace; else it is URDF.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest
from conftest import CHECK_URDF_BIN, ERD_ROBOTS, urdfdom_env
from robotmodel.cli.main import main

import robotmodel
from robotmodel.model import load

XACRO_NS = 'xmlns:xacro="http://www.ros.org/wiki/xacro"'
LITERAL = '<robot name="$(env HOME)"><link name="a${1+1}"/></robot>\n'


def test_plain_urdf_file_keeps_dollar_text_literal_as_check_urdf(tmp_path: Path,
                                                                  capsys: pytest.CaptureFixture[str]) -> None:
    path = tmp_path / "literal.urdf"
    path.write_text(LITERAL)
    desc = load(path)
    assert desc.name == "$(env HOME)" and desc.root == "a${1+1}"
    assert main(["check-urdf", str(path)]) == 0
    reference = subprocess.run([str(CHECK_URDF_BIN), str(path)], capture_output=True, text=True,
                               env=urdfdom_env(), check=True).stdout
    assert capsys.readouterr().out == reference


def test_xacro_namespace_or_other_names_still_expand(tmp_path: Path) -> None:
    as_xacro = tmp_path / "literal.urdf.xacro"
    as_xacro.write_text(LITERAL.replace("$(env HOME)", "$(env RM_PLAIN_TEST)"))
    os.environ["RM_PLAIN_TEST"] = "expanded"
    try:
        assert load(as_xacro).name == "expanded"
        assert load(as_xacro.read_text()).name == "expanded"  # text: $( means xacro
        with_ns = tmp_path / "ns.urdf"
        with_ns.write_text(f'<robot {XACRO_NS} name="$(env RM_PLAIN_TEST)"><link name="a${{1+1}}"/></robot>')
        desc = load(with_ns)
        assert (desc.name, desc.root) == ("expanded", "a2")
        uses_tags = tmp_path / "tags.urdf"
        uses_tags.write_text(f'<robot {XACRO_NS} name="r"><xacro:property name="n" value="b"/>'
                             '<link name="${n}"/></robot>')
        assert load(uses_tags).root == "b"
    finally:
        del os.environ["RM_PLAIN_TEST"]


def test_plain_urdf_is_parsed_without_the_xacro_child_process(tmp_path: Path) -> None:
    # An audit hook sees every process start; none may happen for a plain URDF, as file or text.
    panda = ERD_ROBOTS / "panda_description/urdf/panda.urdf"
    code = f"""
import sys
started = []
sys.addaudithook(lambda event, args: started.append(args) if event == "subprocess.Popen" else None)
import robotmodel
text = open({str(panda)!r}).read()
assert robotmodel.load({str(panda)!r}).name == "panda"
assert robotmodel.load(text).name == "panda"
print(len(started), "xacro" in sys.modules)
"""
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.split() == ["0", "False"]


def test_top_level_load_is_the_model_load() -> None:
    assert robotmodel.load is load
