"""seal bench startup: child CPU is measured, ratios and stages are computed from it."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from seal_cli.bench import startup


def test_child_cpu_counts_the_childs_work_not_ours() -> None:
    idle = startup.child_cpu([sys.executable, "-c", "pass"], 3)
    busy = startup.child_cpu([sys.executable, "-c", "sum(i * i for i in range(3_000_000))"], 3)
    assert 0 < idle < busy


def test_a_failing_command_is_not_timed() -> None:
    with pytest.raises(subprocess.CalledProcessError):
        startup.child_cpu([sys.executable, "-c", "raise SystemExit(3)"], 1)


def test_measure_reports_ratios_against_a_bare_interpreter(monkeypatch: pytest.MonkeyPatch) -> None:
    seen: list[list[str]] = []
    cpu = {"pass": 0.01}

    def fake(argv: list[str], runs: int, env: dict[str, str] | None = None) -> float:
        seen.append(list(argv))
        code = argv[2]
        if code == "pass":
            return cpu["pass"]
        if code == startup.ENTRY:
            cold = env is not None and "SEAL_CACHE_DIR" in env
            return 0.05 if argv[3] == "--version" else 0.3 if cold else 0.2
        return 0.01 + sum(0.01 * (k + 1) for k, step in enumerate(startup.STAGES.values()) if step in code)

    warmed: list[list[str]] = []
    monkeypatch.setattr(startup, "child_cpu", fake)
    monkeypatch.setattr(startup, "warm_up", lambda argv: warmed.append(list(argv)))
    said: list[str] = []
    result = startup.measure(runs=2, progress=said.append)
    assert result["commands"]["version"] == {"cpu_s": 0.05, "ratio": pytest.approx(5.0), "target": 6.0, "ok": True}
    assert result["commands"]["parse"]["ratio"] == pytest.approx(20.0) and not result["commands"]["parse"]["ok"]
    assert list(result["stages_s"]) == list(startup.STAGES)
    assert list(result["stages_s"].values()) == pytest.approx([0.01, 0.02, 0.03])  # what each one adds
    assert result["cold"]["parse"] == {"cpu_s": 0.3, "ratio": pytest.approx(30.0)}
    assert [a[3:] for a in seen if a[2] == startup.ENTRY] == [["--version"], ["parse", startup.COMMAND],
                                                              *[["parse", startup.COMMAND]] * 2]
    assert [a[3:] for a in warmed] == [["--version"], ["parse", startup.COMMAND]]   # each warmed before timing
    assert said[0] == "a bare interpreter" and "seal --version" in said


def test_the_version_commands_run_as_the_console_script_runs_them() -> None:
    run = subprocess.run([sys.executable, "-c", startup.ENTRY, "--version"], capture_output=True, text=True,
                         check=True)
    assert run.stdout == "seal 0.1.0\n"
    frameworks = "{'typer', 'rich', 'yaml', 'lark'}"
    code = (f"import sys; sys.argv = ['seal', '--version']; {startup.ENTRY}; "
            f"print(sorted({{m.split('.')[0] for m in sys.modules}} & {frameworks}))")
    loaded = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert loaded.stdout.splitlines()[-1] == "[]"   # --version imports no framework, no parser


def test_a_cold_run_starts_with_an_empty_cache_of_its_own(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    code = "import os, sys; from seal_cli import cache; sys.exit(0 if not os.listdir(cache.folder()) else 3)"
    assert startup.cold_cpu([sys.executable, "-c", code], 2) > 0   # exit 3 would raise
    monkeypatch.setenv("PYTHONDONTWRITEBYTECODE", "1")
    marker = tmp_path / "flag"
    startup.warm_up([sys.executable, "-c", f"import os, sys; open({str(marker)!r}, 'w').write("
                     f"str(sys.dont_write_bytecode))"])
    assert marker.read_text() == "False"     # the warm-up may write bytecode
