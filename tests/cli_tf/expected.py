"""Expected texts shared by the TF tool tests."""

# tf2_echo for `static_transform_publisher 1 2 3 0.5 0.1 -1.0 foo bar` and `tf2_echo foo bar`, worked out
# by hand from tf2's setRPY, Matrix3x3 and getEulerYPR formulas (the project's tf2 reference, section 8.1).
EXPECTED_STATIC = """\
At time 0.0
- Translation: [1.000, 2.000, 3.000]
- Rotation: in Quaternion [-0.475, -0.076, 0.240, 0.843]
- Rotation: in RPY (radian) [-1.000, 0.100, 0.500]
- Rotation: in RPY (degree) [-57.296, 5.730, 28.648]
- Matrix:
  0.873 -0.333 -0.356  1.000
  0.477  0.434  0.764  2.000
 -0.100 -0.837  0.538  3.000
  0.000  0.000  0.000  1.000
"""
