"""``seal bench startup``: what ``seal --version`` and ``seal parse TEXT`` cost against a bare interpreter."""

from __future__ import annotations

import typer

from seal_cli.cli import JsonOption, bench_app, command, emit_json, err, out


@command("startup", on=bench_app)
def startup(
    runs: int = typer.Option(20, "--runs", min=1, help="Fresh interpreters per figure (the median is kept)."),
    as_json: bool = JsonOption,
) -> None:
    """CPU (user + system) of `seal --version` and `seal parse TEXT` as multiples of `python -c pass` (warm:
    seal's cache filled, as after the first command; and a cold parse, its cache empty), and what a warm
    parse pays for, stage by stage."""
    from rich.table import Table

    from seal_cli.bench.startup import COMMAND, measure

    err.print("[dim]seal bench startup: CPU seconds of child processes (other work on the machine does not "
              "count), median of each figure's runs[/dim]")
    result = measure(runs, lambda text: err.print(f"[dim]{text}[/dim]"))
    if as_json:
        emit_json(result)
        return
    table = Table(title=f"start-up, {runs} runs each; a bare python -c pass: {result['python_s'] * 1000:.1f} ms",
                  title_justify="left")
    for column in ("command", "CPU ms", "× python", "target", ""):
        table.add_column(column, justify="left" if column in ("command", "") else "right")
    names = {"version": "seal --version", "parse": f"seal parse {COMMAND!r}"}
    for name, figures in result["commands"].items():
        table.add_row(names[name], f"{figures['cpu_s'] * 1000:.1f}", f"{figures['ratio']:.1f}×",
                      f"≤ {figures['target']:g}×", "ok" if figures["ok"] else "over")
    cold = result["cold"]["parse"]
    table.add_row(f"{names['parse']}, cold (empty cache)", f"{cold['cpu_s'] * 1000:.1f}", f"{cold['ratio']:.1f}×",
                  "", "")
    out.print(table)
    stages = Table(title="what a parse pays for (each stage: what it adds to the ones above)", title_justify="left")
    stages.add_column("stage")
    stages.add_column("CPU ms", justify="right")
    for name, seconds in result["stages_s"].items():
        stages.add_row(name, f"{seconds * 1000:.1f}")
    out.print(stages)
