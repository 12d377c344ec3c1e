"""Search cost in a house with walls: ``python -m tests.apartment_paths [--seeds 5]``.

Runs every policy on a few commands on the shipped apartment (18 × 12 m, five rooms, walls, a
5 m sensor; the objects where ``maps/apartment.yaml`` puts them) and prints, per command and
policy, the mean path and how many runs were done; then the mean over the commands and the
ratios the ALFRED-2D targets name. SeFM and object-only run once per seed; coverage and the oracle
draw nothing at random. One house and one placement of its objects: an illustration of where the
targets stand at building scale, not a benchmark (about two minutes).
"""

from __future__ import annotations

import argparse
import statistics

import numpy as np

from seal_cli.frames.reading import load_library
from seal_cli.maps.formats.map_server import load_map
from seal_cli.pipeline import run_on_map
from seal_cli.resources import map_path
from seal_cli.sim.policies import make_policy

COMMANDS = ("stir the cup", "bring the apple to the bedroom", "put the spoon in the sink",
            "pick up the cup and put it on the dining table", "heat the apple")
POLICIES = ("sefm", "object_only", "coverage", "oracle")
RANDOM = frozenset({"sefm", "object_only"})


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seeds", type=int, default=5)
    args = parser.parse_args()
    library = load_library(None)
    apartment = load_map(map_path("apartment"))
    means: dict[str, list[float]] = {p: [] for p in POLICIES}
    for text in COMMANDS:
        for policy in POLICIES:
            seeds = range(args.seeds) if policy in RANDOM else range(1)
            paths, done = [], 0
            for seed in seeds:
                _, result = run_on_map(apartment, text, library, make_policy(policy), rng=np.random.default_rng(seed))
                paths.append(result.path_m)
                done += result.completed
            means[policy].append(statistics.mean(paths))
            print(f"{text:48s} {policy:12s} {statistics.mean(paths):6.2f} m  done {done}/{len(seeds)}", flush=True)
    mean = {p: statistics.mean(v) for p, v in means.items()}
    print("mean over the commands: " + ", ".join(f"{p} {m:.2f} m" for p, m in mean.items()))
    print(f"sefm / coverage {mean['sefm'] / mean['coverage']:.2f}, sefm / oracle {mean['sefm'] / mean['oracle']:.2f}")


if __name__ == "__main__":
    main()
