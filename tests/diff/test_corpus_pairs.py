"""robotmodel diff on real xacro packages of the corpus: variants of one description (other xacro arguments,
a tf_prefix, optional accessories) and related robots, checked against an independent comparison of the two
expansions' XML and yourdfpy's poses; a prefix must read as renames only."""

from __future__ import annotations

from pathlib import Path

import pytest
from diff.xmlref import check_report

from robotmodel.diff import diff_descriptions, diff_json
from robotmodel.model import load
from robotmodel.xacro import expand

UR = "Universal_Robots_ROS2_Description/ur_description/urdf/ur.urdf.xacro"
PAIRS = {
    "ur5-ur5e": ((UR, {"ur_type": "ur5", "name": "ur"}), (UR, {"ur_type": "ur5e", "name": "ur"})),
    "ur10e-ur16e": ((UR, {"ur_type": "ur10e", "name": "ur"}), (UR, {"ur_type": "ur16e", "name": "ur"})),
    "husky-realsense": (("husky/husky_description/urdf/husky.urdf.xacro", {}),
                        ("husky/husky_description/urdf/husky.urdf.xacro",
                         {"realsense_enabled": "1", "realsense_mount": "top_plate_link"})),
    "fr3-without-hand": (("franka_description/franka_description/robots/fr3/fr3.urdf.xacro", {}),
                         ("franka_description/franka_description/robots/fr3/fr3.urdf.xacro", {"hand": "false"})),
    "burger-waffle": (("turtlebot3/turtlebot3_description/urdf/turtlebot3_burger.urdf", {}),
                      ("turtlebot3/turtlebot3_description/urdf/turtlebot3_waffle.urdf", {})),
    "kr16-xacro-urdf": (("kuka_experimental/kuka_kr16_support/urdf/kr16_2.xacro", {}),
                        ("kuka_experimental/kuka_kr16_support/urdf/kr16_2.urdf", {})),
}


def _text(corpus: Path, path: str, args: dict[str, str]) -> str:
    source = corpus / path
    text = source.read_text(encoding="utf-8")
    # turtlebot3's .urdf files are xacro (${namespace}): expanded, as robotmodel.load does.
    return expand(source, args) if path.endswith(".xacro") or "xmlns:xacro" in text else text


@pytest.mark.parametrize("pair", PAIRS, ids=list(PAIRS))
def test_corpus_pair_reports_exactly_the_xml_differences(corpus: Path, pair: str) -> None:
    (old_path, old_args), (new_path, new_args) = PAIRS[pair]
    old = load(corpus / old_path, old_args)
    new = load(corpus / new_path, new_args)
    report = diff_json(diff_descriptions(old, new))
    check_report(report, _text(corpus, old_path, old_args), _text(corpus, new_path, new_args))
    if pair != "kr16-xacro-urdf":
        assert report["equal"] is False


@pytest.mark.parametrize(
    ("path", "args", "prefix"),
    [(UR, {"ur_type": "ur5e", "name": "ur"}, {"tf_prefix": "left_"}),
     ("turtlebot3/turtlebot3_description/urdf/turtlebot3_burger.urdf", {}, {"namespace": "tb3_0/"})],
    ids=["ur-tf_prefix", "turtlebot3-namespace"],
)
def test_prefix_is_renames_only(corpus: Path, path: str, args: dict[str, str], prefix: dict[str, str]) -> None:
    old = load(corpus / path, args)
    new = load(corpus / path, {**args, **prefix})
    report = diff_json(diff_descriptions(old, new))
    added = next(iter(prefix.values()))
    check_report(report, _text(corpus, path, args), _text(corpus, path, {**args, **prefix}),
                 rename=lambda name: added + name)
    new_links = {x.name for x in new.links}
    # Every link the prefix reaches (UR's 'world' stays), and every joint.
    assert sorted(r["old"] for r in report["links"]["renamed"]) == sorted(
        x.name for x in old.links if added + x.name in new_links)
    assert len(report["links"]["renamed"]) >= len(old.links) - 1
    assert len(report["joints"]["renamed"]) == len(old.joints)
    for section in ("links", "joints"):
        assert report[section]["added"] == report[section]["removed"] == report[section]["changed"] == []
    assert report["poses"] == []
