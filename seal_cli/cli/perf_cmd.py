"""``seal bench perf``: belief updates per second of SeFM's engine and of the exact O(P²) evaluation."""

from __future__ import annotations

import typer

from seal_cli.cli import JsonOption, bench_app, command, emit_json, err, out


@command("perf", on=bench_app)
def perf(
    scales: list[str] | None = typer.Option(None, "--scale", help="paper or building (repeatable; default both).",
                                            show_default=False),
    seed: int = typer.Option(0, "--seed", min=0, help="Seed of the random generators."),
    as_json: bool = JsonOption,
) -> None:
    """Updates per second of SeFM (grid kernel sums) and of the exact O(P²) reference, and the total variation
    distance between their weights on the same particles, at the paper's scale and a building's."""
    from rich.table import Table

    from seal_cli.bench.perf import measure
    from seal_cli.bench.perf import scales as build_scales
    from seal_cli.errors import SealError
    from seal_cli.frames.reading import load_library
    from seal_cli.maps.formats.map_server import load_map
    from seal_cli.resources import map_path

    wanted = scales or ["paper", "building"]
    unknown = sorted(set(wanted) - {"paper", "building"})
    if unknown:
        raise SealError(f"unknown scale {', '.join(unknown)}; the scales are paper and building")
    err.print("[dim]seal bench perf: one thread; times are this process's CPU seconds (other work on the "
              "machine does not count)[/dim]")
    library = load_library()
    results = [measure(scale, seed, lambda text: err.print(f"[dim]{text}[/dim]"))
               for scale in build_scales(library, lambda: load_map(map_path("apartment")), wanted, seed)]
    if as_json:
        emit_json({"scales": results})
        return
    table = Table(title="SeFM belief updates (one core)", title_justify="left")
    for column in ("scale", "frames", "objects", "particles", "updates/s", "exact updates/s", "speed-up", "TV"):
        table.add_column(column, justify="left" if column == "scale" else "right")
    for r in results:
        table.add_row(r["name"], str(r["frames"]), str(r["objects"]), str(r["particles"]), f"{r['updates_per_s']:.1f}",
                      f"{r['exact_updates_per_s']:.3g}", f"{r['updates_per_s'] / r['exact_updates_per_s']:.0f}×",
                      f"{r['tv_distance']:.4f}")
    out.print(table)
