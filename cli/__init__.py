"""robotmodel's command line, installed as ``robotmodel.cli``; a thin layer over the library."""
