"""``seal run --rrd``: the same scene as ``seal localize --rrd`` (map image, class colours, layout), read back."""

from __future__ import annotations

from collections import defaultdict
from datetime import datetime
from pathlib import Path
from typing import Any

import pytest
from typer.testing import CliRunner

from seal_cli.cli import app

rr = pytest.importorskip("rerun")


def entities(path: Path, store: Any = None) -> dict[str, list[dict[str, Any]]]:
    out: dict[str, list[dict[str, Any]]] = defaultdict(list)
    for chunk in rr.chunk.RrdReader(str(path)).stream(store=store).to_chunks():
        batch = chunk.to_record_batch()
        table = batch.select([n for n in batch.schema.names if n not in ("log_time", "log_tick")]).to_pydict()
        for i in range(chunk.num_rows):
            out[str(chunk.entity_path)].append({k: v[i] for k, v in table.items()})
    return out


def test_run_recording_shares_the_localize_scene(tmp_path: Path) -> None:
    rrd = tmp_path / "run.rrd"
    result = CliRunner().invoke(app, ["run", "--map", "apartment", "stir the cup", "--rrd", str(rrd),
                                      "--particles", "100"])
    assert result.exit_code == 0, result.output
    logged = entities(rrd)
    (occupancy,) = logged["/map/occupancy"]
    assert occupancy["EncodedImage:media_type"] == ["image/png"]
    (context,) = logged["/"]
    labels = [c["class_description"]["info"]["label"] for c in context["AnnotationContext:context"][0]]
    assert "stir_cup_spoon" in labels and "spoon" in labels
    ids = {c["class_description"]["info"]["label"]: c["class_id"] for c in context["AnnotationContext:context"][0]}
    objects = logged["/objects/particles"]  # one entity for every class, told apart by class ids
    assert objects and all(set(r["Points2D:class_ids"]) <= {ids["spoon"], ids["cup"]} for r in objects)
    assert any(ids["spoon"] in r["Points2D:class_ids"] for r in objects)
    assert all(len(r["Points2D:class_ids"]) == len(r["Points2D:positions"]) for r in objects)
    frames = logged["/frames/particles"]  # the frame at hand, and the commanded frame it serves
    assert {ids["pick_spoon"], ids["stir_cup_spoon"]} <= {c for r in frames for c in r["Points2D:class_ids"]}
    assert not [e for e in logged if e.startswith(("/objects/", "/frames/", "/observations/", "/commanded"))
                and e not in ("/objects/particles", "/frames/particles")]
    seen = logged["/observations"]
    assert {"spoon", "cup"} <= {label for r in seen for label in (r["Points2D:labels"] or [])}
    assert logged["/robot/log"] and logged["/metrics/path_m"][-1]["Scalars:scalars"][0] > 0
    rooms = logged["/metrics/rooms/stir_cup_spoon"]
    assert all(sum(r["Scalars:scalars"]) == pytest.approx(1.0) for r in rooms)
    assert all(name.startswith("stir_cup_spoon: ") for name in rooms[0]["SeriesLines:names"])
    assert all(r["SeriesLines:names"] is None for r in rooms[1:])  # the names once, with the first values
    chunks = list(rr.chunk.RrdReader(str(rrd)).stream().to_chunks())
    assert len(chunks) == len({str(c.entity_path) for c in chunks})  # one chunk per entity, metrics included
    assert not rrd.read_bytes().endswith(b"RRF2FOOT\x01\x00\x00\x00")  # rerun's footer trailer
    (blueprint,) = rr.chunk.RrdReader(str(rrd)).blueprints()
    names = {r["ViewBlueprint:display_name"][0] for found in entities(rrd, blueprint).values() for r in found
             if "ViewBlueprint:display_name" in r}
    assert {"map apartment", "path (m)", "what the robot did"} <= names


