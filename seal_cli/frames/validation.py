"""Checks that make a frame library correct as a whole.

The readers already refuse what is wrong inside one frame (a fact naming an element the frame
lacks, a repeated element). These checks look across frames and types, and return *every*
problem rather than stopping at the first:

- duplicate frame names;
- an element typed with an unknown category, or a default outside its category;
- an action that is not a known primitive, or has the wrong number of arguments;
- a predicate used with different numbers of arguments;
- a precondition that no frame's postcondition achieves and that is not a world fact (a negated one, `not f(x)`,
  holds in the closed world until something makes `f(x)` true: it needs no achiever);
- preconditions that can only be achieved in a cycle (A needs what only B gives, B needs what only A gives);
- two frames claiming the same lexical unit with the same element pattern (the parser could not choose);
- a synonym claimed by two classes, or naming a category (grounding could not choose).
"""

from __future__ import annotations

import difflib
from collections.abc import Iterable, Iterator, Sequence

from seal_cli.errors import SealError
from seal_cli.frames.actions import PRIMITIVES
from seal_cli.frames.model import Fact, Frame
from seal_cli.frames.taxonomy import Synonyms, Taxonomy, class_key

__all__ = ["check_library"]


def check_library(frames: Sequence[Frame], taxonomy: Taxonomy) -> list[SealError]:
    """Every cross-frame problem in these frames, in source order."""
    checks = (_duplicates(frames), _types(frames, taxonomy), _actions(frames), _arities(frames),
              _unachieved(frames, taxonomy), _cycles(frames, taxonomy), _unit_clashes(frames),
              _synonym_clashes(taxonomy), _category_cycles(taxonomy))
    return [problem for check in checks for problem in check]


def _at(frame: Frame) -> str:
    return f" (at {frame.where})" if frame.where and frame.where.line else ""


def _duplicates(frames: Sequence[Frame]) -> Iterator[SealError]:
    first: dict[str, Frame] = {}
    for frame in frames:
        if frame.name in first:
            yield SealError(f"duplicate frame name {frame.name!r}: already defined{_at(first[frame.name])}",
                            frame.where)
        else:
            first[frame.name] = frame


def _suggest(word: str, choices: Iterable[str]) -> str:
    close = difflib.get_close_matches(word, sorted(set(choices) - {word}), n=1)
    return f" (did you mean {close[0]!r}?)" if close else ""


def _types(frames: Sequence[Frame], taxonomy: Taxonomy) -> Iterator[SealError]:
    known = set(taxonomy.by_name)
    for frame in frames:
        for element in frame.elements:
            if class_key(element.type) not in known:
                listing = ", ".join(sorted(known)) if known else "none (declare categories in a types file)"
                yield SealError(f"{frame.name}.{element.role} has unknown category {element.type!r}"
                                f"{_suggest(class_key(element.type), known)}; known categories: {listing}",
                                element.where)
            elif element.default is not None and taxonomy.is_a(element.default, element.type) is not True:
                members = sorted(taxonomy.members(element.type))
                yield SealError(f"{frame.name}.{element.role} defaults to {element.default!r}, which is not a "
                                f"{element.type} (its members: {', '.join(members) or 'none'})", element.where)


def _actions(frames: Sequence[Frame]) -> Iterator[SealError]:
    for frame in frames:
        for action in frame.actions:
            primitive = PRIMITIVES.get(action.name)
            if primitive is None:
                yield SealError(f"{frame.name} uses unknown action {action.name!r}"
                                f"{_suggest(action.name, PRIMITIVES)}; known actions: {', '.join(PRIMITIVES)}",
                                action.where)
            elif len(action.args) != primitive.arity:
                yield SealError(f"action {action.name} takes {primitive.arity} argument"
                                f"{'s' if primitive.arity != 1 else ''} ({', '.join(primitive.params)}), "
                                f"not {len(action.args)}: {action}", action.where)


def _facts(frame: Frame) -> Iterator[Fact]:
    yield from frame.preconditions
    yield from frame.postconditions


def _arities(frames: Sequence[Frame]) -> Iterator[SealError]:
    first: dict[str, tuple[Fact, Frame]] = {}
    for frame in frames:
        for fact in _facts(frame):
            seen = first.setdefault(fact.predicate, (fact, frame))
            if len(seen[0].args) != len(fact.args):
                yield SealError(f"{fact.predicate} takes {len(seen[0].args)} argument(s) in {seen[1].name} "
                                f"({seen[0].positive}) but {len(fact.args)} here: {fact}", fact.where)


def _is_world(fact: Fact, taxonomy: Taxonomy) -> bool:
    """World facts need no frame: declared world predicates and category tests (``openable(x)``)."""
    return fact.predicate in taxonomy.world or (len(fact.args) == 1 and fact.predicate in taxonomy)


