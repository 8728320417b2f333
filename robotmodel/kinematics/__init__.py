"""robotmodel.kinematics (being built)."""
