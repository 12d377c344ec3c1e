#!/usr/bin/env python3
"""Rebuild ``seal_cli/bench/suites/saycan_examples.json``: the worked examples of the SayCan baseline's prompt.

SayCan's prompt (Ahn et al. 2022) opens with a few worked examples, each an instruction and the
robot's skills for it, one a line, ending with "done"; the language model continues the pattern.
Here the examples are ALFRED *train* trials: the instruction is the trial's gold sentence (the same
plain sentence :func:`seal_cli.sim.skills.gold_instruction` writes) and, separately, its first
human goal sentence; the skills are the expert's high-level plan (``high_pddl``) written in the
runner's skill words:

- ``PickupObject o`` → "find the o", "pick up the o" (the expert's ``GotoLocation`` went where it knew
  the thing was; the runner's "find" goes to a seen one or searches);
- ``SliceObject o`` → "find the o", "slice the o with the K" (K: the thing in hand);
- ``PutObject o r`` → "go to the r" (or "find the r" for a movable receptacle), "open the r" if it
  opens, "put the o in the r"; where o is not what the task moves (the knife, put away after
  slicing) → "put down the o", as in SayCan's skills;
- ``Heat/Cool/CleanObject o`` → "go to the microwave / fridge / sink basin", "heat / cool / clean the o
  with the ...";
- ``ToggleObject x`` → "go to the x", "turn on the x"; ``NoOp`` → "done".

Each example also lists its *slots*: the task's labelled classes (object, movable receptacle,
receptacle, toggle target, and the knife a sliced task names) in the order the instruction names
them; a human sentence that does not name every label in the class's own words is not used. Where
the instruction says "a knife" and the expert took a butter knife, the steps say "knife": the
example is read as the instruction says it. Per task type, the first ``--per-type`` trials
whose plan is complete, in the order of a hash of their id (another hash than ``seal bench tasks
--sample``'s, so the sampled train episodes are not the examples), and ``--sliced`` more with a
sliced object where the type has them.

    python scripts/build_saycan_examples.py            # rewrite the shipped file
    python scripts/build_saycan_examples.py --check    # exit 1 if the shipped file differs
"""

from __future__ import annotations

import argparse
import json
import re
import sys
import zlib
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from seal_cli.bench.alfred2d import TASK_TYPES, read_floorplans  # noqa: E402
from seal_cli.frames.taxonomy import class_key  # noqa: E402
from seal_cli.sim.skills import gold_instruction, words  # noqa: E402

OUT = ROOT / "seal_cli" / "bench" / "suites" / "saycan_examples.json"
APPLIANCE = {"HeatObject": ("heat", "microwave"), "CoolObject": ("cool", "fridge"),
             "CleanObject": ("clean", "sink_basin")}


def steps_of(pddl: list[dict[str, Any]], name: dict[str, str], openable: set[str], movable: set[str],
             goals: set[str]) -> list[str]:
    out: list[str] = []
    held: str | None = None

    def approach(cls: str) -> None:
        line = f"find the {words(cls)}" if cls in movable else f"go to the {words(cls)}"
        if not out or out[-1] != line:
            out.append(line)

    for action in pddl:
        kind, args = action["action"], [name[a] for a in action.get("args", ())]
        if kind == "PickupObject":
            approach(args[0])
            out.append(f"pick up the {words(args[0])}")
            held = args[0]
        elif kind == "SliceObject":
            approach(args[0])
            out.append(f"slice the {words(args[0])} with the {words(held or 'knife')}")
        elif kind == "PutObject" and args[0] not in goals:   # the knife, once it has sliced: out of the way
            out.append(f"put down the {words(args[0])}")
            held = None
        elif kind == "PutObject":
            obj, target = args
            approach(target)
            if target in openable:
                out.append(f"open the {words(target)}")
            out.append(f"put the {words(obj)} in the {words(target)}")
            held = None
        elif kind in APPLIANCE:
            verb, appliance = APPLIANCE[kind]
            approach(appliance)
            out.append(f"{verb} the {words(args[0])} with the {words(appliance)}")
        elif kind == "ToggleObject":
            approach(args[0])
            out.append(f"turn on the {words(args[0])}")
        elif kind == "NoOp":
            out.append("done")
    if not out or out[-1] != "done":
        out.append("done")
    return out


