"""Planning: grounded state, the problem a command poses, A* search, the plan, PDDL export.

Imports frames and language; never sefm, sim, bench or cli.
"""
