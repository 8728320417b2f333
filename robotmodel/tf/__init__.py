"""robotmodel.tf (being built)."""
