"""robotmodel.check (being built)."""