def _unachieved(frames: Sequence[Frame], taxonomy: Taxonomy) -> Iterator[SealError]:
    achieved = {_key(p) for f in frames for p in f.postconditions}
    produced = sorted({p.predicate for f in frames for p in f.postconditions if not p.negated})
    for frame in frames:
        for fact in frame.preconditions:
            if not _is_world(fact, taxonomy) and not fact.negated and _key(fact) not in achieved:
                yield SealError(f"precondition {fact} of {frame.name} is achieved by no frame's postcondition "
                                f"and is not a world fact{_near(fact, achieved, produced)}; "
                                "declare it under 'world:' if the world or robot provides it", fact.where)


def _near(fact: Fact, achieved: set[tuple[str, bool, int]], produced: Sequence[str]) -> str:
    """What a frame does achieve of this predicate (another sign or number of arguments), else a
    close name."""
    forms = sorted((negated, arity) for name, negated, arity in achieved if name == fact.predicate)
    if not forms:
        return _suggest(fact.predicate, produced)
    said = " or ".join(f"{'not ' if negated else ''}{fact.predicate} with {arity} argument{'s' * (arity != 1)}"
                       for negated, arity in forms)
    return f" (frames achieve only {said})"


def _key(fact: Fact) -> tuple[str, bool, int]:
    """What achieving a fact takes: a postcondition of its predicate, sign and arity."""
    return (fact.predicate, fact.negated, len(fact.args))


def _cycles(frames: Sequence[Frame], taxonomy: Taxonomy) -> Iterator[SealError]:
    """Frames that can never run because what they need is only given by frames that need them.

    Linear in the size of the library: which frames can run is found by counting unmet needs (as
    Horn clauses are solved), and the cycles among the rest are the strongly connected components
    of the graph frame → need → achiever (Tarjan)."""
    unique = {f.name: f for f in frames}
    needs = {name: {_key(fact) for fact in f.preconditions if not _is_world(fact, taxonomy) and not fact.negated}
             for name, f in unique.items()}
    achievers: dict[tuple[str, bool, int], list[str]] = {}
    for name, frame in unique.items():
        for key in dict.fromkeys(_key(p) for p in frame.postconditions):
            achievers.setdefault(key, []).append(name)
    runnable = _runnable(unique, needs)
    stuck = [name for name in unique if name not in runnable and all(key in achievers for key in needs[name])]
    stuck_set = set(stuck)
    edges = {name: [other for key in sorted(needs[name]) for other in achievers[key] if other in stuck_set]
             for name in stuck}
    for component in _components(stuck, edges):
        yield SealError(f"precondition cycle: {_round(component, edges)}; none of these frames can ever run, because "
                        "each needs what only another one in the cycle achieves", unique[component[0]].where)


def _runnable(frames: dict[str, Frame], needs: dict[str, set[tuple[str, bool, int]]]) -> set[str]:
    """The frames that can run from the world facts alone or after other runnable frames."""
    unmet = {name: len(keys) for name, keys in needs.items()}
    waiting: dict[tuple[str, bool, int], list[str]] = {}
    for name, keys in needs.items():
        for key in keys:
            waiting.setdefault(key, []).append(name)
    ready = [name for name, count in unmet.items() if count == 0]
    runnable: set[str] = set(ready)
    achieved: set[tuple[str, bool, int]] = set()
    while ready:
        for key in {_key(p) for p in frames[ready.pop()].postconditions} - achieved:
            achieved.add(key)
            for other in waiting.get(key, ()):
                unmet[other] -= 1
                if unmet[other] == 0:
                    runnable.add(other)
                    ready.append(other)
    return runnable


