"""Parse URDF XML into a :class:`RobotDescription`, validating like urdfdom and more.

Messages reuse urdfdom's sentences where it has one, so a ROS user recognises them,
and name the element at fault. Beyond urdfdom, a description that would make a broken
tree (partial cycle, a link with two parents, a self-joint) or non-finite numbers is
rejected here, so every RobotDescription is a valid tree.
"""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET

from robotmodel.errors import URDFError, URDFParseError
from robotmodel.model._locate import locate
from robotmodel.model._numbers import num as _num
from robotmodel.model._numbers import vec as _vec
from robotmodel.model._numbers import vec3 as _vec3
from robotmodel.model._robot import RobotDescription
from robotmodel.model._types import (
    Box,
    Collision,
    Cylinder,
    Dynamics,
    Geometry,
    Inertia,
    Inertial,
    Joint,
    JointType,
    Limit,
    Link,
    Material,
    Mesh,
    Mimic,
    Pose,
    SafetyController,
    Sphere,
    Vec3,
    Visual,
)

__all__ = ["parse_urdf"]

_TYPES = {t.value: t for t in JointType}


def _quat_to_rpy(x: float, y: float, z: float, w: float, what: str) -> Vec3:
    scale = max(abs(x), abs(y), abs(z), abs(w))
    if scale == 0.0:
        raise URDFParseError(f"origin of {what}: quat_xyzw has zero norm")
    # spatial's kernels (imported here: only version 1.1+ files with quat_xyzw need NumPy);
    # scaled first so that a tiny quaternion's norm does not underflow.
    from robotmodel.spatial import matrix_to_rpy, quat_to_matrix

    q = (x / scale, y / scale, z / scale, w / scale)
    roll, pitch, yaw = (float(v) for v in matrix_to_rpy(quat_to_matrix(q)))
    return (roll, pitch, yaw)


def _pose(elem: ET.Element | None, what: str, version: tuple[int, int]) -> Pose:
    if elem is None:
        return Pose()
    xyz = _vec3(elem.get("xyz", "0 0 0"), f"malformed origin xyz of {what}")
    quat = elem.get("quat_xyzw")
    if quat is not None and version >= (1, 1):
        if elem.get("rpy") is not None:
            raise URDFParseError(f"origin of {what} has both rpy and quat_xyzw")
        qx, qy, qz, qw = _vec(quat, 4, f"malformed origin quat_xyzw of {what}")
        return Pose(xyz, _quat_to_rpy(qx, qy, qz, qw, what))
    return Pose(xyz, _vec3(elem.get("rpy", "0 0 0"), f"malformed origin rpy of {what}"))


def _geometry(elem: ET.Element | None, what: str) -> Geometry:
    shape = next(iter(elem), None) if elem is not None else None
    if shape is None:
        raise URDFParseError(f"{what}: geometry has no shape")
    tag = shape.tag
    if tag == "box":
        if "size" not in shape.attrib:
            raise URDFParseError(f"{what}: Box shape has no size attribute")
        return Box(_vec3(shape.attrib["size"], f"{what}: box size"))
    if tag == "cylinder":
        if "radius" not in shape.attrib or "length" not in shape.attrib:
            raise URDFParseError(f"{what}: Cylinder shape must have both length and radius attributes")
        return Cylinder(_num(shape.attrib["radius"], f"{what}: cylinder radius"),
                        _num(shape.attrib["length"], f"{what}: cylinder length"))
    if tag == "sphere":
        if "radius" not in shape.attrib:
            raise URDFParseError(f"{what}: Sphere shape must have a radius attribute")
        return Sphere(_num(shape.attrib["radius"], f"{what}: sphere radius"))
    if tag == "mesh":
        if not shape.get("filename"):
            raise URDFParseError(f"{what}: Mesh must contain a filename attribute")
        scale = _vec3(shape.get("scale", "1 1 1"), f"{what}: mesh scale")
        return Mesh(shape.attrib["filename"], scale)
    raise URDFParseError(f"{what}: unknown geometry type '{tag}'")


