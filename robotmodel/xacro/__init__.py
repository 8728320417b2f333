"""robotmodel.xacro (being built)."""
