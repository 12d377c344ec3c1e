"""The paper's Fig. 3 on the AWS small house, over many seeds: ``python -m tests.fig3_aws --seeds 10``.

For each room layout of :data:`seal_cli.bench.houses.AWS_LAYOUTS` and each start pose, prints what the
robot sees of the prior rooms, the masses the target itself gives Stir(cup) (integrated on the
free cells, without particles: the model's own answer), and the smallest and largest particle
estimates over the seeds of what Fig. 3 asks (``seal localize`` as a user runs it); then, along
:data:`~seal_cli.bench.houses.AWS_TRAJECTORY`, the farthest any object's or frame's best point ends
from its object. A hand-run benchmark (about a minute); the test suite runs three seeds.
"""

from __future__ import annotations

import argparse
import json
import tempfile
from pathlib import Path
from typing import Any

import numpy as np
from typer.testing import CliRunner

from seal_cli.bench.houses import AWS_OBJECTS, AWS_TRAJECTORY, aws_house
from seal_cli.cli import app
from seal_cli.cli.localize_cmd import _plan
from seal_cli.frames.library import Library
from seal_cli.frames.reading import load_library
from seal_cli.maps.formats.map_server import load_map
from seal_cli.maps.model import Map
from seal_cli.sefm.filter import SeFM
from seal_cli.sefm.potentials import GridKernelSums
from seal_cli.sensing.sensor import visible_region
from tests.conftest import DATA

FIG3 = ["grasp the cup", "grasp the spoon", "stir the cup"]
STARTS = [("wings", (1.0, 4.0, 0.0)), ("wings", (1.5, -4.0, 0.0)), ("wings", (-6.0, -3.5, 0.0)),
          ("wings", (0.0, 0.0, 0.0)), ("wings", (-1.5, 0.5, 0.0)),
          ("north_family", (0.0, 0.0, 0.0)), ("north_family", (1.0, 4.0, 0.0)), ("north_family", (-1.5, 0.5, 0.0)),
          ("north_family", (-6.0, -3.5, 0.0)),
          ("kitchen_diner", (1.0, 4.0, 0.0)), ("kitchen_diner", (-6.0, -3.5, 0.0)), ("kitchen_diner", (0.0, 0.0, 0.0))]


def seen(m: Map, pose: tuple[float, float, float]) -> dict[str, float]:
    """The share of each prior room's free space in view from the pose."""
    centres, rooms = m.free_centres, m.free_cell_room
    inside = visible_region(m, pose).contains(centres) & (np.hypot(*(centres - pose[:2]).T) <= m.sensor.range)
    return {r.name: float(inside[rooms == i].mean()) for i, r in enumerate(m.rooms)
            if r.name in ("kitchen", "bedroom", "family_room")}


def target_rooms(m: Map, library: Library, pose: tuple[float, float, float], holding: str | None) -> dict[str, float]:
    """Stir(cup)'s room masses from its target γ after one look from ``pose`` that sees nothing: the object
    beliefs are the priors times 1 − p·v on the free cells, the frames' beliefs their targets (iterated
    until the context has settled), all integrated on the free cells."""
    bindings, state = _plan(FIG3, library, holding, [], m)
    sefm = SeFM(m, bindings, state, np.random.default_rng(0))
    centres = m.free_centres
    v = visible_region(m, pose).contains(centres) & (np.hypot(*(centres - pose[:2]).T) <= m.sensor.range)
    p = min(m.sensor.p_detect, sefm.objects.model.max_p_detect)
    C, F = len(sefm.sources), len(bindings)
    kernel = GridKernelSums(C + F, m.bounds, sefm.config.sigma)
    weights = np.zeros((C + F, len(centres)))
    for row, source in enumerate(sefm.sources):
        prior = m.prior(source.key).weights if source.kind == "object" else np.ones(len(centres))
        weights[row] = prior * (1 - p * v) if source.kind == "object" and source.key != holding else prior
    terms = sefm.terms()
    grid = np.broadcast_to(centres, (F, len(centres), 2))
    gamma = np.ones((F, len(centres)))
    for _ in range(4):
        weights[C:] = gamma
        kernel.set(range(C + F), np.broadcast_to(centres, (C + F, len(centres), 2)),
                   weights / weights.sum(axis=1, keepdims=True))
        gamma = sefm.frames.gamma_of(terms, *sefm.frames.potentials(terms, kernel, grid))
    stir = next(i for i, b in enumerate(bindings) if b.frame.name == "Stir")
    mass = np.bincount(m.free_cell_room + 1, gamma[stir], minlength=len(m.rooms) + 1) / gamma[stir].sum()
    return {r.name: float(mass[i + 1]) for i, r in enumerate(m.rooms)}


