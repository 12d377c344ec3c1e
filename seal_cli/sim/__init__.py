"""The household simulator: the world, navigation, the agent and the search policies.

Imports everything below it; never bench or cli.
"""
