"""Joint states recorded without /tf become TF through the kinematics (URDF given or recorded)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from handfk import HandFK
from recording.bagfiles import NS, Msg, write
from recording.test_load import mat

from robotmodel.errors import RecordingError
from robotmodel.recording import load_recording

T0 = 1_700_000_000 * NS

URDF = """<?xml version="1.0"?>
<robot name="recorded">
  <link name="base"/><link name="upper"/><link name="slider"/><link name="finger"/><link name="tool"/>
  <joint name="shoulder" type="revolute"><parent link="base"/><child link="upper"/>
    <origin xyz="0 0 0.5" rpy="0.1 0 0"/><axis xyz="0 1 0"/><limit lower="-3" upper="3" effort="1" velocity="1"/>
  </joint>
  <joint name="extend" type="prismatic"><parent link="upper"/><child link="slider"/>
    <origin xyz="0.3 0 0"/><axis xyz="1 0 0"/><limit lower="0" upper="1" effort="1" velocity="1"/></joint>
  <joint name="finger_joint" type="revolute"><parent link="slider"/><child link="finger"/>
    <origin xyz="0.1 0 0"/><axis xyz="0 0 1"/><limit lower="-3" upper="3" effort="1" velocity="1"/>
    <mimic joint="shoulder" multiplier="-2" offset="0.1"/></joint>
  <joint name="tool_mount" type="fixed"><parent link="finger"/><child link="tool"/>
    <origin xyz="0.05 0 0" rpy="0 0 1.5707963267948966"/></joint>
</robot>
"""


def states(n: int = 25) -> list[tuple[int, dict[str, float]]]:
    return [(T0 + k * 20_000_000, {"shoulder": 0.8 * math.sin(0.3 * k), "extend": 0.02 * k}) for k in range(n)]


def recording(with_description: bool) -> list[Msg]:
    msgs = [Msg("/robot_description", T0 - NS, "str", URDF)] if with_description else []
    for t, values in states():
        msgs.append(Msg("/joint_states", t + 500, "js", (t, list(values), list(values.values()))))
    return msgs


@pytest.mark.parametrize("fmt", ["ros1", "mcap", "db3_folder"])
def test_recorded_description_gives_fk_at_recorded_stamps(tmp_path, fmt):
    path = write(tmp_path / "js", fmt, recording(with_description=True))
    loaded = load_recording(path, progress=False)
    assert loaded.from_joint_states and loaded.robot_description == URDF
    assert (loaded.start_ns, loaded.end_ns) == (states()[0][0], states()[-1][0])
    fk = HandFK(URDF)
    for t, values in states():
        want = fk.poses(values)
        for link in ("upper", "slider", "finger", "tool"):
            pose, used = loaded.buffer.lookup_ns("base", link, t)
            assert used == t
            np.testing.assert_allclose(mat(pose), want[link], atol=1e-12, err_msg=f"{link} at {t}")


def test_urdf_given_when_none_recorded(tmp_path):
    path = write(tmp_path / "js", "mcap", recording(with_description=False))
    urdf = tmp_path / "robot.urdf"
    urdf.write_text(URDF)
    loaded = load_recording(path, robot=urdf, progress=False)
    t, values = states()[7]
    pose, _ = loaded.buffer.lookup_ns("base", "tool", t)
    np.testing.assert_allclose(mat(pose), HandFK(URDF).poses(values)["tool"], atol=1e-12)


def test_no_robot_is_one_line_error(tmp_path):
    path = write(tmp_path / "js", "mcap", recording(with_description=False))
    with pytest.raises(RecordingError, match="joint states without /tf need the robot"):
        load_recording(path, progress=False)


def test_tf_present_means_joint_states_are_not_converted(tmp_path):
    msgs = [*recording(with_description=True), Msg("/tf", T0, "tf", [("world", "base", T0, (0, 0, 0, 0, 0, 0, 1.0))])]
    loaded = load_recording(write(tmp_path / "both", "mcap", msgs), progress=False)
    assert not loaded.from_joint_states
    assert sorted(loaded.buffer.frames()) == ["base"]