def _components(nodes: list[str], edges: dict[str, list[str]]) -> list[list[str]]:
    """Tarjan's strongly connected components with a cycle (more than one node, or a self-loop),
    each in ``nodes`` order; iterative, so a 10,000-frame chain needs no deep recursion."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    found: list[list[str]] = []
    order = {n: k for k, n in enumerate(nodes)}
    for root in nodes:
        if root in index:
            continue
        work = [(root, 0)]
        while work:
            node, i = work.pop()
            if i == 0:
                index[node] = low[node] = len(index)
                stack.append(node)
                on_stack.add(node)
            if i < len(edges[node]):
                work.append((node, i + 1))
                other = edges[node][i]
                if other not in index:
                    work.append((other, 0))
                elif other in on_stack:
                    low[node] = min(low[node], index[other])
                continue
            if low[node] == index[node]:
                members = []
                while True:
                    member = stack.pop()
                    on_stack.discard(member)
                    members.append(member)
                    if member == node:
                        break
                if len(members) > 1 or node in edges[node]:
                    found.append(sorted(members, key=order.__getitem__))
            if work:
                parent = work[-1][0]
                low[parent] = min(low[parent], low[node])
    return found


WHOLE = 30
"""The most frames (or categories) a cycle is said through, every one: a larger knot of them that need one another
is said by one loop through its first and how many more there are (a way round 5,000 frames took 10 s to find and
would be no message to read)."""


def _round(component: list[str], edges: dict[str, list[str]]) -> str:
    """The component said as a way round it from its first member and back, through every member: the shortest
    way to the nearest one not yet passed, again and again, then home (a member passed twice where no simple cycle
    holds them all: "Zap → Bop → Zap → Cop → Zap"). A member's need of what it achieves itself is no step of it when
    the component holds others: a cycle of three where one frame also needs its own was said "Zap → Zap", naming
    one frame of the three (hostile32). Past :data:`WHOLE` members, the shortest loop through the first and the
    count of the rest."""
    start = component[0]
    if len(component) == 1:
        return f"{start} → {start}"
    inside = set(component)
    steps = {name: [other for other in edges[name] if other != name and other in inside] for name in component}
    if len(component) > WHOLE:
        loop = [start, *_shortest_way(start, {start}, steps)]
        on = set(loop)
        others = [name for name in component if name not in on]
        more = f" (and {len(others):,} more of the same knot: {', '.join(others[:3])}{', …' * (len(others) > 3)})"
        return " → ".join(loop) + (more if others else "")
    walk, here, left = [start], start, inside - {start}
    while left:
        way = _shortest_way(here, left, steps)
        walk += way
        here = way[-1]
        left -= set(way)
    return " → ".join(walk + _shortest_way(here, {start}, steps))


def _shortest_way(start: str, goals: set[str], steps: dict[str, list[str]]) -> list[str]:
    """The frames after ``start`` on a shortest way to one of ``goals`` (``start`` itself may be one: the way
    back), the first found in the edges' order; ``steps`` is strongly connected, so there is one."""
    previous: dict[str, str] = {}
    seen, frontier = {start}, [start]
    while frontier:
        following = []
        for name in frontier:
            for other in steps[name]:
                if other in goals:
                    way = [other, name]
                    while way[-1] != start:
                        way.append(previous[way[-1]])
                    return way[::-1][1:]
                if other not in seen:
                    seen.add(other)
                    previous[other] = name
                    following.append(other)
        frontier = following
    raise AssertionError(f"no way from {start} to {sorted(goals)} inside a strongly connected component")


def _category_cycles(taxonomy: Taxonomy) -> Iterator[SealError]:
    """Categories that contain themselves through other categories (``a: [b]``, ``b: [a]``); a
    category listing its own name (``person: [person, ...]``) names the class of that name."""
    by_name = taxonomy.by_name
    names = list(by_name)
    edges = {name: [class_key(m) for m in by_name[name].members or () if class_key(m) in by_name
                    and class_key(m) != name] for name in names}
    for component in _components(names, edges):
        yield SealError(f"category cycle: {_round(component, edges)}; a category cannot contain itself",
                        by_name[component[0]].where)


def _pattern(frame: Frame) -> frozenset[tuple[str, str]]:
    return frozenset((e.role, class_key(e.type)) for e in frame.elements)


def _unit_clashes(frames: Sequence[Frame]) -> Iterator[SealError]:
    claimed: dict[tuple[str, frozenset[tuple[str, str]]], Frame] = {}
    for frame in frames:
        for unit in frame.lexical_units:
            key = (unit.text, _pattern(frame))
            other = claimed.setdefault(key, frame)
            if other is not frame and other.name != frame.name:
                yield SealError(f"lexical unit {unit.text!r} of {frame.name} is also claimed by {other.name}"
                                f"{_at(other)} with the same elements ({', '.join(sorted(frame.roles))}); "
                                "the parser could not tell them apart", unit.where)


def _synonym_clashes(taxonomy: Taxonomy) -> Iterator[SealError]:
    """A name is one class's: two entries of different classes may not share one, and a category
    (``furniture``) is no other name of a class."""
    owner: dict[str, Synonyms] = {}
    for entry in taxonomy.synonyms:
        for name in entry.all_names:
            other = owner.setdefault(name, entry)
            if other.name != entry.name:
                where = f" (at {other.where})" if other.where and other.where.line else ""
                yield SealError(f"{name!r} is a name of both {other.name}{where} and {entry.name}; "
                                "a name may denote one class only", entry.where)
            elif name in taxonomy.by_name and name != entry.name:
                yield SealError(f"{name!r} is a category, not another name of {entry.name}", entry.where)


# -- checking files as a user hands them over ---------------------------------------------------
