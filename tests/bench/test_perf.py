"""``seal bench perf``: the SPEC's JSON, and the engine against the exact reference on the same particles."""

from __future__ import annotations

import json
from dataclasses import replace

import numpy as np
from typer.testing import CliRunner

from seal_cli.bench.perf import building, measure, scales, tv_distance
from seal_cli.cli import app
from seal_cli.frames.library import Library
from seal_cli.maps.formats.map_server import load_map
from seal_cli.resources import map_path


def test_the_building_is_a_walled_floor_of_rooms_with_one_thing_of_each_class() -> None:
    m = building(np.random.default_rng(0), classes=12, columns=3, rows=2)
    assert len(m.rooms) == 6 and len(m.objects) == 12 and len(m.priors) == 12
    assert m.grid.has_obstacles
    assert all(0.9 < sum(p.values()) < 1.0 for p in m.priors.values())
    doorway = np.array([[5.0, 2.5]])  # the middle of the wall between the first two rooms
    assert m.is_free(doorway)[0] and not m.is_free(np.array([[5.0, 0.6]]))[0]


def test_the_paper_scale_is_the_papers_fig3(library: Library) -> None:
    (paper,) = scales(library, lambda: load_map(map_path("apartment")), ["paper"])
    assert (len(paper.bindings), paper.objects, paper.particles) == (3, 2, 200)
    result = measure(replace(paper, updates=5, exact_updates=2))
    assert set(result) == {"name", "frames", "objects", "particles", "updates_per_s", "exact_updates_per_s",
                           "tv_distance", "peak_rss_mb", "compiled"}
    assert result["peak_rss_mb"] > 10
    assert result["updates_per_s"] > 0 and result["exact_updates_per_s"] > 0
    assert 0 <= result["tv_distance"] <= 0.02


def test_the_building_scale_has_the_spec_size_and_grid_matches_exact(library: Library) -> None:
    (big,) = scales(library, lambda: load_map(map_path("apartment")), ["building"])
    assert len(big.bindings) >= 60 and big.objects >= 60 and big.particles == 1000
    small = replace(big, particles=150, updates=3)
    from seal_cli.bench.perf import _run

    sefm, _ = _run(small, "grid", small.updates, 0)
    assert tv_distance(sefm) <= 0.02


def test_cli_json_and_unknown_scale() -> None:
    runner = CliRunner()
    bad = runner.invoke(app, ["bench", "perf", "--scale", "city"])
    assert bad.exit_code == 1 and "unknown scale city" in bad.stderr
    assert "--scale" in runner.invoke(app, ["bench", "perf", "--help"]).stdout


def test_json_output_shape(monkeypatch: object) -> None:
    import seal_cli.bench.perf as perfbench

    asked = []

    def quick(name: str, seed: int = 0) -> dict[str, object]:
        asked.append(name)
        return {"name": name, "frames": 3, "objects": 2, "particles": 200, "updates_per_s": 1.0,
                "exact_updates_per_s": 0.5, "tv_distance": 0.0, "peak_rss_mb": 120.0}

    monkeypatch.setattr(perfbench, "measure_apart", quick)  # type: ignore[attr-defined]
    result = CliRunner().invoke(app, ["bench", "perf", "--json", "--scale", "large", "--scale", "paper"])
    assert result.exit_code == 0, result.output
    data = json.loads(result.stdout)
    assert asked == ["paper", "large"]  # smallest first, whatever the order asked
    assert [s["name"] for s in data["scales"]] == ["paper", "large"]
    table = CliRunner().invoke(app, ["bench", "perf", "--scale", "paper"])
    assert table.exit_code == 0 and "120" in table.stdout  # the peak column


def test_a_scale_measured_apart_reports_its_own_peak_memory() -> None:
    from seal_cli.bench.perf import measure_apart

    result = measure_apart("paper", 0)
    assert result["name"] == "paper" and result["frames"] == 3
    assert 10 < result["peak_rss_mb"] < 2000


def test_the_large_scale_has_the_spec_size(library: Library) -> None:
    from seal_cli.bench.perf import scale

    large = scale("large", library, lambda: load_map(map_path("apartment")))
    xmin, ymin, xmax, ymax = large.map.bounds
    assert (xmax - xmin, ymax - ymin) == (120.0, 80.0)
    assert len(large.bindings) == 200 and len(large.map.priors) == 200 and large.particles == 1000
    assert large.objects == 200
    cup = large.map.prior(sorted(large.map.priors)[0])
    assert sum(len(cells) for cells, _ in cup.components) < len(large.map.free_centres) / 50  # sparse