def _material(elem: ET.Element, what: str) -> Material:
    color = elem.find("color")
    rgba = None
    if color is not None:
        r, g, b, a = _vec(color.get("rgba", ""), 4, f"{what}: material color rgba")
        rgba = (r, g, b, a)
    texture = elem.find("texture")
    filename = texture.get("filename") if texture is not None else None
    return Material(elem.get("name", ""), rgba, filename)


def _inertial(elem: ET.Element | None, link: str, version: tuple[int, int]) -> Inertial | None:
    if elem is None:
        return None
    what = f"inertial of link [{link}]"
    mass_elem = elem.find("mass")
    if mass_elem is None or "value" not in mass_elem.attrib:
        raise URDFParseError(f"{what}: mass element must have a value attribute")
    mass = _num(mass_elem.attrib["value"], f"{what}: mass")
    ine = elem.find("inertia")
    if ine is None:
        raise URDFParseError(f"{what}: inertial element must have an inertia element")
    keys = ("ixx", "ixy", "ixz", "iyy", "iyz", "izz")
    missing = [k for k in keys if k not in ine.attrib]
    if missing:
        raise URDFParseError(f"{what}: inertia element must have {', '.join(missing)} attributes")
    values = [_num(ine.attrib[k], f"{what}: inertia {k}") for k in keys]
    return Inertial(mass, Inertia(*values), _pose(elem.find("origin"), what, version))


def _link(elem: ET.Element, version: tuple[int, int]) -> Link:
    name = elem.get("name")
    if not name:
        raise URDFParseError("No name given for the link.")
    visuals = []
    for i, v in enumerate(elem.findall("visual")):
        what = f"visual {i} of link [{name}]"
        mat = v.find("material")
        visuals.append(Visual(
            _geometry(v.find("geometry"), what), _pose(v.find("origin"), what, version),
            v.get("name"), _material(mat, what) if mat is not None else None,
        ))
    collisions = []
    for i, c in enumerate(elem.findall("collision")):
        what = f"collision {i} of link [{name}]"
        collisions.append(Collision(_geometry(c.find("geometry"), what),
                                    _pose(c.find("origin"), what, version), c.get("name")))
    return Link(name, tuple(visuals), tuple(collisions), _inertial(elem.find("inertial"), name, version))


def _limit(elem: ET.Element | None, name: str, jtype: JointType, version: tuple[int, int]) -> Limit | None:
    if elem is None:
        if jtype is JointType.REVOLUTE:
            raise URDFError(f"Joint [{name}] is of type REVOLUTE but it does not specify limits")
        if jtype is JointType.PRISMATIC:
            raise URDFError(f"Joint [{name}] is of type PRISMATIC without limits")
        return None
    for attr in ("effort", "velocity"):
        if attr not in elem.attrib:
            raise URDFParseError(f"joint [{name}]: limit has no {attr}")
    lower = elem.get("lower")
    upper = elem.get("upper")
    if version >= (1, 2) and jtype in (JointType.REVOLUTE, JointType.PRISMATIC) and (
        lower is None or upper is None
    ):
        raise URDFError(
            f"joint [{name}]: revolute and prismatic joints must have both lower and upper position "
            "limits specified in URDF version 1.2 or later"
        )
    what = f"limit of joint [{name}]"
    return Limit(
        _num(elem.attrib["effort"], what), _num(elem.attrib["velocity"], what),
        _num(lower, what) if lower is not None else None,
        _num(upper, what) if upper is not None else None,
    )


