"""``robotmodel tf-export --bag FILE SOURCE TARGET -o poses.csv [--rate HZ]``: a pose time series.

Writes TARGET's pose in SOURCE (as tf2_echo's lookup) over the recording: at the
recorded stamps of the frames between them, or every 1/HZ seconds with ``--rate``. CSV
columns ``stamp_ns,time_s,x,y,z,qx,qy,qz,qw``; Parquet when the name ends in ``.parquet``
(needs pyarrow). The program is :func:`robotmodel.recording.run_tf_export`.
"""

from __future__ import annotations

import argparse
from typing import Any

from robotmodel.cli._bag_args import add_bag_arguments

__all__ = ["register", "run"]


def register(sub: Any) -> None:
    """Add the ``tf-export`` subcommand."""
    parser: argparse.ArgumentParser = sub.add_parser(
        "tf-export", aliases=["tf_export"], help="write a frame pair's poses from a recording to CSV/Parquet",
        description="Write TARGET's pose in SOURCE over a recording (ROS 1 bag, ROS 2 bag, MCAP).",
    )
    add_bag_arguments(parser, required=True)
    parser.add_argument("source_frame", metavar="SOURCE")
    parser.add_argument("target_frame", metavar="TARGET")
    parser.add_argument("-o", "--output", required=True, metavar="FILE",
                        help="output .csv (or .parquet with pyarrow installed)")
    parser.add_argument("--rate", type=float, metavar="HZ", help="sample evenly at HZ (default: recorded stamps)")
    parser.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    """Load the recording, sample the pose, write the file."""
    from robotmodel.recording import run_tf_export

    return run_tf_export(args.bag, args.source_frame, args.target_frame, args.output, rate=args.rate, urdf=args.urdf,
                         progress=False if args.no_progress else None)
