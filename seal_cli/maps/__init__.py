"""Annotated 2-D maps: the model, geometry, priors, file formats, drawing, and where a robot drives on them.

Imports frames (taxonomy); never language, sefm, sim, bench or cli.
"""
