"""The frame model and frame libraries: frames, taxonomy, primitive actions, the library index, its
file formats, reading and validation.

Imports errors, fileio, yamlnodes, resources, cache, names only; never language, planning, maps, sefm, sim, bench
or cli.
"""
