"""Map file formats: the ROS map_server YAML plus seal's semantic keys.
"""
