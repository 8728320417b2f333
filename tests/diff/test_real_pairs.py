"""robotmodel diff on real pairs of example-robot-data that differ (two Pandas, two UR5s, Solo and Solo-12,
...): the report must list exactly the differences an independent comparison of the two XML files finds,
and the pose changes yourdfpy computes."""

from __future__ import annotations

from pathlib import Path

import pytest
from conftest import ERD_ROBOTS
from diff.pairs import PANDA, PANDA_COLLISION, PENDULUM, PENDULUM_CONTINUOUS, UR5, UR5_LIMITED, run_json
from diff.xmlref import check_report

PAIRS = {
    "panda-collision": (PANDA, PANDA_COLLISION),
    "ur5-joint-limited": (UR5, UR5_LIMITED),
    "double-pendulum-continuous": (PENDULUM, PENDULUM_CONTINUOUS),
    "solo-solo12": (ERD_ROBOTS / "solo_description/robots/solo.urdf", ERD_ROBOTS / "solo_description/robots/solo12.urdf"),
    "iris-simple": (ERD_ROBOTS / "iris_description/robots/iris.urdf", ERD_ROBOTS / "iris_description/robots/iris_simple.urdf"),
    "talos-corrected": (ERD_ROBOTS / "talos_data/robots/talos_reduced.urdf",
                        ERD_ROBOTS / "talos_data/robots/talos_reduced_corrected.urdf"),
    "talos-box": (ERD_ROBOTS / "talos_data/robots/talos_full_v2.urdf",
                  ERD_ROBOTS / "talos_data/robots/talos_full_v2_box.urdf"),
}


@pytest.mark.parametrize("pair", PAIRS, ids=list(PAIRS))
def test_real_pair_reports_exactly_the_xml_differences(tmp_path: Path, pair: str) -> None:
    old, new = PAIRS[pair]
    code, report = run_json(str(old), str(new), cwd=tmp_path)
    assert code == 1
    check_report(report, old.read_text(), new.read_text())


def test_known_differences_in_words(tmp_path: Path) -> None:
    """The two example-robot-data Pandas differ in collision geometry only: meshes became primitives."""
    code, report = run_json(str(PANDA), str(PANDA_COLLISION), cwd=tmp_path)
    assert code == 1
    assert report["joints"]["changed"] == [] and report["poses"] == []
    link0 = {c["field"]: c for c in next(x for x in report["links"]["changed"] if x["new"] == "panda_link0")["changes"]}
    assert link0["collision[0].geometry"]["old"] == {
        "type": "mesh", "filename": "package://example-robot-data/robots/panda_description/meshes/collision/link0.stl",
        "scale": [1.0, 1.0, 1.0]}
    assert link0["collision[0].geometry"]["new"] == {"type": "cylinder", "radius": 0.09, "length": 0.03}
    assert link0["collision[0].origin.xyz"]["new"] == [-75.0, 0.0, 60.0]
    assert link0["collision[0].origin.rpy"]["new"] == pytest.approx([0.0, 90.0, 0.0])
    assert link0["collision[1]"]["old"] is None
    assert link0["collision[1]"]["new"]["geometry"] == {"type": "sphere", "radius": 0.09}
    # UR5 against its joint-limited variant: ±2π became ±π on five joints (the elbow keeps ±π).
    code, report = run_json(str(UR5), str(UR5_LIMITED), cwd=tmp_path)
    limits = {c["new"]: {x["field"]: (x["old"], x["new"]) for x in c["changes"]} for c in report["joints"]["changed"]}
    assert set(limits) == {"shoulder_pan_joint", "shoulder_lift_joint", "wrist_1_joint", "wrist_2_joint",
                           "wrist_3_joint"}
    for fields in limits.values():
        assert fields == {"limit.lower": (-6.28318530718, -3.14159265359), "limit.upper": (6.28318530718, 3.14159265359)}