def _joint(elem: ET.Element, version: tuple[int, int]) -> Joint:
    name = elem.get("name")
    if not name:
        raise URDFParseError("unnamed joint found")
    type_text = elem.get("type")
    if not type_text:
        raise URDFParseError(f"joint [{name}] has no type, check to see if it's a reference.")
    if type_text not in _TYPES:
        raise URDFParseError(f"Joint [{name}] has no known type [{type_text}]")
    jtype = _TYPES[type_text]
    parent = elem.find("parent")
    child = elem.find("child")
    if parent is None or child is None or not parent.get("link") or not child.get("link"):
        raise URDFError(f"Joint [{name}] is missing a parent and/or child link specification.")
    axis: Vec3 = (1.0, 0.0, 0.0)
    axis_elem = elem.find("axis")
    # As urdfdom: fixed and floating joints have no axis; an <axis/> without xyz is zero.
    if axis_elem is not None and jtype not in (JointType.FIXED, JointType.FLOATING):
        axis = _vec3(axis_elem.get("xyz", "0 0 0"), f"Malformed axis element for joint [{name}]")
        if axis == (0.0, 0.0, 0.0):
            raise URDFError(f"joint [{name}] has a zero axis")
    mimic = None
    mim = elem.find("mimic")
    if mim is not None:
        if not mim.get("joint"):
            raise URDFParseError(f"mimic element of joint [{name}] has no joint attribute")
        mimic = Mimic(mim.attrib["joint"], _num(mim.get("multiplier", "1"), f"mimic of joint [{name}]"),
                      _num(mim.get("offset", "0"), f"mimic of joint [{name}]"))
    dyn = elem.find("dynamics")
    dynamics = None
    if dyn is not None:
        if dyn.get("damping") is None and dyn.get("friction") is None:
            raise URDFParseError(f"dynamics of joint [{name}]: joint dynamics element specified with no "
                                 "damping and no friction")
        dynamics = Dynamics(_num(dyn.get("damping", "0"), f"dynamics of joint [{name}]"),
                            _num(dyn.get("friction", "0"), f"dynamics of joint [{name}]"))
    sc = elem.find("safety_controller")
    safety = None
    if sc is not None:
        what = f"safety_controller of joint [{name}]"
        if "k_velocity" not in sc.attrib:
            raise URDFParseError(f"{what}: no k_velocity")
        safety = SafetyController(
            _num(sc.attrib["k_velocity"], what), _num(sc.get("k_position", "0"), what),
            _num(sc.get("soft_lower_limit", "0"), what), _num(sc.get("soft_upper_limit", "0"), what),
        )
    return Joint(
        name, jtype, parent.attrib["link"], child.attrib["link"],
        _pose(elem.find("origin"), f"joint [{name}]", version), axis,
        _limit(elem.find("limit"), name, jtype, version), mimic, dynamics, safety,
    )


def _version(robot: ET.Element) -> tuple[int, int]:
    text = robot.get("version")
    if text is None:
        return (1, 0)
    major, dot, minor = text.partition(".")
    if not dot or "." in minor:
        raise URDFParseError("The version attribute should be in the form 'x.y'")
    if not (major.lstrip("-").isdigit() and minor.isdigit()):
        raise URDFParseError("Version attribute is not an integer")
    version = (int(major), int(minor))
    if version[0] < 0:
        raise URDFParseError("Version number must be positive")
    if not (1, 0) <= version <= (1, 2):
        raise URDFParseError(
            "Invalid 'version' specified; versions from 1.0 upto 1.2 are currently supported"
        )
    return version


def parse_urdf(text: str | bytes, *, source: str | None = None) -> RobotDescription:
    """Parse URDF XML into a validated :class:`RobotDescription`.

    ``text`` is a str, or the bytes of a file: then the XML declaration's encoding is
    honoured (UTF-8 without one), as an XML parser must. ``source`` names the file in
    error messages, which also give the offending element's line when it can be found.
    Raises :class:`URDFParseError` for malformed XML or elements and :class:`URDFError`
    for an invalid robot.
    """
    if isinstance(text, bytes):
        text = _decode(text, source or "<string>")
    return parse_located(text, source=source, original=text)


