"""Build Python message packages for real ROS 1 where Debian ships none (turtlesim, nav_msgs), as catkin would.

Run with Debian's /usr/bin/python3:  ros1_msggen.py OUTDIR

Debian 12 packages rospy, std_msgs and geometry_msgs but not turtlesim or nav_msgs. This
writes their .msg files (turtlesim/Pose, nav_msgs/Odometry, as those packages define them),
the .msg files of their dependencies taken from Debian's own generated classes, and runs
genpy's generator (Debian's /usr/lib/genpy/genmsg_py.py) over them: OUTDIR then holds
importable ``turtlesim.msg`` and ``nav_msgs.msg``, md5sums computed by genmsg itself.
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import geometry_msgs.msg
import std_msgs.msg

DEFINITIONS = {
    ("turtlesim", "Pose"): "float32 x\nfloat32 y\nfloat32 theta\n\nfloat32 linear_velocity\nfloat32 angular_velocity\n",
    ("nav_msgs", "Odometry"): "Header header\nstring child_frame_id\ngeometry_msgs/PoseWithCovariance pose\n"
                              "geometry_msgs/TwistWithCovariance twist\n",
}
DEPENDENCIES = [std_msgs.msg.Header, *(getattr(geometry_msgs.msg, name) for name in (
    "PoseWithCovariance", "TwistWithCovariance", "Pose", "Point", "Quaternion", "Twist", "Vector3"))]
GENERATOR = "/usr/lib/genpy/genmsg_py.py"


def own_text(cls: type) -> str:
    """A generated class's own definition: its full text up to the first dependency."""
    return cls._full_text.split("\n" + "=" * 76)[0]


def main() -> int:
    out = Path(sys.argv[1])
    src = out / "src"
    for cls in DEPENDENCIES:
        pkg, name = cls._type.split("/")
        (src / pkg / "msg").mkdir(parents=True, exist_ok=True)
        (src / pkg / "msg" / f"{name}.msg").write_text(own_text(cls))
    for (pkg, name), text in DEFINITIONS.items():
        (src / pkg / "msg").mkdir(parents=True, exist_ok=True)
        (src / pkg / "msg" / f"{name}.msg").write_text(text)
    includes = [f"-I{pkg}:{src / pkg / 'msg'}" for pkg in ("std_msgs", "geometry_msgs", "turtlesim", "nav_msgs")]
    for pkg in ("turtlesim", "nav_msgs"):
        dest = out / pkg / "msg"
        dest.mkdir(parents=True, exist_ok=True)
        (out / pkg / "__init__.py").write_text("")
        files = [str(p) for p in sorted((src / pkg / "msg").glob("*.msg"))]
        for file in files:
            subprocess.run([sys.executable, GENERATOR, "-p", pkg, "-o", str(dest), *includes, file], check=True)
        subprocess.run([sys.executable, GENERATOR, "--initpy", "-p", pkg, "-o", str(dest), *includes, *files],
                       check=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
