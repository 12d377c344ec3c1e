"""Inputs several rounds of ``seal bench reliability``'s hostile cases start from: a small ALFRED-2D data folder, a
researcher's own ROS map, a small bag. Their own module, so that a round's module (:mod:`~seal_cli.bench.
reliability_hostile31`) takes them without importing :mod:`~seal_cli.bench.reliability_attacker`, which imports the
rounds' modules (the two made an import cycle, ``tests/test_imports.py``)."""

from __future__ import annotations

import numpy as np

__all__ = ["alfred2d_data", "robot_map", "sample_bag"]


def alfred2d_data(plan: dict[str, object] | None = None, trial: dict[str, object] | list[object] | None = None
                  ) -> tuple[tuple[str, bytes], ...]:
    """A small ALFRED-2D data folder ``d/`` (one 2 m × 2 m kitchen, a counter with an apple, a fridge; one trial
    that puts the apple in the fridge, in both splits) with the floor plan's and the trial's keys replaced by
    ``plan``'s and ``trial``'s (a list for the trial replaces it whole): it runs as it is."""
    import json

    cells = [[x * 0.25, z * 0.25] for x in range(-4, 5) for z in range(-4, 5)]
    counter, apple = "CounterTop|+01.20|+00.90|+00.00", "Apple|+01.20|+00.95|+00.00"
    floor = {"scene_type": "kitchen", "bounds": [-1.5, -1.5, 1.5, 1.5], "reachable": cells,
             "object_types": ["Apple", "CounterTop", "Fridge"],
             "receptacles": [{"id": counter, "class": "CounterTop", "position": [1.2, 0.9, 0.0], "openable": False,
                              "receptacle": True, "interaction_pose": [0.75, 0.0, 90, 30]},
                             {"id": "Fridge|-01.20|+00.00|+00.00", "class": "Fridge", "position": [-1.2, 0.0, 0.0],
                              "openable": True, "receptacle": True, "interaction_pose": None}], **(plan or {})}
    base = {"task_id": "trial_1", "task_dir": "pick_and_place_simple-Apple-None-Fridge-1", "split": "valid_seen",
            "floor_plan": "FloorPlan1", "scene_type": "kitchen",
            "task": {"type": "pick_and_place_simple", "object": "Apple", "sliced": False, "mrecep": None,
                     "receptacle": "Fridge", "toggle": None},
            "goals": ["put the apple in the fridge"], "agent_start": [0.0, 0.0, 90],
            "objects": [{"id": apple, "class": "Apple", "position": [1.2, 0.95, 0.0], "parent_guess": 0}],
            "expert": {"high_pddl": [{"action": "PickupObject", "object_id": apple, "from_receptacle_id": counter}],
                       "path_length_m": 3.0}}
    one: object = trial if isinstance(trial, list) else {**base, **(trial or {})}
    plans = {"movable_classes": ["Apple"], "floor_plans": {"FloorPlan1": floor}}
    line = (json.dumps(one) + "\n").encode()
    return (("d/floorplans.json", json.dumps(plans).encode()), ("d/trials_valid_seen.jsonl", line),
            ("d/trials_train.jsonl", line))


def sample_bag() -> bytes | None:
    """The bytes of a small MCAP bag of a robot in the apartment (20 scans), or None without the ros extra."""
    try:
        import rosbags  # noqa: F401
    except ImportError:
        return None
    import tempfile
    from pathlib import Path

    from seal_cli.bench.ros import write_run
    from seal_cli.maps.formats.map_server import load_map
    from seal_cli.resources import map_path

    with tempfile.TemporaryDirectory() as folder:
        write_run(Path(folder) / "run.mcap", load_map(map_path("apartment")), 20, 5, np.random.default_rng(0))
        return (Path(folder) / "run.mcap").read_bytes()


def robot_map(rooms: str = "") -> tuple[tuple[str, bytes], tuple[str, bytes]]:
    """A researcher's own ROS map as ``map_saver`` writes it (its six lines, six decimal places, a trinary P5 image of
    a 10 m × 10 m house at 5 cm: walls 0, free 254, unknown 205 around it, a wall between two rooms with a door), the
    rooms added by hand below its lines (``rooms``: the whole ``rooms:`` block; default a kitchen and a hall)."""
    cells = np.full((200, 200), 205, dtype=np.uint8)
    cells[20:180, 20:180] = 254
    cells[20:180, [20, 179]] = 0
    cells[[20, 179], 20:180] = 0
    cells[20:180, 100] = 0
    cells[90:110, 100] = 254  # the door
    image = b"P5\n200 200\n255\n" + cells.tobytes()
    head = (b"image: map.pgm\nmode: trinary\nresolution: 0.050000\norigin: [-5.000000, -5.000000, 0.000000]\n"
            b"negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.25\n\n")
    added = rooms or ("name: lab\nrooms:\n  - {name: kitchen, box: [-3.9, -3.9, -0.1, 3.9]}\n"
                      "  - {name: hall, box: [0.1, -3.9, 3.9, 3.9]}\nplaces:\n"
                      "  - {name: table_1, class: table, at: [-2, 0]}\nrobot: {pose: [2, 0, 0]}\n")
    return ("m.yaml", head + added.encode()), ("map.pgm", image)
