"""The offline translator for household commands: command + household world -> goal conditions.

Meaning before arithmetic, as for the warehouse: the parser (:mod:`pipflow.household.language.parser`, a
lark grammar over the world's names and a small lexicon) reads the command into *orders*, one per
reading of the sentence; the resolver (:mod:`pipflow.household.language.resolver`) turns an order into
goal conditions against this world, or refuses with the reason. When a sentence has several
readings, each is resolved: readings the world rules out are dropped, and if those left mean
different goals the command is refused as ambiguous, quoting both (never a silent pick).

Leaving things as found: a closed container that a plan must open (to put something in or take
something out) is closed again at the end unless the command says otherwise; the goal says so,
and the benchmark's ground truth lists the same condition. A thing whose switch or door
condition already holds (a torch already off in a closed chest, in "lights out") is not touched,
so its container is not opened and not listed (benchmarks/README.md).
"""
from __future__ import annotations

import json

from pipflow.errors import Refusal, TranslationError
from pipflow.household.language.candidates import candidate_readings
from pipflow.household.language.names import held
from pipflow.household.language.parser import parse
from pipflow.household.language.resolver import resolve
from pipflow.household.language.tagger import tags_kept
from pipflow.household.world import members
from pipflow.language.asides import said
from pipflow.language.characters import line_readings


#: readings offered at most when a command is refused as ambiguous
MAX_CANDIDATES = 3


def _leave_closed(world: dict, goal: dict) -> None:
    """Closed containers the plan must open are closed again unless the command said open."""
    # a thing kept where it already is ("don't touch the labneh") moves nothing: its place need not be opened
    kept = {(o, p) for p, items in goal.get("in", {}).items() for o in items
            if (world["objects"].get(o) or {}).get("in") == p}
    touched = {p for p, items in goal.get("in", {}).items() if any((o, p) not in kept for o in items)}
    moved = [o for p, items in goal.get("in", {}).items() for o in items if (o, p) not in kept]
    # a thing whose state already holds is not touched: its container need not be opened
    # (benchmarks/README.md: only a container the plan must open is expected closed again)
    named = moved + [o for o, conds in goal.get("state", {}).items()
                     if o in moved or not all(_already(world, o, c) for c in conds)]
    touched |= {world["objects"][o]["in"] for o in named if o in world["objects"]}
    touched |= {c["in"] for c in goal.get("count", [])}
    # a thing heated where the command does not say: when the home has one heater and it opens,
    # the plan opens it to put the thing in
    heaters = [p for p, e in world["places"].items() if "heater" in e["properties"]]
    heated = [o for o, conds in goal.get("state", {}).items()
              if "hot" in conds and o in world["objects"] and not world["objects"][o].get("state", {}).get("hot")]
    if len(heaters) == 1 and heated:
        touched.add(heaters[0])
    for p in sorted(touched, key=list(world["places"]).index):
        e = world["places"][p]
        said = goal["state"].get(p, [])
        # "put the apple in the oven and turn it on": its switch says nothing of its door
        if "openable" in e["properties"] and not e["state"].get("open") and not {"open", "closed"} & set(said):
            goal["state"][p] = said + ["closed"]


#: switch and door conditions: (the state key, the value that makes the condition hold)
_SWITCHES = {"on": ("on", True), "off": ("on", False), "open": ("open", True), "closed": ("open", False)}


def _already(world: dict, name: str, cond: str) -> bool:
    """Whether an object's switch or door condition holds in the world as it is (other
    conditions are taken not to: their container is listed, as before)."""
    if cond not in _SWITCHES or name not in world["objects"]:
        return False
    key, value = _SWITCHES[cond]
    return bool((world["objects"][name].get("state") or {}).get(key, False)) == value


def _closed_again(world: dict, goal: dict) -> dict:
    """A copy of a goal with the containers a plan opens closed again (:func:`_leave_closed`)."""
    out = json.loads(json.dumps(goal))
    out.setdefault("state", {})
    _leave_closed(world, out)
    return out


