"""The two frame file formats: YAML and the ``.frame`` DSL, read with positions and written back.
"""