def test_the_png_labels_where_a_go_ended_as_well_as_each_action(library: Any) -> None:
    """A frame that only drives (Go) is labelled where it ended, with the drive's line; every action
    where it was done: "go to the bedroom and tell Ben the time" is three labels, in order."""
    import numpy as np

    from seal_cli import pipeline
    from seal_cli.maps.formats.map_server import load_map
    from seal_cli.sim.policies import make_policy
    from seal_cli.sim.record import _acts

    apartment = load_map("apartment")
    agent, result = pipeline.run_on_map(apartment, "go to the bedroom and tell Ben the time", library,
                                        make_policy("oracle"), rng=np.random.default_rng(0),
                                        clock=datetime(2026, 12, 2, 9, 0))
    assert result.completed
    labels = [text for _, text in _acts(agent.records)]
    assert labels[0].startswith("goes to the bedroom") and not labels[0].endswith(" m)")
    assert labels[1:] == ["is with Ben", 'said "the time is 09:00"']
    bedroom = apartment.room("bedroom")
    assert all(bedroom.contains([pose[:2]])[0] for pose, _ in _acts(agent.records))
    asked, counted = pipeline.run_on_map(apartment, "how many cups are in the family room?", library,
                                         make_policy("oracle"), rng=np.random.default_rng(0))
    assert [text for _, text in _acts(asked.records)] == [f"answer: {counted.answer}"]   # said once
    state, _ = pipeline.run_on_map(apartment, "is the fridge open?", library, make_policy("oracle"),
                                   rng=np.random.default_rng(0))
    assert [text for _, text in _acts(state.records)] == ["answer: no: fridge_1 is closed (as the map has it)"]
    peeked, _ = pipeline.run_on_map(apartment, "how many cups are in the kitchen?", library, make_policy("sefm", 50),
                                    rng=np.random.default_rng(0))
    labels = [text for _, text in _acts(peeked.records)]      # opened, looked in, closed: one label, not two
    assert labels[:2] == ["looked into fridge_1; inside: apple_1", "looked into microwave_1; it is empty"]


