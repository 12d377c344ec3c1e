"""What the robot sees: the sensor model, simulated detections, observation files.

Imports maps; never sefm, sim, bench or cli.
"""
