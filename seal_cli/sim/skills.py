"""SayCan (Ahn et al. 2022) in the 2-D world: a language model picks the next primitive skill.

A :class:`SkillRunner` never sees frames or a plan. At every step it lists the candidate skills
grounded on what the robot knows — the map's places and the things it has seen — plus, for the
classes its perception knows but has not seen, "pick up the X" and "go to the X" (not afforded),
"explore" and "done". Each skill gets

    score = p_LM(skill | instruction, history) × affordance(skill, state)

with ``p_LM`` from a :class:`~seal_cli.sim.scorers.Scorer` and the affordance from detection, as
the public SayCan implementation does with its value functions: a skill on a thing that is seen,
reachable and in the right state scores :data:`AFFORDED`, one that would fail now (out of reach,
hand full, thing unseen) :data:`UNAFFORDED`. The argmax is executed with the agent's perception
and driving (an :class:`~seal_cli.sim.agent.Agent` whose policy is coverage, used only for
"explore"), until it chooses "done" or the budget ends.

What went wrong is counted: ``proposed_unafforded`` (the language model's own first choice was not
afforded: the "turn on the microwave before closing it" of the paper), ``never_seen`` (classes the
instruction names that the robot never saw), and whether it said ``done``. Whether the task is done
is the caller's judge's business; :func:`failure_kinds` names what went wrong from both.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np

from seal_cli.frames.library import Library
from seal_cli.frames.taxonomy import class_key
from seal_cli.maps.model import SPEAKER
from seal_cli.sim.agent import Agent, Budget, Known, Record, Scene
from seal_cli.sim.scorers import DONE, Example, Scorer, prompt_for
from seal_cli.sim.world import PERSON, Outcome

if TYPE_CHECKING:
    from seal_cli.maps.model import Map

__all__ = ["AFFORDED", "UNAFFORDED", "Skill", "SkillResult", "SkillRunner", "failure_kinds", "gold_instruction",
           "run_text_on_map"]

AFFORDED = 1.0
UNAFFORDED = 0.001
"""Affordance of a skill that can succeed now, and of one that would fail (SayCan's value
functions are near zero there, never exactly zero)."""

MAX_SKILLS = 60
"""Skills chosen before the runner gives up, on top of the agent's step and path budget."""


@dataclass(frozen=True)
class Skill:
    """One grounded primitive: ``text`` is what the language model scores."""

    text: str
    action: str
    args: tuple[str, ...] = ()
    affordance: float = AFFORDED


@dataclass
class SkillResult:
    completed: bool
    """It said "done" (whether the task is done is the judge's business)."""
    reason: str
    path_m: float
    steps: int
    history: list[str]
    proposed_unafforded: int = 0
    failed_skills: int = 0
    never_seen: list[str] = field(default_factory=list)
    records: list[Record] = field(default_factory=list)
    known: list[str] = field(default_factory=list)
    """The items the robot knew at the end (the map's and those it saw)."""

    @property
    def plan(self) -> list[str]:
        return self.history


def failure_kinds(result: SkillResult, success: bool) -> list[str]:
    """What went wrong, in the report's words; empty on success."""
    if success:
        return []
    kinds = []
    if result.completed:
        kinds.append("done too early")
    if result.never_seen:
        kinds.append("object never found")
    if result.proposed_unafforded:
        kinds.append("unafforded action proposed")
    if not result.completed:
        kinds.append("out of budget")
    return kinds


def words(cls: str) -> str:
    """A class as the words of a sentence: ``sink_basin`` → ``sink basin``."""
    return cls.replace("_", " ")


