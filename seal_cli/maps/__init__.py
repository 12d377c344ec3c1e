"""Annotated 2-D maps: the model, geometry, priors, file formats and drawing.

Imports frames (taxonomy); never language, sefm, sim, bench or cli.
"""
