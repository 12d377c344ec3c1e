"""ros.goals: where ``localize --goals`` may write, checked before the run."""

from __future__ import annotations

from pathlib import Path

import pytest

from seal_cli.errors import SealError
from seal_cli.ros.goals import check_goals_path


def test_goals_to_standard_output_are_refused_as_every_other_output_is(tmp_path: Path,
                                                                       monkeypatch: pytest.MonkeyPatch) -> None:
    """``--goals -`` made a ROS 2 bag folder called "-" (a name without a suffix), where ``--png -`` is refused
    (hostile31)."""
    monkeypatch.chdir(tmp_path)
    with pytest.raises(SealError, match=r"--goals '-': seal writes this output into a file, not to standard output"):
        check_goals_path(Path("-"))
    check_goals_path(Path("./-.yaml"))
    assert list(tmp_path.iterdir()) == []
