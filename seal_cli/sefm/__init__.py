"""SeFM, Semantic Frame Mapping: object and frame beliefs, relations, potentials, resampling, modes,
and the observers that watch the filter.

Imports frames, planning, maps, sensing; never sim, bench or cli.
"""
