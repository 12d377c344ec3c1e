"""Observers of a SeFM run: metrics, the Rerun recording, the PNG picture.
"""