def localize(path: Path, *args: str) -> dict[str, Any]:
    tasks = [a for t in FIG3 for a in ("--task", t)]
    result = CliRunner().invoke(app, ["localize", "--map", str(path), *tasks, *args, "--json"])
    assert result.exit_code == 0, result.output
    return dict(json.loads(result.stdout))


def stir(data: dict[str, Any]) -> dict[str, float]:
    return dict(next(f for f in data["frames"] if f["frame"] == "Stir")["rooms"])


def margin(rooms: dict[str, float]) -> float:
    """How far the bedroom is ahead of the next room (negative: behind)."""
    return rooms["bedroom"] - max(v for k, v in rooms.items() if k != "bedroom")


def start_row(folder: Path, library: Library, layout: str, pose: tuple[float, float, float],
              seeds: range) -> str:
    path = aws_house(folder, DATA, layout, pose)
    m = load_map(path)
    a, b = target_rooms(m, library, pose, None), target_rooms(m, library, pose, "spoon")
    runs = [(stir(localize(path, "--seed", str(s))), stir(localize(path, "--seed", str(s), "--holding", "spoon")))
            for s in seeds]
    spoon_rooms = [r["kitchen"] + r["bedroom"] for r, _ in runs]
    margins = [margin(r) for r, _ in runs]
    cup_rooms = [r["family_room"] + r["bedroom"] for _, r in runs]
    kitchen = [r["kitchen"] for _, r in runs]
    view = ", ".join(f"{k} {v:.0%}" for k, v in seen(m, pose).items() if v >= 0.005) or "none"
    return (f"| {layout} | {pose[0]:g}, {pose[1]:g} | {view} | {a['bedroom']:.2f} / {a['kitchen']:.2f} "
            f"({margin(a):+.3f}) | {min(spoon_rooms):.2f} | {min(margins):+.3f} … {max(margins):+.3f} | "
            f"{b['family_room'] + b['bedroom']:.2f} / {b['kitchen']:.3f} | {min(cup_rooms):.2f} | {max(kitchen):.3f} |")


def trajectory_row(folder: Path, layout: str, seeds: range) -> str:
    path = aws_house(folder, DATA, layout, AWS_TRAJECTORY[0])
    poses = folder / "path.yaml"
    poses.write_text("poses:\n" + "".join(f"  - [{x}, {y}]\n" for x, y in AWS_TRAJECTORY))
    truth = {o["class"]: np.array(o["at"]) for o in AWS_OBJECTS}
    worst = {"objects": 0.0, "Pick": 0.0, "Stir": 0.0}
    for s in seeds:
        for holding in (None, "spoon"):
            data = localize(path, "--seed", str(s), "--trajectory", str(poses), *(["--holding", holding] if holding
                                                                                   else []))
            for o in data["objects"]:
                if o["class"] != holding:
                    worst["objects"] = max(worst["objects"], float(np.hypot(*(o["best"] - truth[o["class"]]))))
            for f in data["frames"]:
                goal = ("cup" if holding else "spoon") if f["frame"] == "Stir" else f["elements"]["theme"]
                if goal != holding:
                    worst[f["frame"]] = max(worst[f["frame"]], float(np.hypot(*(f["best"] - truth[goal]))))
    return f"| {layout} | {worst['objects']:.2f} | {worst['Pick']:.2f} | {worst['Stir']:.2f} |"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seeds", type=int, default=10)
    seeds = range(parser.parse_args().seeds)
    library = load_library()
    with tempfile.TemporaryDirectory() as folder:
        print(f"Fig. 3 A/B, seeds 0–{seeds[-1]}: target = the model's own masses (bedroom / kitchen, margin of the "
              "bedroom over the next room); particles = min (… max) over the seeds")
        print("| layout | start | prior rooms in view | A target | A spoon rooms min | A bedroom margin | "
              "B target cup rooms / kitchen | B cup rooms min | B kitchen max |")
        print("|---|---|---|---|---|---|---|---|---|")
        for layout, pose in STARTS:
            print(start_row(Path(folder), library, layout, pose, seeds), flush=True)
        print(f"\nFig. 3 C/D along the trajectory, seeds 0–{seeds[-1]}, both hands: farthest best point from its "
              "object (m)")
        print("| layout | objects | Pick frames | Stir |")
        print("|---|---|---|---|")
        for layout in ("wings", "north_family", "kitchen_diner"):
            print(trajectory_row(Path(folder), layout, seeds), flush=True)


if __name__ == "__main__":
    main()
