"""``seal bench tasks --backend``: the process pool and Ray's drop-in pool give the same outcomes."""

from __future__ import annotations

from pathlib import Path

import pytest

from seal_cli.errors import SealError

DATA = Path(__file__).resolve().parents[2] / ".." / "shared" / "data" / "alfred2d"


def test_an_unknown_backend_is_refused() -> None:
    from seal_cli.bench.tasks import run_suite

    with pytest.raises(SealError, match="unknown backend 'slurm'; use one of process, ray"):
        list(run_suite(DATA, "valid_seen", ["oracle"], limit=1, backend="slurm"))


@pytest.mark.skipif(not DATA.is_dir(), reason="needs ../shared/data/alfred2d")
def test_the_ray_backend_gives_the_process_pools_outcomes() -> None:
    pytest.importorskip("ray")
    from seal_cli.bench.tasks import run_suite

    def key(backend: str) -> list[tuple[str, str, bool, int, float]]:
        return [(o.task_id, o.policy, o.success, o.steps, o.path_m)
                for o in run_suite(DATA, "valid_seen", ["oracle", "coverage"], limit=1, types=["pick_and_place_simple",
                                   "pick_heat_then_place_in_recep"], seed=1, jobs=2, backend=backend)]

    assert key("ray") == key("process")


@pytest.mark.skipif(not DATA.is_dir(), reason="needs ../shared/data/alfred2d")
def test_a_stratified_sample_takes_as_many_of_each_type_the_same_whatever_the_seed() -> None:
    from collections import Counter

    from seal_cli.bench.alfred2d import TASK_TYPES, load_suite

    sample = load_suite(DATA, "train", sample=3, with_priors=False).episodes
    assert Counter(e.group for e in sample) == {t: 3 for t in TASK_TYPES}
    first = load_suite(DATA, "train", limit=3, with_priors=False).episodes
    assert {e.task_id for e in sample} != {e.task_id for e in first}   # not the file's first ones
    assert [e.task_id for e in load_suite(DATA, "train", sample=3, with_priors=False).episodes] == \
        [e.task_id for e in sample]


def test_limit_and_sample_together_are_refused() -> None:
    from typer.testing import CliRunner

    from seal_cli.cli import app

    result = CliRunner().invoke(app, ["bench", "tasks", "--limit", "1", "--sample", "1"])
    assert result.exit_code == 1 and "--limit" in result.output and "not both" in result.output
    assert "Traceback" not in result.output
