"""``seal bench reliability``: the issue-14 cases and hundreds of hostile inputs, run as subprocesses."""

from __future__ import annotations

import typer

from seal_cli.cli import JsonOption, bench_app, command, emit_json, err, out


@command("reliability", on=bench_app)
def reliability(
    seed: int = typer.Option(0, "--seed", min=0, help="Seed of the generated hostile inputs."),
    count: int = typer.Option(320, "--count", min=0, max=100_000, help="How many hostile inputs to generate "
                              "(besides the cases of issue 14)."),
    limit: int | None = typer.Option(None, "--limit", min=1, help="Run only the first N cases.",
                                     show_default=False),
    jobs: int = typer.Option(2, "--jobs", min=1, max=64, help="Cases run at once."),
    match: str | None = typer.Option(None, "--match", help="Run only the cases whose name holds this text "
                                     "(e.g. 'R ' for the reviewer's).", show_default=False),
    as_json: bool = JsonOption,
) -> None:
    """Run seal as a hostile user would: count tracebacks, hangs, wrong exit codes, lost or partial
    files and nondeterminism (all should be zero)."""
    from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeRemainingColumn

    from seal_cli.bench.reliability import run_cases, summarise
    from seal_cli.bench.reliability_review import cases
    from seal_cli.errors import SealError

    every = list(cases(seed, count))
    todo = [c for c in every if match is None or match in c.name][:limit]
    if not todo:  # a mistyped --match ran nothing and reported every count 0, as if all had passed
        raise SealError(f"--match {match!r}: no case's name holds this text (of {len(every):,} cases; names start "
                        "'R ', 'A ', 'O ', 'U ' or a number)")
    with Progress(TextColumn("cases"), BarColumn(), MofNCompleteColumn(), TimeRemainingColumn(),
                  console=err.console, transient=True, disable=not err.is_terminal) as progress:
        bar = progress.add_task("cases", total=len(todo))
        outcomes = run_cases(todo, jobs, lambda done, total: progress.update(bar, completed=done))
    report = summarise(outcomes)
    if as_json:
        emit_json(report)
    else:
        for item in report["problems"]:  # type: ignore[attr-defined]
            for problem in item["problems"]:
                out.print(f"{item['case']}: {problem}", markup=False)
        out.print(" ".join(f"{key} {report[key]}" for key in ("tried", "tracebacks", "hangs", "wrong_exit_codes",
                                                              "lost_or_partial_files", "nondeterministic",
                                                              "unclear_messages", "slowest_s")), markup=False)
    failed = any(report[k] for k in ("tracebacks", "hangs", "wrong_exit_codes", "lost_or_partial_files",
                                     "nondeterministic", "unclear_messages"))
    if failed:
        raise typer.Exit(1)
