"""The policy registry: every name makes its policy; an unknown name is refused with the known ones."""

from __future__ import annotations

import pytest

from seal_cli.errors import SealError
from seal_cli.sim.policies import DEFAULT_POLICIES, POLICIES, make_policy
from seal_cli.sim.policies.base import Policy


@pytest.mark.parametrize("name", list(POLICIES))
def test_every_registered_name_makes_a_policy_of_that_name(name: str) -> None:
    policy = make_policy(name, particles=50)
    assert isinstance(policy, Policy)
    assert policy.name == name
    assert getattr(policy, "particles", 50) == 50


def test_unknown_policy_is_refused_with_the_known_ones() -> None:
    with pytest.raises(SealError, match="unknown policy 'psychic'; known: sefm, object_only") as error:
        make_policy("psychic")
    assert all(name in error.value.message for name in POLICIES)


def test_defaults_are_registered_and_leave_out_the_ablation() -> None:
    assert set(DEFAULT_POLICIES) <= set(POLICIES)
    assert "sefm" in DEFAULT_POLICIES and "uniform" not in DEFAULT_POLICIES


def test_the_base_policy_answers_every_question_but_where_to_look() -> None:
    policy = Policy()
    assert not policy.oracle and policy.clouds == [] and not policy.keep_clouds
    assert policy.choose(None, "cup", []) is None  # type: ignore[arg-type]
    with pytest.raises(NotImplementedError):
        policy.next_view(None, None, "cup")  # type: ignore[arg-type]