class SkillRunner:
    """One SayCan run; see the module docstring."""

    def __init__(self, scene: Scene, library: Library, scorer: Scorer, *, rng: np.random.Generator,
                 budget: Budget | None = None, observers: Sequence[Callable[[Record], None]] = (),
                 examples: Sequence[Example] = ()) -> None:
        from seal_cli.sim.policies.coverage import CoveragePolicy

        self.agent = Agent(scene, library, CoveragePolicy(), rng=rng, budget=budget, observers=observers)
        self.world = scene.world
        self.scorer = scorer
        vocabulary = scene.vocabulary or tuple(sorted({i.key for i in self.world.items.values()}))
        self.movable = sorted({i.key for i in self.world.items.values() if i.movable} & set(vocabulary))
        self.seen: set[str] = set()
        self.placed: set[str] = set()
        """Things this run has put down: a later "find" looks for another."""
        self.explored_all = False
        self.acted: dict[str, str] = {}
        """The thing of each class last acted on: what "the apple" means after slicing one."""
        self.focus = ""
        """The thing last gone to: what an ambiguous phrase ("pick up the book") means."""
        self.examples = tuple(examples)
        self.rooms = tuple(r.name for r in scene.map.rooms if not r.name.startswith("_")) if len(scene.map.rooms) > 1 \
            else ()
        """The map's rooms, to go to ("go to the bedroom"); none on a one-room map (ALFRED's)."""

    # -- candidates ----------------------------------------------------------------------------

    def _reach(self, k: Known) -> bool:
        return self.world.within_reach(k.id) and self.world.enclosure(k.id) is None

    def candidates(self) -> list[Skill]:
        world, agent = self.world, self.agent
        held = world.robot.holding
        known = [k for k in agent.known.values() if not world.held_chain(k.id)]
        skills = [Skill("explore", "explore"), Skill(DONE, "done")]
        taxonomy = world.taxonomy
        for k in known:
            name = words(k.cls)
            item = world.items[k.id]
            near = self._reach(k)
            if not k.movable and k.cls != PERSON:   # a thing is gone to by finding it (below); where it stands: a no-op
                skills.append(Skill(f"go to the {name}", "go", (k.id,)))
            if k.movable:
                ok = near and held is None
                skills.append(Skill(f"pick up the {name}", "pick", (k.id,), AFFORDED if ok else UNAFFORDED))
            if item.openable:
                skills.append(Skill(f"open the {name}", "open", (k.id,),
                                    AFFORDED if near and not item.is_open else UNAFFORDED))
                skills.append(Skill(f"close the {name}", "close", (k.id,),
                                    AFFORDED if near and item.is_open else UNAFFORDED))
            if item.toggleable:
                on = "on" in item.states
                skills.append(Skill(f"turn on the {name}", "toggle_on", (k.id,),
                                    AFFORDED if near and not on else UNAFFORDED))
                skills.append(Skill(f"turn off the {name}", "toggle_off", (k.id,),
                                    AFFORDED if near and on else UNAFFORDED))
            if held is not None and k.receptacle:
                hname = words(world.items[held].key)
                ok = near and (not item.openable or item.is_open)
                skills.append(Skill(f"put the {hname} in the {name}", "place", (held, k.id),
                                    AFFORDED if ok else UNAFFORDED))
            if held is not None:
                hname = words(world.items[held].key)
                for verb, category in (("heat", "heater"), ("cool", "cooler"), ("clean", "washer")):
                    if taxonomy.is_a(k.cls, category) is True:
                        skills.append(Skill(f"{verb} the {hname} with the {name}", verb, (held, k.id),
                                            AFFORDED if near else UNAFFORDED))
                if taxonomy.is_a(world.items[held].key, "cutter") is True and k.movable:
                    skills.append(Skill(f"slice the {name} with the {hname}", "slice", (k.id, held),
                                        AFFORDED if near else UNAFFORDED))
                if taxonomy.is_a(world.items[held].key, "utensil") is True and \
                        taxonomy.is_a(k.cls, "container") is True:
                    skills.append(Skill(f"stir the {name} with the {hname}", "stir", (held, k.id),
                                        AFFORDED if near else UNAFFORDED))
                if k.cls == PERSON:
                    person = "me" if k.id == SPEAKER else k.id
                    skills.append(Skill(f"give the {hname} to {person}", "hand_over", (held, k.id),
                                        AFFORDED if near else UNAFFORDED))
            if k.cls == PERSON:
                skills.append(Skill(f"go to {'me' if k.id == SPEAKER else k.id}", "go", (k.id,)))
                continue
        for room in self.rooms:
            skills.append(Skill(f"go to the {words(room)}", "enter", (room,)))
            if held is not None:   # put down in the room: where such a thing is put there, if within reach
                place = self.agent.surface_in(self.agent.room(room), world.items[held].key)
                ok = place is not None and self._reach(self.agent.known[place])
                skills.append(Skill(f"put the {words(world.items[held].key)} in the {words(room)}", "place",
                                    (held, place or ""), AFFORDED if ok else UNAFFORDED))
        if held is not None:
            name = words(world.items[held].key)
            skills.append(Skill(f"look at the {name}", "look_at", (held,)))
            spot = self._put_down_spot(held)
            skills.append(Skill(f"put down the {name}", "place", (held, spot or ""),
                                AFFORDED if spot else UNAFFORDED))
        for cls in self.movable:
            if cls not in self.seen:
                skills.append(Skill(f"pick up the {words(cls)}", "unseen", (cls,), UNAFFORDED))
            skills.append(Skill(f"find the {words(cls)}", "find", (cls,), self._findable(cls)))
        unique: dict[str, Skill] = {}
        for s in skills:   # two fridges are one phrase: keep the afforded one, the one just gone to first
            if s.text not in unique or self._rank(s) > self._rank(unique[s.text]):
                unique[s.text] = s
        return list(unique.values())

    def _rank(self, skill: Skill) -> tuple[float, bool, bool]:
        first = skill.args[0] if skill.args else ""
        return skill.affordance, first == self.focus, first not in self.placed

    def _targets(self, cls: str) -> list[Known]:
        """The things of a class the robot knows and may go to: not in hand, not put down by it."""
        return [k for k in self.agent.known.values() if k.cls == cls and k.movable and k.id not in self.placed
                and not self.world.held_chain(k.id)]

    def _findable(self, cls: str) -> float:
        """Finding is afforded while a thing of the class is known, or none is known and something
        is left to explore; not while the hand holds one."""
        held = self.world.robot.holding
        if held is not None and self.world.items[held].key == cls:
            return UNAFFORDED
        return AFFORDED if self._targets(cls) or not self.explored_all else UNAFFORDED

    def _put_down_spot(self, held: str) -> str | None:
        """Where "put down" puts the thing in hand: the nearest open receptacle within reach."""
        world = self.world
        spots = [k for k in self.agent.known.values() if k.receptacle and k.id != held
                 and not world.held_chain(k.id) and world.items[k.id].is_open and self._reach(k)]
        here = world.robot.pose[:2]
        return min(spots, key=lambda k: (np.hypot(k.at[0] - here[0], k.at[1] - here[1]), k.id)).id if spots \
            else None

    # -- executing -----------------------------------------------------------------------------

    def execute(self, skill: Skill) -> Outcome:
        agent, world = self.agent, self.world
        if skill.action == "explore":
            view = agent.policy.next_view(agent, None, "")  # type: ignore[arg-type]  # coverage ignores both
            if view is None:
                return Outcome(False, "nothing left to explore")
            agent.drive_to(view.cell, "explores")
            world.face(view.look_at)
            if view.open is not None:
                agent.open_to_look(view.open)
            return Outcome(True, "explored")
        if skill.action == "find":
            return self.find(skill.args[0])
        if skill.action == "enter":
            return self.enter(skill.args[0])
        if skill.action == "unseen":
            world.step += 1
            return Outcome(False, f"sees no {words(skill.args[0])}")
        if skill.action == "go":
            return self._approach(agent.known[skill.args[0]])
        if skill.action == "place" and not skill.args[1]:
            world.step += 1
            return Outcome(False, "nothing open within reach to put it down on")
        outcome = world.act(skill.action, *skill.args)
        if outcome.ok:
            for thing in skill.args:
                self.acted[world.items[thing].key] = thing
        if outcome.ok and skill.action == "place":
            agent.known[skill.args[0]] = agent._known(world.items[skill.args[0]])
            self.placed.add(skill.args[0])
        if outcome.ok and skill.action == "pick":
            self.placed.discard(skill.args[0])
        return outcome

    def enter(self, name: str) -> Outcome:
        """Go into a room of the map, as the agent's ``navigate`` does (:meth:`Agent.go_to`): holding a thing,
        to the place there where such a thing is put (so "put the cup in the kitchen" is within reach next);
        else into the room, near its middle (:meth:`Agent.into_room`), not to its nearest appliance."""
        agent, world = self.agent, self.world
        room = agent.room(name)
        held = world.robot.holding
        place = agent.surface_in(room, world.items[held].key) if held is not None else None
        if place is not None:
            return self.execute(Skill(f"go to the {words(agent.known[place].cls)}", "go", (place,)))
        if bool(room.contains([world.robot.pose[:2]])[0]):
            world.step += 1
            return Outcome(True, f"in {name}")
        outcome = agent.into_room(room, name)
        if not outcome.ok:
            world.step += 1
        return outcome

    def find(self, cls: str) -> Outcome:
        """Go to the nearest known thing of the class; with none known, explore (the coverage
        searcher's views, looking all the way) until one is seen, then go to it."""
        agent, world = self.agent, self.world
        while not (targets := self._targets(cls)):
            if agent.exhausted() is not None:
                return Outcome(False, f"no {words(cls)} found within the budget")
            view = agent.policy.next_view(agent, None, "")  # type: ignore[arg-type]  # coverage ignores both
            if view is None:
                self.explored_all = True
                world.step += 1
                return Outcome(False, f"explored everything: no {words(cls)}")
            agent.drive_to(view.cell, f"looks for a {words(cls)}")
            world.face(view.look_at)
            if view.open is not None:
                agent.open_to_look(view.open)
            self._look()
        here = world.robot.pose[:2]
        target = min(targets, key=lambda k: (k.id != self.acted.get(cls),   # "the apple": the one last acted on
                                             np.hypot(k.at[0] - here[0], k.at[1] - here[1]), k.id))
        return self._approach(target)

    def _approach(self, known: Known) -> Outcome:
        """Drive to where the robot can act on a known thing, face it, and keep it in focus."""
        cell = self.agent.stand_cell(known)
        if cell is None:
            self.world.step += 1
            return Outcome(False, f"cannot reach {known.id}")
        self.agent.drive_to(cell, f"goes to {known.id}")
        self.world.face(known.at)
        self.focus = known.id
        return Outcome(True, f"at {known.id}")

    def run(self, instruction: str) -> SkillResult:
        agent, world = self.agent, self.world
        agent.policy.begin(agent)
        self._look()
        history: list[str] = []
        unafforded = failed = 0
        explored = 0
        said_done = False
        reason = f"chose {MAX_SKILLS} skills without saying done"
        for _ in range(MAX_SKILLS):
            if (stop := agent.exhausted()) is not None:
                reason = stop
                break
            skills = self.candidates()
            logp = self.scorer.score(prompt_for(instruction, history, self.examples), [s.text for s in skills])
            lm = np.exp(logp)
            combined = lm * np.array([s.affordance for s in skills])
            if skills[int(np.argmax(lm))].affordance < AFFORDED:
                unafforded += 1
            skill = skills[int(np.argmax(combined))]
            agent.say("skill", f"{skill.text} (p_LM {lm[int(np.argmax(combined))]:.3f}, "
                               f"affordance {skill.affordance:g})", skill=skill.text)
            if skill.action == "done":
                said_done, reason = True, "said done"
                break
            outcome = self.execute(skill)
            agent.say("act" if outcome.ok else "fail", outcome.message, action=skill.action, args=list(skill.args))
            if not outcome.ok:
                failed += 1
            if skill.action == "explore":
                explored += 1
                history.append(f"explored area {explored}")  # each look goes somewhere new: not a repeat
            else:
                history.append(skill.text if outcome.ok else f"failed to {skill.text}")
            self._look()
        named = self.named_classes(instruction)
        return SkillResult(said_done, reason, world.robot.path_m, world.step, history, unafforded, failed,
                           sorted(c for c in named if c not in self.seen), agent.records, sorted(agent.known))

    def _look(self) -> None:
        for d in self.agent.look(quiet=True):
            self.seen.add(class_key(d.cls))
        if (held := self.world.robot.holding) is not None:
            self.seen.add(self.world.items[held].key)

    def named_classes(self, instruction: str) -> set[str]:
        """The movable classes the instruction names (their words appear in it, singular or plural)."""
        text = " " + " ".join(re.findall(r"[a-z0-9]+", instruction.lower())) + " "
        return {c for c in self.movable if re.search(rf" {re.escape(words(c))}(s|es)? ", text)}


