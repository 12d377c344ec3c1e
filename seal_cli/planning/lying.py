"""A thing said to go where one of its kind lies already: what the command means, one rule for ``seal plan`` and
``seal run`` (e2e28).

- **The other one.** "put the book back on the shelf", a book on the shelf and one on the nightstand: the
  nightstand's is meant; nobody asks for what is so already (e2e27). Only where the goal is the map's one place of
  its class: with a fridge in the shop and one in the kitchen, a milk in each, "put the milk in the fridge" is no
  request for a third milk (:func:`another_meant`).
- **One of several places the command did not tell apart.** "put the milk in the fridge" there: the milk is in a
  fridge already, and the command said no more of which fridge; it needs no doing (the fridge it lies in is the
  goal, :func:`goal_among`). A user who means the other fridge says which ("the fridge in the kitchen").

The planner asks these of the map (:func:`seal_cli.planning.problem.the_ones_not_there`); ``seal run``'s robot, which
knows no thing until it sees it, asks the same of what it sees (:meth:`seal_cli.sim.agent.Agent.already_so`).
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Sequence
from typing import TYPE_CHECKING

from seal_cli.frames.model import Binding
from seal_cli.frames.taxonomy import class_key

if TYPE_CHECKING:
    from seal_cli.maps.model import Map

__all__ = ["another_meant", "goal_among", "several_said", "unseen_there"]


def several_said(bindings: Iterable[Binding], class_of: Callable[[str], str]) -> set[str]:
    """The classes the frames name several things of ("all the cups", "two plates", "a cup and another cup"): each
    of those is one of them, not the other one of a kind."""
    names: dict[str, set[str]] = {}
    for binding in bindings:
        for _, value in binding.values:
            names.setdefault(class_of(value), set()).add(class_key(value))
    return {cls for cls, said in names.items() if len(said) > 1}


def another_meant(binding: Binding, thing: str, kind: str, *, held: str | None, places_like_goal: int,
                  several: Iterable[str]) -> bool:
    """Whether a frame that would put ``thing`` (of class ``kind``) on or in its goal, a place where one of its kind
    lies already, means another one: the frame takes the thing up (it needs it held) as its theme, the robot holds
    none of its kind (it would put down the one it holds), the goal is the map's one place of its class
    (``places_like_goal``: how many places of the goal's class the map has), and the command names one thing of its
    kind (not one of ``several``). The caller knows that one lies there, and whether another is to be had."""
    return (binding.frame.needs_held("theme") and binding.elements.get("theme") == thing
            and held != kind and places_like_goal == 1 and kind not in set(several))


def goal_among(binding: Binding, thing: str, kind: str, *, held: str | None, among: Sequence[str],
               lies_in: Callable[[str], str | None]) -> str | None:
    """The place, of the ``among`` places the command's goal was one of and did not tell apart (several places of one
    class), that a thing of ``kind`` lies in already: what the frame asks is so there ("put the milk in the fridge",
    a milk in each fridge). ``lies_in(place)``: the thing of the kind lying in that place, or None. None when the
    frame does not take ``thing`` up as its theme, the robot holds one of its kind (it puts down the one it holds),
    or none lies in any of them. Of several, the one ``thing`` itself lies in, else the goal, else the first."""
    if (len(among) < 2 or not binding.frame.needs_held("theme") or binding.elements.get("theme") != thing
            or held == kind):
        return None
    goal = binding.elements.get("goal")
    lying = {p: lies_in(p) for p in among}     # the thing itself where it lies first, then the goal, then the others
    order = sorted(among, key=lambda p: (lying[p] != thing, p != goal))
    return next((p for p in order if lying[p] is not None), None)


def unseen_there(commanded: Sequence[Binding], m: Map, class_of: Callable[[str], str],
                 known: Map | None = None) -> list[str]:
    """What ``seal run``'s robot says before it drives, for each frame that would put a thing on or in the map's one
    place of its class where the map's prior expects such a thing: it cannot know before it looks whether one lies
    there already (it knows no thing until it sees it; the map's objects are the world it finds, which ``seal plan``
    reads), and if one does, the other-one rule sends it to look for another where the prior keeps such things before
    it can say the frame needs no doing (e2e28: "put the remote on the sofa" on the studio searched 21 m, silent on
    why). Nothing is said of a kind the robot knows a thing of (``known``: what it knows of the map, with the things the
    done commands handled, ``seal run --done``): it knows where that one lies (e2e31: "put it back" after `--done
    'bring the cup to the table'` said "it knows no cup until it sees one")."""
    from seal_cli.maps.priors import prior_of
    from seal_cli.planning.keeping import Spot, mass

    knows = {class_key(o.cls) for o in known.objects} if known is not None else set()
    said = []
    several = several_said(commanded, class_of)
    for binding in commanded:
        theme, goal = binding.elements.get("theme"), binding.elements.get("goal")
        place = m.place(goal) if goal else None
        if theme is None or place is None or not binding.frame.needs_held("theme") or class_of(theme) in several:
            continue
        if sum(1 for p in m.places if class_key(p.cls) == class_key(place.cls)) != 1:
            continue
        kind = class_of(theme)
        if class_key(kind) in knows:
            continue
        share = mass(prior_of(m.priors, kind), Spot(class_key(place.name), place.cls, place.room, place.at))
        if share > 0:
            words = kind.replace("_", " ")
            said.append(f"it knows no {words} until it sees one, and the map's prior puts one at {place.name} "
                        f"({share:.2f}): if one lies there already, it first looks for another {words} where such "
                        "things are kept")
    return said