def _key(goal: dict) -> str:
    return json.dumps({"in": {p: sorted(v) for p, v in goal.get("in", {}).items()},
                       "state": {n: sorted(v) for n, v in goal.get("state", {}).items()},
                       "count": goal.get("count", [])}, sort_keys=True)


def understand(command: str, world: dict, choose: dict[str, str] | None = None) -> dict:
    """``{"order", "goal", "explain", "notes", "words"}``: the one meaning of the command in this world
    (module docstring); TranslationError (not understood, ambiguous) or Refusal (impossible).

    A line break ends a sentence. A command that only makes sense with its lines joined (a
    sentence wrapped onto the next line) is read joined; one that makes sense both ways with two
    different goals is refused, quoting both (:func:`pipflow.language.characters.line_readings`)."""
    texts = line_readings(command)
    results: list[dict] = []
    first_error: Exception | None = None
    for text in texts:
        try:
            results.append(_understand(text, world, choose))
        except (TranslationError, Refusal) as exc:
            first_error = first_error or exc
    if not results:
        assert first_error is not None
        raise first_error
    if len(results) > 1 and _key(results[0]["goal"]) != _key(results[1]["goal"]):
        raise TranslationError(f"the line breaks of {texts[0]!r} can end sentences or continue them, and the two "
                               f"readings ask for different things: " + " or ".join(
                                   json.dumps(r["goal"], sort_keys=True) for r in results)
                               + "; nothing is guessed: end each sentence with a full stop")
    result = results[0]
    result["order"] = {**result["order"], "command": command}
    return result


def _understand(command: str, world: dict, choose: dict[str, str] | None = None) -> dict:
    """:func:`understand` of one reading of the command's line breaks."""
    notes: list[str] = []
    readings = parse(command, world, notes)
    meant: dict[str, tuple[dict, dict]] = {}
    errors: list[Exception] = []
    for order in readings:
        try:
            out = resolve(order, world, choose)
        except (TranslationError, Refusal) as exc:
            errors.append(exc)
            continue
        meant.setdefault(_key(out["goal"]), (order, out))
    if not meant:
        # no reading resolves: the one that got as far as asking which thing is meant says most
        # (its choices become the candidate readings), else the first
        asking = next((e for e in errors if getattr(e, "choices", None)), None)
        if asking is not None:
            raise asking
        impossible = [e for e in errors if isinstance(e, Refusal)]
        if impossible and len(impossible) < len(errors):
            # one reading is impossible, another is not understood ("..., and the dolls house in
            # the toy box": the dolls house that is in the box, or (put) the dolls house in the
            # box): the command is impossible only if the first is what was meant, so it is asked
            raise TranslationError(f"{command.strip()!r} is impossible if read one way ({impossible[0]}), "
                                   f"and another reading is not understood "
                                   f"({next(e for e in errors if not isinstance(e, Refusal))}); say it in other words")
        raise errors[0]
    if len(meant) > 1:
        # coordination before gapping: "chop the carrot and the onion on the worktop" is one
        # clause about both, not "chop the carrot" and "(chop) the onion on the worktop"
        fewest = min(len(order["statements"]) for order, _ in meant.values())
        simplest = {k: v for k, v in meant.items() if len(v[0]["statements"]) == fewest}
        if len(simplest) == 1:
            notes.append("read as one clause with its things coordinated; also readable with an elided verb")
            meant = simplest
    if len(meant) > 1:
        goals = [out["goal"] for _, out in meant.values()]
        # ask rather than refuse (issue 23): each reading is offered, in plain words, with the
        # words it rests on; none is acted on unchosen
        offered = [{"reading": "; ".join(out["explain"]), "goal": _closed_again(world, out["goal"]), "order": order,
                    "words": "; ".join(st.get("words", "") for st in order["statements"])}
                   for order, out in list(meant.values())[:MAX_CANDIDATES]]
        raise TranslationError(f"{command.strip()!r} can be read in {len(goals)} ways: "
                               + " or ".join(json.dumps(g, sort_keys=True) for g in goals[:2]) + "; say it in other words",
                               candidates=offered)
    order, out = next(iter(meant.values()))
    return {"order": order, "goal": out["goal"], "explain": out["explain"], "notes": notes + out["notes"],
            "words": out["words"]}


