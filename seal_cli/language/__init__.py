"""The command language: words, tags, the grammar, clauses, roles, reference and grounding.

Imports frames; never planning, maps, sefm, sim, bench or cli.
"""
