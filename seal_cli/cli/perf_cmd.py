"""``seal bench perf``: belief updates per second of SeFM's engine and of the exact O(P²) evaluation."""

from __future__ import annotations

import typer

from seal_cli.cli import JsonOption, bench_app, command, emit_json, err, out


@command("perf", on=bench_app)
def perf(
    scales: list[str] | None = typer.Option(None, "--scale", help="paper, building or large (repeatable; default "
                                            "paper and building).", show_default=False),
    seed: int = typer.Option(0, "--seed", min=0, help="Seed of the random generators."),
    as_json: bool = JsonOption,
) -> None:
    """Updates per second of SeFM (grid kernel sums) and of the exact O(P²) reference, the total variation
    distance between their weights on the same particles, and peak memory, at the paper's scale, a building's
    and a large floor's (each in a process of its own)."""
    from rich.table import Table

    import seal_cli.bench.perf as perfbench
    from seal_cli.errors import SealError

    wanted = scales or ["paper", "building"]
    unknown = sorted(set(wanted) - set(perfbench.SCALES))
    if unknown:
        raise SealError(f"unknown scale {', '.join(unknown)}; the scales are {', '.join(perfbench.SCALES)}")
    err.print("[dim]seal bench perf: one thread; times are the CPU seconds of the process that runs the scale "
              "(other work on the machine does not count)[/dim]")
    results = []
    for name in (n for n in perfbench.SCALES if n in wanted):
        err.print(f"[dim]{name}: building the scale, then timing the updates[/dim]")
        results.append(perfbench.measure_apart(name, seed))
    if as_json:
        emit_json({"scales": results})
        return
    table = Table(title="SeFM belief updates (one core)", title_justify="left")
    for column in ("scale", "frames", "objects", "particles", "updates/s", "exact updates/s", "speed-up", "TV",
                   "peak MB"):
        table.add_column(column, justify="left" if column == "scale" else "right", no_wrap=True)
    for r in results:
        table.add_row(r["name"], str(r["frames"]), str(r["objects"]), str(r["particles"]), f"{r['updates_per_s']:.1f}",
                      f"{r['exact_updates_per_s']:.3g}", f"{r['updates_per_s'] / r['exact_updates_per_s']:.0f}×",
                      f"{r['tv_distance']:.4f}", f"{r['peak_rss_mb']:.0f}")
    out.print(table)