def complete(pddl: list[dict[str, Any]], task: dict[str, Any], name: dict[str, str]) -> bool:
    """The plan ends with the task's last goal: the put into its receptacle, or the lamp switched on
    (a few trials' plans stop early)."""
    if any(a not in name for action in pddl for a in action.get("args", ())):
        return False   # a class this data's floor plans do not name
    last = [a for a in pddl if a["action"] != "NoOp"][-1:]
    if not last:
        return False
    args = [name[a] for a in last[0].get("args", ())]
    if task.get("receptacle"):
        return last[0]["action"] == "PutObject" and args[-1:] == [class_key(task["receptacle"])]
    return last[0]["action"] == "ToggleObject"


def slot_order(text: str, slots: list[str]) -> list[str] | None:
    """The slots in the order the text names them (whole words, plurals folded); None if one is missing."""
    low = " " + " ".join(re.findall(r"[a-z0-9]+", text.lower())) + " "
    found = []
    for slot in dict.fromkeys(slots):
        m = re.search(rf" {re.escape(slot)}(s|es)? ", low)
        if m is None:
            return None
        found.append((m.start(), slot))
    return [s for _, s in sorted(found)]


def build(data: Path, per_type: int, sliced: int) -> dict[str, Any]:
    plans, movable_raw = read_floorplans(data)
    classes = {c for p in plans.values() for c in [*(r.cls for r in p.receptacles), *p.object_types]}
    classes |= set(movable_raw)
    name = {c.lower(): class_key(c) for c in classes}
    openable = {class_key(r.cls) for p in plans.values() for r in p.receptacles if r.openable}
    movable = {class_key(c) for c in movable_raw}
    trials = [json.loads(line) for line in (data / "trials_train.jsonl").open(encoding="utf-8")]
    trials.sort(key=lambda t: zlib.crc32(("saycan examples " + t["task_id"]).encode()))  # not --sample's order
    examples: list[dict[str, Any]] = []
    for kind in TASK_TYPES:
        of_kind = [t for t in trials if t["task"]["type"] == kind]
        usable = [t for t in of_kind if complete(t["expert"]["high_pddl"], t["task"], name)]
        chosen = [t for t in usable if not t["task"]["sliced"]][:per_type] + \
            [t for t in usable if t["task"]["sliced"]][:sliced]
        for t in chosen:
            task = t["task"]
            labels = [words(class_key(task[k])) for k in ("object", "mrecep", "receptacle", "toggle") if task.get(k)]
            goals = {class_key(task[k]) for k in ("object", "mrecep") if task.get(k)}
            steps = steps_of(t["expert"]["high_pddl"], name, openable, movable, goals)
            gold = gold_instruction(kind, task["object"], task.get("receptacle"), task.get("mrecep"),
                                    task.get("toggle"), bool(task.get("sliced")))
            for source, text in (("gold", gold), ("human", (t.get("goals") or [""])[0].strip())):
                said = steps
                if slot_order(text, ["knife"]) and not slot_order(text, ["butter knife"]):
                    said = [re.sub(r"\bbutter knife\b", "knife", s) for s in steps]   # the knife it names
                order = slot_order(text, labels + (["knife"] if task.get("sliced") else []))
                if order is not None or (order := slot_order(text, labels)) is not None:
                    examples.append({"trial": t["task_id"], "type": kind, "source": source, "instruction": text,
                                     "slots": order, "steps": said})
    return {"format": "seal saycan examples v1",
            "source": "ALFRED train trials, expert high_pddl; rebuilt by scripts/build_saycan_examples.py",
            "examples": examples}


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--data", type=Path, default=ROOT.parent / "shared" / "data" / "alfred2d")
    parser.add_argument("--per-type", type=int, default=4)
    parser.add_argument("--sliced", type=int, default=2)
    parser.add_argument("--check", action="store_true")
    args = parser.parse_args()
    text = json.dumps(build(args.data, args.per_type, args.sliced), indent=1) + "\n"
    if args.check:
        same = OUT.is_file() and OUT.read_text(encoding="utf-8") == text
        print("up to date" if same else f"{OUT} differs from a rebuild")
        return 0 if same else 1
    OUT.write_text(text, encoding="utf-8")
    print(f"wrote {OUT}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
