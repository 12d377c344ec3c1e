"""``seal map``: what an annotated map holds, as a table, JSON or a picture; ``seal bench maps``."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import typer

from seal_cli.cli import MAX_COUNT, JsonOption, bench_app, command, emit_json, err, out
from seal_cli.cli.output import plain, styled


def summary(m: Any) -> dict[str, Any]:
    """The map as plain data: grid, rooms (with free area and the preposition they are said with), places, prior
    masses per room, objects."""
    from seal_cli.maps.prepositions import room_preposition

    areas = m.room_free_area()
    return {
        "name": m.name, "file": m.file, "bounds": list(m.bounds),
        "grid": {"shape": list(m.grid.shape), "resolution": m.grid.resolution, "origin": list(m.grid.origin)},
        "free_area": round(m.free_area, 3),
        "rooms": [{"name": r.name, "area": round(r.area, 3), "free_area": round(areas[r.name], 3),
                   "preposition": room_preposition(r.name, m)} for r in m.rooms],
        "places": [{"name": p.name, "class": p.cls, "at": list(p.at), "room": p.room, "openable": p.openable,
                    "open": p.open, "reach": p.reach} for p in m.places],
        "priors": {cls: {"masses": dict(masses), "rooms": {k: round(v, 4) for k, v in
                                                            m.prior(cls).room_masses().items()}}
                   for cls, masses in m.priors.items()},
        "objects": [{"class": o.cls, "at": list(o.at), "in": o.inside, "room": m.room_of([o.at])[0]}
                    for o in m.objects],
        "robot": {"pose": list(m.robot.pose), "holding": m.robot.holding, "room": m.room_of([m.robot.xy])[0]},
        "sensor": {"range": m.sensor.range, "fov": m.sensor.fov_deg, "p_detect": m.sensor.p_detect,
                   "sigma": m.sensor.sigma, "noise": m.sensor.noise},
        "people": [{"name": p.name, "at": [round(v, 3) for v in m.person_at(p)],
                    "room": m.room_of([m.person_at(p)])[0], "roles": list(p.roles)} for p in m.people],
        "speaker": {"at": [round(v, 3) for v in m.speaker_at], "room": m.room_of([m.speaker_at])[0],
                    "roles": list(m.speaker_roles)},
    }


def show(data: dict[str, Any]) -> None:
    from rich.table import Table

    grid = data["grid"]
    out.print(f"{styled('bold', data['name'])}  bounds {data['bounds']}  "
              f"grid {grid['shape'][1]}×{grid['shape'][0]} at {grid['resolution']:g} m  "
              f"free {data['free_area']:.1f} m²")
    rooms = Table("room", "area m²", "free m²", *map(plain, data["priors"]), title="rooms and prior mass per room")
    for room in data["rooms"]:
        masses = [f"{p['rooms'][room['name']]:.2f}" for p in data["priors"].values()]
        rooms.add_row(plain(room["name"]), f"{room['area']:.1f}", f"{room['free_area']:.1f}", *masses)
    out.print(rooms)
    if data["places"]:
        places = Table("place", "class", "at", "room", "state")
        for p in data["places"]:
            state = ("open" if p["open"] else "closed") if p["openable"] else ""
            places.add_row(plain(p["name"]), plain(p["class"]), _xy(p["at"]), plain(p["room"] or "—"), state)
        out.print(places)
    if data["objects"]:
        objects = Table("object", "at", "room", "in")
        for o in data["objects"]:
            objects.add_row(plain(o["class"]), _xy(o["at"]), plain(o["room"]), plain(o["in"] or ""))
        out.print(objects)
    if data["people"]:
        people = Table("person", "at", "room", "role")
        for p in data["people"]:
            people.add_row(plain(p["name"]), _xy(p["at"]), plain(p["room"]), plain(", ".join(p["roles"])))
        speaker = data["speaker"]
        people.add_row("(speaker: me)", _xy(speaker["at"]), plain(speaker["room"]), plain(", ".join(speaker["roles"])))
        out.print(people)
    robot, sensor = data["robot"], data["sensor"]
    out.print(f"robot at {_xy(robot['pose'][:2])} yaw {robot['pose'][2]:g} in {plain(robot['room'])}, holding "
              f"{plain(robot['holding'] or 'nothing')}; sensor {sensor['range']:g} m, {sensor['fov']:g}°, "
              f"p_detect {sensor['p_detect']:g}, σ {sensor['sigma']:g} m")


def _rate(per_second: float) -> str:
    for scale, unit in ((1e9, "G"), (1e6, "M"), (1e3, "k")):
        if per_second >= scale:
            return f"{per_second / scale:.1f} {unit}"
    return f"{per_second:.0f}"


def _xy(p: list[float]) -> str:
    return f"[{p[0]:g}, {p[1]:g}]"


@command("map")
def map_command(
    path: str = typer.Argument(..., help="A map file, or the name of a shipped map (apartment, townhouse, cafe, ...)."),
    png: Path | None = typer.Option(None, "--png", help="Also draw the map, its rooms, places, objects and the "
                                    "robot's visible region into this PNG file.", show_default=False),
    as_json: bool = JsonOption,
) -> None:
    """Show what an annotated map holds: rooms, places, priors per room, objects, robot and sensor."""
    from seal_cli.cli import OUTPUT_SUFFIXES
    from seal_cli.fileio import Outputs
    from seal_cli.maps.formats.map_server import load_map
    from seal_cli.resources import map_path

    m = load_map(map_path(path))
    for warning in m.warnings:
        err.print(f"warning: {warning}", markup=False)
    with Outputs({"--png": png}, [map_path(path)], suffixes=OUTPUT_SUFFIXES) as outputs:
        if png is not None:
            from seal_cli.maps.drawing import save_map_png

            save_map_png(m, outputs["--png"])
    data = summary(m)
    if as_json:
        emit_json(data)
    else:
        show(data)


@command("maps", on=bench_app)
def bench_maps(
    path: str = typer.Option("apartment", "--map", help="A map file, or the name of a shipped map."),
    repeats: int = typer.Option(5, "--repeats", min=1, max=MAX_COUNT,
                                help="Calls per figure (the median is reported)."),
    points: list[int] | None = typer.Option(None, "--points", min=1, max=1_000_000,
                                            help="Numbers of points to time each query "
                                            "on (repeatable; default 1000 and 60000).", show_default=False),
    as_json: bool = JsonOption,
) -> None:
    """Time the map queries a particle filter makes, on 1,000 and 60,000 points."""
    from rich.table import Table

    from seal_cli.bench.maps import bench_map
    from seal_cli.resources import map_path

    result = bench_map(map_path(path), sizes=tuple(points or (1_000, 60_000)), repeats=repeats)
    if as_json:
        emit_json(result)
        return
    out.print(f"{plain(result['map'])}: grid {result['grid'][1]}×{result['grid'][0]} at {result['resolution']:g} m, "
              f"load {result['load_ms']:.1f} ms, visible region {result['visible_region_ms']:.1f} ms "
              f"({result['rays']} rays)")
    table = Table("query", "points", "ms per call", "points per second")
    for row in result["queries"]:
        rate = row["points"] / row["ms"] * 1000 if row["ms"] else float("inf")
        table.add_row(row["query"], f"{row['points']:,}", f"{row['ms']:.2f}", _rate(rate))
    out.print(table)
