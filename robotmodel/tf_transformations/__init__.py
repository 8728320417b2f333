"""ROS's ``tf_transformations`` (ROS 1: ``tf.transformations``): same names, arguments and conventions.

Code written for it runs with the import changed::

    from robotmodel.tf_transformations import euler_from_quaternion, quaternion_from_euler

    q = quaternion_from_euler(0.0, 0.0, 1.57)   # roll, pitch, yaw -> (x, y, z, w)

Conventions, as in ROS: quaternions are (x, y, z, w); Euler functions take ``axes``, one
of the 24 sequences (``'sxyz'``, the default, is static x then y then z: URDF's roll,
pitch, yaw; ``'r...'`` are rotating-axis sequences) or its tuple encoding; matrices are
4x4 homogeneous and act on column vectors; ``quaternion_multiply(q1, q0)`` rotates by
``q0`` first. Implemented on :mod:`robotmodel.spatial`. Projection, clipping, shearing,
superimposition and the Arcball class are not provided; ``decompose_matrix`` takes
affine matrices only.
"""

from __future__ import annotations

from robotmodel.tf_transformations._axes import AXES
from robotmodel.tf_transformations._compose import compose_matrix, decompose_matrix
from robotmodel.tf_transformations._euler import (
    euler_from_matrix,
    euler_from_quaternion,
    euler_matrix,
    quaternion_from_euler,
)
from robotmodel.tf_transformations._matrix import (
    concatenate_matrices,
    identity_matrix,
    inverse_matrix,
    is_same_transform,
    random_vector,
    rotation_from_matrix,
    rotation_matrix,
    scale_matrix,
    translation_from_matrix,
    translation_matrix,
    unit_vector,
    vector_norm,
)
from robotmodel.tf_transformations._quaternion import (
    quaternion_about_axis,
    quaternion_conjugate,
    quaternion_from_matrix,
    quaternion_inverse,
    quaternion_matrix,
    quaternion_multiply,
    quaternion_slerp,
    random_quaternion,
    random_rotation_matrix,
)

__all__ = [
    "AXES",
    "compose_matrix",
    "concatenate_matrices",
    "decompose_matrix",
    "euler_from_matrix",
    "euler_from_quaternion",
    "euler_matrix",
    "identity_matrix",
    "inverse_matrix",
    "is_same_transform",
    "quaternion_about_axis",
    "quaternion_conjugate",
    "quaternion_from_euler",
    "quaternion_from_matrix",
    "quaternion_inverse",
    "quaternion_matrix",
    "quaternion_multiply",
    "quaternion_slerp",
    "random_quaternion",
    "random_rotation_matrix",
    "random_vector",
    "rotation_from_matrix",
    "rotation_matrix",
    "scale_matrix",
    "translation_from_matrix",
    "translation_matrix",
    "unit_vector",
    "vector_norm",
]