def _shut_in(world: dict, place: str) -> bool:
    """Whether a place is a container closed now (what lies in it is taken only by opening it)."""
    entry = world["places"].get(place) or {}
    return "openable" in (entry.get("properties") or []) and not (entry.get("state") or {}).get("open")


def resolve_counts(world: dict, goal: dict) -> dict:
    """Goal with every count condition replaced by concrete objects: members already there count;
    the rest are the pickupable members that lie in no closed container first (a plan that need
    not open the fridge does not), then the nearest to the place (travel distance), then by name."""
    # deferred: pulls networkx and numpy (~350 ms; only a count goal is resolved by travel)
    from pipflow.team.travel import TravelMap

    out = {"in": {p: list(v) for p, v in (goal.get("in") or {}).items()},
           "state": {n: list(v) for n, v in (goal.get("state") or {}).items()}}
    if not goal.get("count"):
        return out
    tm = TravelMap(world)
    for c in goal["count"]:
        place, cat, n = c["in"], c["category"], int(c["at_least"])
        placed = {o for items in out["in"].values() for o in items}
        cands = [o for o in members(world, cat) if o in world["objects"]]
        there = [o for o in cands if (world["objects"][o]["in"] == place and o not in placed) or o in out["in"].get(place, [])]
        free = [o for o in cands if o not in there and o not in placed and "pickupable" in world["objects"][o]["properties"]]
        free.sort(key=lambda o: (_shut_in(world, world["objects"][o]["in"]), tm.distance(world["objects"][o]["in"], place), o))
        need = max(0, n - len(there))
        if need > len(free):
            raise Refusal(f"only {len(there) + len(free)} {cat} can end in {place}, not {n}")
        for o in there[:n] + free[:need]:
            out["in"].setdefault(place, [])
            if o not in out["in"][place]:
                out["in"][place].append(o)
    return out



def translate(command: str, world: dict) -> dict:
    """``{"goal": conditions as the command states them (counts kept), "concrete": the goal with
    counts resolved to objects, for the PDDL problem, "order": the parsed order, "explain": one
    line per condition with the words it came from, "notes": [...], "words": the words each
    condition came from (:func:`pipflow.household.language.resolver.resolve`)}``.

    A command refused as not understood carries up to three candidate readings
    (:mod:`pipflow.household.language.candidates`); none is acted on unchosen."""
    with held(world), tags_kept(world):   # the world's names stay as they are while the command is read
        try:
            return _translate(command, world)
        except TranslationError as exc:
            offered = candidate_readings(command, world, exc, _translate)
            if len(offered) == len(exc.candidates):
                raise
            raise TranslationError(str(exc), candidates=offered) from None


def _translate(command: str, world: dict, choose: dict[str, str] | None = None) -> dict:
    """:func:`translate` without looking for candidate readings; ``choose``: words that name
    several things -> the one meant (:func:`pipflow.household.language.resolver.resolve`)."""
    meaning = understand(command, world, choose)
    goal = meaning["goal"]
    _leave_closed(world, goal)
    if goal.get("count"):
        # the things a count takes come out of closed containers too ("bring two of the pastries
        # to the table": the bread bin is opened for them, and closed again)
        _leave_closed(world, {"in": resolve_counts(world, goal)["in"], "state": goal["state"]})   # goal's state, shared
    aside = meaning["order"].get("set_aside")
    own = meaning["order"].get("speaker_does") or []
    return {"goal": goal, "concrete": resolve_counts(world, goal), "order": meaning["order"],
            "explain": meaning["explain"] + ([said(aside)] if aside else [])
            + [f"set aside, not read (what the speaker will do, no order for the robots): '{o}'" for o in own]
            + [f"set aside, not read (where a thing is, as this home has it): {r}"
               for r in meaning["order"].get("restated") or []],
            "notes": meaning["notes"],
            "words": meaning["words"]}
