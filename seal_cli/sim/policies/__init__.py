"""Where a robot looks next: the search policies (SeFM and the baselines).
"""