_DECLARED = re.compile(rb"""^<\?xml[^>]*?encoding\s*=\s*["']([A-Za-z0-9._-]+)["']""")
_BOMS = ((b"\xef\xbb\xbf", "utf-8-sig"), (b"\xff\xfe", "utf-16"), (b"\xfe\xff", "utf-16"))


def _decode(data: bytes, label: str) -> str:
    """The text of an XML document's bytes: its byte-order mark, else its declaration, else UTF-8.

    Decoded with Python's codecs rather than expat's, which knows only a handful of
    encodings (not UTF-16LE by that name, nor most single-byte code pages).
    """
    encoding = next((name for bom, name in _BOMS if data.startswith(bom)), None)
    if encoding is None:
        declared = _DECLARED.match(data)
        if declared is None and data[:2] in (b"<\x00", b"\x00<"):
            encoding = "utf-16-le" if data[0] == 0x3C else "utf-16-be"
        else:
            encoding = declared.group(1).decode("ascii") if declared else "utf-8"
    try:
        return data.decode(encoding).lstrip("\ufeff")
    except LookupError:
        raise URDFParseError(f"{label}: malformed XML: unknown encoding '{encoding}'") from None
    except UnicodeDecodeError as exc:
        raise URDFParseError(f"{label}: malformed XML: not valid {encoding} at byte {exc.start}") from None


def parse_located(text: str, *, source: str | None, original: str) -> RobotDescription:
    """:func:`parse_urdf`, with error lines looked up in ``original`` (the pre-xacro text)."""
    label = source or "<string>"
    if not text.strip("\ufeff \t\r\n"):
        raise URDFParseError(f"{label}: malformed XML: empty document (XML_ERROR_EMPTY_DOCUMENT)")
    try:
        robot = ET.fromstring(text)
    except ET.ParseError as exc:
        raise URDFParseError(f"{label}: malformed XML: {exc}") from None
    if robot.tag.startswith("{"):
        # tinyxml (urdfdom) ignores namespaces, so <robot xmlns="..."> is a robot.
        namespace = robot.tag[: robot.tag.index("}") + 1]
        for elem in robot.iter():
            if isinstance(elem.tag, str) and elem.tag.startswith(namespace):
                elem.tag = elem.tag[len(namespace) :]
    try:
        return _robot(robot, text, source)
    except URDFError as exc:
        line = locate(original, str(exc))
        where = f"{label}:{line}" if line is not None else label
        raise type(exc)(f"{where}: {exc}") from None


def _robot(robot: ET.Element, text: str, source: str | None) -> RobotDescription:
    if robot.tag != "robot":
        raise URDFParseError("Could not find the 'robot' element in the xml file")
    version = _version(robot)
    name = robot.get("name")
    if not name:
        raise URDFParseError("No name given for the robot.")
    materials: dict[str, Material] = {}
    for elem in robot.findall("material"):
        mat = _material(elem, f"material [{elem.get('name', '')}]")
        if not mat.name:
            raise URDFParseError("material without a name")
        if mat.name in materials:
            raise URDFError(f"material '{mat.name}' is not unique.")
        materials[mat.name] = mat
    links: dict[str, Link] = {}
    for elem in robot.findall("link"):
        link = _link(elem, version)
        if link.name in links:
            raise URDFError(f"link '{link.name}' is not unique.")
        links[link.name] = link
    if not links:
        raise URDFError("No link elements found in urdf file")
    joints: dict[str, Joint] = {}
    for elem in robot.findall("joint"):
        joint = _joint(elem, version)
        if joint.name in joints:
            raise URDFError(f"joint '{joint.name}' is not unique.")
        joints[joint.name] = joint
    # Construction checks the tree (and everything else again, cheaply).
    desc = RobotDescription(name, tuple(links.values()), tuple(joints.values()), tuple(materials.values()),
                            source)
    # Provenance: set after construction, as it is no constructor argument (see RobotDescription).
    object.__setattr__(desc, "source_text", text)
    return desc
