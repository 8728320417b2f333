"""``robotmodel demo``: a tour of the toolkit on the bundled robots."""

from __future__ import annotations

import argparse
from typing import Any


def register(sub: Any) -> None:
    """Add the ``demo`` subcommand."""
    parser: argparse.ArgumentParser = sub.add_parser("demo", help="run a short tour on the bundled robots")
    parser.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    """Run the tour."""
    print("robotmodel demo: (being built)")
    return 0
