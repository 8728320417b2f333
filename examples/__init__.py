"""Runnable examples, installed as ``robotmodel.examples``: ``python -m robotmodel.examples.NAME``.

Each is also a plain script (``python examples/NAME.py``). ``robotmodel demo`` runs the
odometry pair (``robot_controller``, ``sensor_simulator``) from here.
"""
