"""seal bench startup: child CPU is measured, ratios and stages are computed from it."""

from __future__ import annotations

import subprocess
import sys

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

    def fake(argv: list[str], runs: int) -> float:
        seen.append(list(argv))
        code = argv[2]
        if code == "pass":
            return cpu["pass"]
        if code == startup.ENTRY:
            return 0.05 if argv[3] == "--version" else 0.2
        return 0.01 + sum(0.01 * (k + 1) for k, step in enumerate(startup.STAGES.values()) if step in code)

    monkeypatch.setattr(startup, "child_cpu", fake)
    said: list[str] = []
    result = startup.measure(runs=2, progress=said.append)
    assert result["commands"]["version"] == {"cpu_s": 0.05, "ratio": pytest.approx(5.0), "target": 6.0, "ok": True}
    assert result["commands"]["parse"]["ratio"] == pytest.approx(20.0) and not result["commands"]["parse"]["ok"]
    assert list(result["stages_s"]) == list(startup.STAGES)
    assert list(result["stages_s"].values()) == pytest.approx([0.01, 0.02, 0.03, 0.04])  # what each one adds
    assert [a[3:] for a in seen if a[2] == startup.ENTRY] == [["--version"], ["parse", startup.COMMAND]]
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
