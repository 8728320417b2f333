"""Loggers under ``--ros-args --log-level``: run with robotmodel's rclpy, and (imports swapped) with the real one.

Every logger writes one line at each severity; the effective levels are printed on stdout.
The test compares what both print for the loggers named here.
"""

import sys

from robotmodel import rclpy
from robotmodel.rclpy.logging import get_logger
from robotmodel.rclpy.node import Node


def main():
    rclpy.init(args=sys.argv)
    node = Node("probe")
    loggers = [node.get_logger(), node.get_logger().get_child("child"), get_logger("other")]
    for logger in loggers:
        logger.debug("debug line")
        logger.info("info line")
        logger.warning("warn line")
        logger.error("error line")
        print(logger.name, int(logger.get_effective_level()))
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