def test_the_png_legend_names_every_mark_and_the_end_is_drawn_over_the_last_action(library: Any) -> None:
    """The red stars (where things truly are), the green diamonds, the people, the start and the end are all
    in the legend; the end's square is hollow and above the last action's diamond, so both show."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    from seal_cli import pipeline
    from seal_cli.maps.formats.map_server import load_map
    from seal_cli.sim.policies import make_policy
    from seal_cli.sim.record import _draw_run

    agent, result = pipeline.run_on_map(load_map("apartment"), "bring me the spoon", library, make_policy("oracle"),
                                        rng=np.random.default_rng(0))
    fig, ax = plt.subplots()
    try:
        _draw_run(ax, agent)
        handles, labels = ax.get_legend_handles_labels()
        assert {"start", "end", "where it acted (numbered)", "things, where they are at the end",
                "a moved thing, where it was at the start", "people"} <= set(labels) and len(labels) == len(set(labels))
        assert [t for t in labels if t.startswith("step ")] == ["step 1: Pick(theme=spoon_1)",   # e2e24: leg by leg
                                                               "step 2: Bring(theme=spoon_1, recipient=me)"]
        # (e2e26: each step names what the robot handled in it, as the narration does once it has chosen)
        spoon = agent.started["spoon_1"]       # the spoon moved: a hollow star where it was, a full one where it ended
        assert tuple(handles[labels.index("a moved thing, where it was at the start")].get_xydata()[0]) == spoon
        ends = [tuple(line.get_xydata()[0]) for line in ax.get_lines() if line.get_marker() == "*"
                and line.get_markerfacecolor() != "none"]
        assert agent.world.position("spoon_1") in ends and spoon not in ends
        end = handles[labels.index("end")]
        acted = handles[labels.index("where it acted (numbered)")]
        assert end.get_zorder() > acted.get_zorder() and end.get_markerfacecolor() == "none"
        assert tuple(end.get_xydata()[-1]) == tuple(agent.world.robot.trajectory[-1])
    finally:
        plt.close(fig)


def test_the_png_marks_each_view_the_search_stopped_at_as_the_narration_says_it(library: Any) -> None:
    """search27: the narration's "goes to look" lines ("looks for spoon: bedroom: ...") had no mark on the picture, so
    a reader could not find where each look was; each is a hollow circle where that drive ended, and only those."""
    import dataclasses

    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    from seal_cli import pipeline
    from seal_cli.bench.houses import cottage
    from seal_cli.maps.model import ObjectTruth, Robot
    from seal_cli.sim.policies import make_policy
    from seal_cli.sim.record import _draw_run

    world = dataclasses.replace(cottage(), objects=(ObjectTruth("spoon", (12.5, 8.5)), ObjectTruth("cup", (2.0, 7.0))),
                                robot=Robot((7.5, 4.5, 0.0)))
    agent, result = pipeline.run_on_map(world, "stir the cup", library, make_policy("sefm", 100),
                                        rng=np.random.default_rng(0))
    assert result.completed, result.reason
    went = [r.pose[:2] for r in agent.records if r.kind == "go" and r.text.startswith("goes to look")]
    assert went                                  # the spoon is out of sight from the hall: the search looked
    fig, ax = plt.subplots()
    try:
        _draw_run(ax, agent)
        handles, labels = ax.get_legend_handles_labels()
        looks = handles[labels.index("where it stopped to look")]
        assert [tuple(p) for p in looks.get_xydata()] == [tuple(p) for p in went]
        assert looks.get_markerfacecolor() == "white" and looks.get_marker() == "o"
    finally:
        plt.close(fig)


def test_a_person_led_is_drawn_where_they_ended_with_where_they_stood(library: Any) -> None:
    """e2e25: the picture of "guide Anna to the lounge" showed Anna where she stood at the start (under the robot's
    end square once she walked with it): now a full triangle where she is, a hollow one where she stood."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    from seal_cli import pipeline
    from seal_cli.maps.formats.map_server import load_map
    from seal_cli.sim.policies import make_policy
    from seal_cli.sim.record import _draw_run

    agent, result = pipeline.run_on_map(load_map("guesthouse"), "take Anna to the kitchen", library,
                                        make_policy("oracle"), rng=np.random.default_rng(0))
    assert result.completed
    fig, ax = plt.subplots()
    try:
        _draw_run(ax, agent)
        handles, labels = ax.get_legend_handles_labels()
        stood = handles[labels.index("a person led, where they stood at the start")]
        assert tuple(stood.get_xydata()[0]) == agent.started["anna"] == (2.0, 8.0)
        now = [tuple(line.get_xydata()[0]) for line in ax.get_lines() if line.get_marker() == "^"
               and line.get_markerfacecolor() != "none"]
        assert agent.world.items["anna"].at in now and (2.0, 8.0) not in now
        assert load_map("guesthouse").room_of([agent.world.items["anna"].at]) == ["kitchen"]
    finally:
        plt.close(fig)


def test_a_picture_shows_the_house_not_the_unknown_border_of_a_laser_map(shared_data: Path) -> None:
    """The AWS house's 25 m square map holds a house of about 20 m x 12 m: the picture is cropped to its known
    cells, rooms, places and things plus half a metre (``shown_extent``), never beyond the bounds."""
    from seal_cli.maps.drawing import MARGIN, shown_extent
    from seal_cli.maps.formats.map_server import load_map

    aws = load_map(shared_data / "maps" / "aws_small_house" / "map.yaml")
    xmin, ymin, xmax, ymax = shown_extent(aws)
    assert -11.0 < xmin < -9.0 and 9.0 < xmax < 11.0 and -7.5 < ymin < -5.0 and 5.0 < ymax < 7.5
    apartment = load_map("apartment")       # known all over its bounds: the bounds
    assert shown_extent(apartment) == pytest.approx(apartment.bounds, abs=MARGIN)


