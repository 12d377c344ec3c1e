"""The one way through: text → parse → ground → plan → SeFM (and, in the simulator, act).

Each stage is a module of its own — :mod:`seal_cli.language.parser` (words → frames),
:mod:`seal_cli.planning.problem` (frames + the robot's state + the map → grounded frames),
:mod:`seal_cli.planning.plan` (A*), :mod:`seal_cli.sefm.filter` (beliefs), :mod:`seal_cli.sim.agent`
(acting). This module strings them together the way ``seal parse``, ``seal plan``, ``seal localize``
and ``seal run`` do, so that a program using seal as a library takes the same path::

    from seal_cli import pipeline

    result = pipeline.plan("stir the cup")                  # the standard library, no map
    beliefs = pipeline.localise(the_map, ["stir the cup"], rng=np.random.default_rng(0))

Where a function takes ``library=None`` it uses the shipped standard library
(:func:`seal_cli.frames.reading.standard_library`, read once). Parsing and planning import no
numpy: the maps, SeFM and the simulator are imported by the functions that need them.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import replace
from typing import TYPE_CHECKING, Any

from seal_cli.frames.library import Library
from seal_cli.frames.model import Binding
from seal_cli.frames.reading import standard_library
from seal_cli.frames.taxonomy import class_key
from seal_cli.language.grounding import Vocabulary, vocabulary_of_map
from seal_cli.language.parser import Parse, parse_command
from seal_cli.planning import plan as planning
from seal_cli.planning.plan import MAX_NODES, Plan
from seal_cli.planning.problem import Things, build_problem, naming_done, parse_to_plan, problem_of_text
from seal_cli.planning.state import State
from seal_cli.sim.unsearched import SEARCH_END

if TYPE_CHECKING:
    from datetime import datetime

    import numpy as np

    from seal_cli.maps.model import Map
    from seal_cli.sefm.filter import Observer, SeFM, SeFMConfig
    from seal_cli.sim.agent import Agent, Budget, Policy, Record, Result

__all__ = ["frames_to_localise", "localise", "parse", "plan", "run_on_map"]


def _or_standard(library: Library | None) -> Library:
    return standard_library() if library is None else library


def parse(text: str, library: Library | None = None, vocabulary: Vocabulary | None = None) -> Parse:
    """The frames a command evokes, with their elements (and, with a vocabulary, the classes they denote)."""
    return parse_command(text, _or_standard(library), vocabulary)


def plan(text: str, library: Library | None = None, *, holding: str | None = None, done: Sequence[str] = (),
         map: Map | None = None, vocabulary: Any = None, max_nodes: int = MAX_NODES) -> Plan:
    """Parse a command, ground it in the robot's state and the map (:mod:`seal_cli.planning.problem`), plan it.

    ``holding``: what the robot holds; ``done``: commands already carried out, in order. On a map, a condition the
    robot checks first ("*if Tom is in the garage*, give him the hammer") is the plan's ``check``: the look that
    answers it, before the steps ``seal run`` carries out only when it holds."""
    library = _or_standard(library)
    problem = problem_of_text(text, library, holding=holding, done=done, map=map, vocabulary=vocabulary)
    found = planning.plan(problem.commanded, library, problem.state, max_nodes=max_nodes, text=text)
    found = replace(found, warnings=(*problem.warnings, *found.warnings)) if problem.warnings else found
    from seal_cli.planning.conditions import may_be_checked

    if map is None or not may_be_checked(text):
        return found
    words = vocabulary_of_map(map) if vocabulary is None else vocabulary      # as problem_of_text parsed it
    condition, check = _condition_check(parse_to_plan(text, library, words), library, words, map)
    if condition is None or check is None:
        return found
    return replace(found, check=replace(condition, looks=tuple(str(b) for b in check[1].commanded)))


def frames_to_localise(tasks: Sequence[str], library: Library, map: Map, *, holding: str | None = None,
                       done: Sequence[str] = ()) -> tuple[list[Binding], State]:
    """Every distinct grounded frame of the tasks' plans, in order, and the state they start from:
    what ``seal localize`` keeps beliefs over.

    Plans are made from what the robot knows (:meth:`Map.known <seal_cli.maps.model.Map.known>`): never
    from the map's ground-truth objects, which only simulate what it sees. Without a task, the
    state is the one the map, the hand and the commands already done leave.
    """
    vocabulary = vocabulary_of_map(map)
    known = map.known()
    bindings: list[Binding] = []
    state: State | None = None
    for text in tasks:
        found = plan(text, library, holding=holding, done=tuple(done), map=known, vocabulary=vocabulary)
        state = state or found.initial
        bindings.extend(b for b in found.bindings if b not in bindings)
    if state is not None:
        return bindings, state
    if not done:
        things = Things(library.taxonomy, known)
        things.hold(holding)
        return bindings, things.state()
    with naming_done(done, ""):     # the last --done is parsed as the command: a refusal in it names it (hostile26)
        problem = problem_of_text(done[-1], library, holding=holding, done=tuple(done[:-1]), map=known,
                                  vocabulary=vocabulary)
    state = problem.state
    for binding in problem.commanded:
        state = state.apply(binding)
    return bindings, state


def localise(map: Map, tasks: Sequence[str], library: Library | None = None, *, rng: np.random.Generator,
             config: SeFMConfig | None = None, observers: Sequence[Observer] = (), holding: str | None = None,
             done: Sequence[str] = ()) -> SeFM:
    """SeFM over every frame of the tasks' plans on a map (:func:`frames_to_localise`), ready for
    :meth:`~seal_cli.sefm.filter.SeFM.update`. Without a task it believes in every class of the map's
    priors and places (what ``seal localize`` does)."""
    from seal_cli.sefm.filter import SeFM

    library = _or_standard(library)
    bindings, state = frames_to_localise(tasks, library, map, holding=holding, done=done)
    classes = () if bindings else map.classes
    return SeFM(map, bindings, state, rng, config, observers, classes=classes)


def unchecked_conditions(parse: Any) -> list[str]:
    """A warning for each frame said under a condition on the world ("*when the water boils*, turn
    off the stove"): the parse keeps the condition, but the simulated robot cannot sense it, so
    ``seal run`` carries the frame out at once rather than drop what was said without a word."""
    return [f"{frame.frame} ('{frame.lexical_unit}') is said with the condition '{frame.condition}', "
            "which seal run cannot check: it carries the frame out now" for frame in parse.frames if frame.condition]


def inferred_steps(parse: Any) -> list[str]:
    """A note for each frame the parse inferred rather than read (:mod:`seal_cli.language.steps`: the
    step a sentence most likely leaves unsaid; :mod:`seal_cli.language.stacking`: one thing put in the
    other it was said with; :mod:`seal_cli.language.slicing`: the slice it leaves unsaid), so that
    ``seal run`` says what it adds on its own."""
    return [f"(inferred: {_inferred_act(frame)}, {frame.inferred:.2f})" for frame in parse.frames
            if getattr(frame, "inferred", None) is not None]


def _inferred_act(frame: Any) -> str:
    """What an inferred frame does, in words: "cool it first" (a step), "put the apple in the fridge"."""
    theme, goal = frame.elements.get("theme"), frame.elements.get("goal")
    if frame.frame == "Place" and theme is not None and goal is not None:
        return f"{frame.lexical_unit} {theme.text or theme.head} in {goal.text or 'the ' + goal.head}"
    if frame.frame == "LookAt" and theme is not None:      # :mod:`seal_cli.language.tasks`: looked at last
        return f"{frame.lexical_unit} {theme.text or theme.head}"
    return f"{frame.lexical_unit} it first"


def run_on_map(m: Map, text: str, library: Library, policy: Policy, *, rng: np.random.Generator,
               holding: str | None = None, done: Sequence[str] = (), vocabulary: Any = None,
               budget: Budget | None = None, observers: Sequence[Callable[[Record], None]] = (),
               clock: datetime | None = None, search_end: float | None = SEARCH_END) -> tuple[Agent, Result]:
    """Carry out a command on a map whose ground-truth objects are the world (``seal run``).

    The command and the ``done`` commands (already carried out) are parsed with the map's
    vocabulary — or ``vocabulary``, restricted to the map's classes — and grounded on what the
    robot knows of the map (its rooms, places and people: :mod:`seal_cli.planning.grounding`),
    without the map's objects, which the robot must find; ``holding`` overrides what the map's
    robot holds. A room or a fixed thing the map lacks raises SealError before anything moves; a
    kind of thing the map knows nothing of is warned about and searched for in the whole house.
    A question (:mod:`seal_cli.planning.questions`) is answered from what the robot sees; ``clock`` is
    what the robot's clock reads at the start (None: the computer's), for "tell Anna the time". A search
    for a kind of thing the map has a prior of ends, not found, once less than ``search_end`` of that
    prior is left unsearched (:mod:`seal_cli.sim.unsearched`; None: only the budget ends it). Where the
    command says a thing is ("a beer from the fridge": the robot knows no object, so a frame's source is
    the speaker's word) is evidence the search weighs (:attr:`Agent.told <seal_cli.sim.agent.Agent.told>`, read
    off the robot's own first plan).
    """
    from seal_cli.maps.model import Robot
    from seal_cli.planning.grounding import MapNames
    from seal_cli.planning.keeping import back_where_taken, where_kept
    from seal_cli.planning.lying import unseen_there
    from seal_cli.planning.questions import read_questions
    from seal_cli.sim.agent import Agent, scene_from_map
    from seal_cli.sim.policies import make_policy

    if holding is not None:
        m.check_holding(holding)
        m = replace(m, robot=Robot(m.robot.pose, holding))
    known = vocabulary_of_map(m)
    vocabulary = known if vocabulary is None else replace(vocabulary.restricted_to(known.classes), house=True)
    known_map = m.known()     # once: a map checks itself when made (0.1 s), and --done may hold 1,000 commands
    with naming_done(done, text):
        parses = [parse_to_plan(t, library, vocabulary) for t in (*done, text)]
        drawn = m
        if done:                # the house as the done commands left it; the robot knows what it handled (e2e30)
            m, known_map = _after_done(m, parses[:-1], library, holding, known_map)
        problem = build_problem(parses[-1], library, holding=holding, done=parses[:-1], map=known_map,
                                vocabulary=vocabulary)
    questions = read_questions(parses[-1], problem.commanded, MapNames(m, library.taxonomy))
    condition, check = _condition_check(parses[-1], library, vocabulary, m)
    if check is not None:
        questions |= read_questions(check[0], check[1].commanded, MapNames(m, library.taxonomy))
    kept = {b: where_kept(library.taxonomy, m, problem.state.class_of(b.elements["theme"])) for b in problem.put_away}
    kept |= {b: back_where_taken for b in problem.put_back}
    agent = Agent(scene_from_map(m, library), library, policy, rng=rng, budget=budget, observers=observers,
                  classes={**(check[1].state.classes if check else {}), **problem.state.classes},
                  sweeper=lambda: make_policy("coverage"), questions=questions,
                  clock=clock, search_end=search_end, put_away=kept, put_back=problem.put_back,
                  heed_sources=True, names=problem.names, absent_said=True, among=problem.among,
                  one_away=problem.one_away, nearest=problem.nearest)
    executed = list(problem.done)     # grounded in order, each after the ones before it ("put it on the table")
    agent.remember(left_by_done(drawn, m))     # it moved them itself: it knows where it left them (e2e31)
    warnings = [*problem.warnings, *(unchecked_conditions(parses[-1]) if check is None else [])]
    for warning in warnings:
        agent.say("warn", f"warning: {warning}")
    notes = inferred_steps(parses[-1])
    for note in notes:
        agent.say("warn", note)
    for note in unseen_there(problem.commanded, m, problem.state.class_of, known_map):   # why it may search (e2e28)
        agent.say("plan", note)
    if check is not None and condition is not None:
        agent.say("plan", f"checks first whether {condition.said.split(None, 1)[1]}: {condition.question}")
        first = agent.run(check[1].commanded, done=executed)
        holds = first.completed and (first.answer or "").lower().startswith("yes")
        if not holds:
            if first.completed:
                acts = " or ".join(dict.fromkeys(f.lexical_unit for f in parses[-1].frames))
                first.reason = (f"'{condition.said}' does not hold ({first.answer or first.reason}), so it did not "
                                f"{acts} (the command's condition)")
                agent.say("done", first.reason)
            first.warnings = [*warnings, *notes]
            return agent, first
        agent.told = {}         # what the check's question said of where things are is no word of the command
    if (every := _every_seen(agent, parses[-1], library, vocabulary, m)) is not None:
        if not every[0].completed:
            return agent, every[0]
        with naming_done(done, text):
            problem = build_problem(parses[-1], library, holding=holding, done=parses[:-1], map=m.known(),
                                    vocabulary=vocabulary, every=every[1])
        agent.classes.update({class_key(k): class_key(v) for k, v in problem.state.classes.items()})
        agent.say("plan", "then " + ", ".join(f"every {k.replace('_', ' ')} it saw ({n})" for k, n in every[1].items()))
    result = agent.run(problem.commanded, done=executed)
    result.warnings = [*warnings, *notes]
    return agent, result


def _after_done(m: Map, done: Sequence[Parse], library: Library, holding: str | None,
                known: Map) -> tuple[Map, Map]:
    """The world the done commands left (:func:`~seal_cli.planning.aftermath.world_after`), and what the robot knows
    of the map before them: ``known`` and the objects they handled, where the map drew them (the plan replays the done
    commands on those)."""
    from seal_cli.planning.aftermath import handled, world_after
    from seal_cli.planning.problem import carry_out_done

    things = Things(library.taxonomy, m)
    things.hold(holding)
    carry_out_done(done, library, things)
    remembered = handled(m, things)
    return world_after(m, things), replace(known, objects=remembered) if remembered else known


def left_by_done(drawn: Map, after: Map) -> list[str]:
    """The world's ids (as :func:`~seal_cli.sim.agent.scene_from_map` names them) of the objects the done commands
    left somewhere other than where the map drew them: the robot moved them, so it knows where they lie (e2e31: after
    `--done 'take the catalogue to Anna'`, "where is the catalogue?" searched the showroom, workshop, finishing room
    and kitchen by the prior and said none was found; the catalogue was with Anna in the office)."""
    counts: dict[str, int] = {}
    ids = []
    for o in after.objects:
        counts[o.cls] = counts.get(o.cls, 0) + 1
        if o not in drawn.objects:
            ids.append(f"{o.cls}_{counts[o.cls]}")
    return ids


def _every_seen(agent: Any, parse: Parse, library: Library, vocabulary: Any,
                m: Map) -> tuple[Any, dict[str, int]] | None:
    """"put all the cups in the sink" on a map whose robot knows no object until it sees it (e2e23): it counts
    them first, and the command is then every one it saw (at least one); the count's result, and how many of each
    kind. The count looks where the map's priors keep the kind (e2e24: the cupboard and the sink for the plates,
    :meth:`~seal_cli.sim.agent.Agent.kept_spots`), and all over the house, as "count all the cups" does, for a kind
    the map has no prior of. None when the command asks for no "all"."""
    from seal_cli.planning.grounding import MapNames
    from seal_cli.planning.problem import every_said
    from seal_cli.planning.questions import read_questions

    phrases = every_said(parse)
    if not phrases or not m.rooms:
        return None
    counted: dict[str, int] = {}
    result = None
    for phrase in phrases:
        count = parse_to_plan(f"count {phrase.text}", library, vocabulary)
        problem = build_problem(count, library, map=m.known(), vocabulary=vocabulary)
        if [b.frame.name for b in problem.commanded] != ["Count"]:
            continue
        agent.questions.update(read_questions(count, problem.commanded, MapNames(m, library.taxonomy)))
        agent.classes.update({class_key(k): class_key(v) for k, v in problem.state.classes.items()})
        key = class_key(problem.commanded[0].elements["theme"])
        agent.kept.add(key)
        where = "looks where the map keeps them" if agent.kept_spots(key) else "looks all over the house"
        agent.say("plan", f"counts first: {phrase.text} ({where})")
        result = agent.run(problem.commanded)
        if not result.completed:
            return result, counted
        counted[key] = max(1, sum(1 for k in agent.known.values() if k.cls == key and k.id in agent.world.items))
    return None if result is None else (result, counted)


def _condition_check(parse: Parse, library: Library, vocabulary: Any, m: Map) -> tuple[Any, Any]:
    """The condition every frame of a parse is said under, when the robot checks it by looking
    (:mod:`seal_cli.planning.conditions`: "if Tom is in the garage", "if the fridge is open"), with its question's
    parse and problem (one Find: "is Tom in the garage?", or one LookAt: "is the fridge open?"); (None, None) when
    there is none, or the question plans to anything else (:func:`_checks`)."""
    from seal_cli.errors import SealError
    from seal_cli.planning.conditions import checked_condition

    condition = checked_condition(parse.frames)
    if condition is None:
        return None, None
    try:
        asked = parse_to_plan(condition.question, library, vocabulary)
        check = build_problem(asked, library, map=m.known(), vocabulary=vocabulary)
    except SealError:
        return None, None
    if not _checks(asked, check):
        return None, None
    return condition, (asked, check)


def _checks(asked: Parse, check: Any) -> bool:
    """Whether a condition's question plans to one look that answers it: a Find of the thing with where it is
    said to be as its ground ("is Tom in the garage?"), or a LookAt of a thing with the state asked ("is the
    fridge open?")."""
    frames = [b.frame.name for b in check.commanded]
    if frames == ["Find"]:
        return "ground" in check.commanded[0].elements
    return frames == ["LookAt"] and len(asked.frames) == 1 and bool(getattr(asked.frames[0], "asked", None))
