"""robotmodel.spatial (being built)."""