def gold_instruction(kind: str, obj: str, receptacle: str | None = None, mrecep: str | None = None,
                     toggle: str | None = None, sliced: bool = False) -> str:
    """An ALFRED task's labels as one plain sentence, the way its templates read."""
    o, r = words(class_key(obj)), words(class_key(receptacle or ""))
    first = f"slice the {o} with a knife, then " if sliced else ""
    sentence = {
        "look_at_obj_in_light": f"look at the {o} in the light of the {words(class_key(toggle or 'desk_lamp'))}",
        "pick_and_place_simple": f"put the {o} in the {r}",
        "pick_two_obj_and_place": f"put two {o}s in the {r}",
        "pick_and_place_with_movable_recep": f"put the {o} in the {words(class_key(mrecep or ''))}, "
                                             f"then put the {words(class_key(mrecep or ''))} in the {r}",
        "pick_heat_then_place_in_recep": f"heat the {o}, then put it in the {r}",
        "pick_cool_then_place_in_recep": f"cool the {o}, then put it in the {r}",
        "pick_clean_then_place_in_recep": f"clean the {o}, then put it in the {r}",
    }.get(kind, f"{kind.replace('_', ' ')} {o} {r}")
    return first + sentence


def run_text_on_map(m: Map, text: str, library: Library, policy: Any, *, rng: np.random.Generator,
                    holding: str | None = None, budget: Budget | None = None,
                    observers: Sequence[Callable[[Record], None]] = ()) -> SkillResult:
    """A self-driving policy (``saycan``) on a map whose ground-truth objects are the world (``seal run``)."""
    from dataclasses import replace

    from seal_cli.maps.model import Robot
    from seal_cli.sim.agent import scene_from_map

    if holding is not None:
        m.check_holding(holding)
        m = replace(m, robot=Robot(m.robot.pose, holding))
    result: SkillResult = policy.run(scene_from_map(m, library), library, text, rng=rng, budget=budget,
                                     observers=observers)
    return result
