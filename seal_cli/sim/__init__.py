"""The household simulator: the world, the agent and the search policies (it drives on :mod:`seal_cli.maps.navigation`).

Imports everything below it; never bench or cli.
"""
