"""The benchmarks: the task suites (ALFRED-2D, map suite), parsing, planning, perf and map-query timings.

May import anything but cli.
"""