def test_a_place_closed_after_something_was_taken_out_adds_no_card_of_its_own(library: Any) -> None:
    """"bring me the jam from the larder": opened (with what it showed), then "picked up jam_1 from larder_1,
    closed larder_1" where it stood, not a third card at that spot."""
    import numpy as np

    from seal_cli import pipeline
    from seal_cli.maps.formats.map_server import load_map
    from seal_cli.sim.policies import make_policy
    from seal_cli.sim.record import _acts

    agent, result = pipeline.run_on_map(load_map("bungalow"), "bring me the jam from the larder", library,
                                        make_policy("sefm", 100), rng=np.random.default_rng(0))
    assert result.completed
    labels = [text for _, text in _acts(agent.records)]
    assert labels[:2] == ["opened larder_1; inside: jam_1, biscuit_tin_1",
                          "picked up jam_1 from larder_1, closed larder_1"]
    assert not any(text.startswith("closed") for text in labels)


def test_the_path_is_cut_into_each_frames_leg_by_the_distance_driven_when_it_began() -> None:
    """e2e24: a multi-step run's path was one blue line; ``_legs`` cuts it where each frame began (its record's
    ``path_m``), each leg starting at the point the last one ended, and a frame that drove nothing has none."""
    import numpy as np

    from seal_cli.sim.agent import Record
    from seal_cli.sim.record import _legs

    trail = np.array([[0.0, 0.0], [1.0, 0.0], [2.0, 0.0], [2.0, 1.0], [2.0, 2.0]])
    records = [Record("frame", "Pick(theme=cup)", 0, 0.0, (0.0, 0.0, 0.0)),
               Record("act", "picked up cup_1", 1, 2.0, (2.0, 0.0, 0.0)),
               Record("frame", "Open(theme=fridge_1)", 2, 2.0, (2.0, 0.0, 0.0)),
               Record("frame", "Place(theme=cup, goal=me)", 3, 2.0, (2.0, 0.0, 0.0))]
    legs = _legs(trail, records)
    assert [name for name, _ in legs] == ["Pick(theme=cup)", "Place(theme=cup, goal=me)"]
    assert legs[0][1].tolist() == [[0.0, 0.0], [1.0, 0.0], [2.0, 0.0]]
    assert legs[1][1].tolist() == [[2.0, 0.0], [2.0, 1.0], [2.0, 2.0]]
    assert _legs(trail[:1], records) == [] and _legs(trail, records[1:2]) == []


def test_a_multi_step_run_draws_each_leg_in_its_colour_and_one_card_a_spot(library: Any) -> None:
    """e2e24: "bring Edith a blanket and Walter the watering can" on the care home: four legs, each named in the
    legend in a colour of its own; the robot picked up the watering can 0.15 m from where it handed it to Walter,
    and the two were cards drawn over each other: now one card holds both, no two cards within 0.5 m."""
    import math

    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    from seal_cli import pipeline
    from seal_cli.maps.formats.map_server import load_map
    from seal_cli.sim.policies import make_policy
    from seal_cli.sim.record import ONE_CARD_M, _draw_run

    agent, result = pipeline.run_on_map(load_map("carehome"), "bring Edith a blanket and Walter the watering can",
                                        library, make_policy("oracle"), rng=np.random.default_rng(0))
    assert result.completed
    fig, ax = plt.subplots()
    try:
        _draw_run(ax, agent)
        handles, labels = ax.get_legend_handles_labels()
        steps = [(h, t) for h, t in zip(handles, labels, strict=True) if t.startswith("step ")]
        assert [t.split(":")[0] for _, t in steps] == ["step 1", "step 2", "step 3", "step 4"]
        assert len({h.get_color() for h, _ in steps}) == 4
        cards = [t for t in ax.texts if "handed" in t.get_text() or "picked up" in t.get_text()]
        spots = [t.xy for t in cards]
        assert all(math.dist(a, b) > ONE_CARD_M for i, a in enumerate(spots) for b in spots[i + 1:])
        picked, handed = (next(r.pose[:2] for r in agent.records if r.text.startswith(what))
                          for what in ("picked up watering_can_1", "handed watering_can_1 to Walter"))
        together = any("picked up watering_can_1" in t.get_text() and "handed watering_can_1" in t.get_text()
                       for t in cards)
        assert together == (math.dist(picked, handed) <= ONE_CARD_M)
    finally:
        plt.close(fig)
