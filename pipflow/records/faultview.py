"""The run report's sections for a run under faults (pipflow.execution): the plan as carried out,
each fault where and when it struck, the recovery rounds, the world as it really was and the state
table at the end. A run without faults has none of them.
"""
from __future__ import annotations

from pathlib import Path
from typing import Any

from pipflow import pictures, values
from pipflow.errors import UserError
from pipflow.records.htmlparts import Pictures, esc, img, table
from pipflow.records.runrecord import find_step
from pipflow.taskdomains import task_domain


def executed_step(steps, shapes: dict[str, str]) -> tuple[str, Path, dict] | None:
    """The execution step of a run under faults (its outputs: the world as it really was, the
    schedule carried out, its graph, faults, rounds); None for a run without faults."""
    found = find_step(steps, shapes, values.EXECUTION)
    if not found or not isinstance(found[2].get("faults"), list) or not found[2]["faults"]:
        return None
    return found


def executed_plan_section(out: dict, graph_s: tuple[str, Path, dict] | None, schedule: dict | None) -> str:
    """The team plan as carried out under faults: every subtask the robots did (the first plan's,
    then each re-plan's ``rK-...``), who did it and when, where it came from; and the subtasks of
    a plan a recovery set aside, with the round that did."""
    nodes = sorted((n for n in (graph_s[2]["graph"].get("nodes", []) if graph_s else []) if isinstance(n, dict)),
                   key=lambda n: n.get("index", 0))
    by_id = {s.get("id"): s for s in (schedule or {}).get("subtasks", []) if isinstance(s, dict)}
    rounds = [r for r in out.get("recoveries") or [] if isinstance(r, dict)]
    made_by = {sid: r for r in rounds for sid in r.get("replanned") or []}
    moved_by = {sid: r for r in rounds for sid in r.get("reallocated") or []}
    rows = []
    for n in nodes:
        sid = n.get("id")
        s = by_id.get(sid)
        text = " ".join(map(str, [n.get("action")] + list(n.get("args", []))))
        if sid in made_by:
            origin = f"re-planned in round {made_by[sid].get('round')}"
        elif sid in moved_by:
            origin = f"first plan, re-allocated in round {moved_by[sid].get('round')}"
        else:
            origin = "first plan"
        rows.append([sid, f"({text})", ", ".join(s["robots"]) if s else "(not carried out)",
                     f"{s['start']:.1f}" if s else "", f"{s['end']:.1f}" if s else "", origin])
    set_aside = [f"{', '.join(r['aborted'])} (round {r.get('round')}: {r.get('action')})"
                 for r in rounds if r.get("aborted")]
    carried = sum(1 for n in nodes if n.get("id") in by_id)
    head = (f"<h2 id='plan'>Team plan as carried out</h2><p class='small'>{carried} subtask(s) carried out, in the "
            f"world as it really was; {len(rounds)} recovery round(s) (see <a href='#faults'>Faults and recovery</a>)."
            + (f" Set aside by a re-plan, never carried out: {esc('; '.join(set_aside))}." if set_aside else "") + "</p>")
    return head + (table(["subtask", "action", "robots", "start (s)", "end (s)", "from"], rows) if rows
                   else "<p>nothing was carried out</p>")


def incidents(world: dict | None, out: dict) -> list[dict]:
    """The faults and recovery rounds of a run as moments of its replay: ``{time, kind, words}``
    and, where the fault is at a point, ``x``/``y`` (a robot's stop, a closed passage's middle,
    a surprising place's access point) or the ``robot`` it struck (the replay puts the mark
    where that robot is at that moment)."""
    places = {}
    try:
        places = task_domain(world).places(world) if isinstance(world, dict) else {}
    except UserError:
        places = {}
    events: list[dict] = []
    for f in out.get("faults") or []:
        if not isinstance(f, dict) or f.get("occurred") is False:
            continue
        words = f"{f.get('id')}: {_fault_words(f)}"
        kind = f.get("kind")
        t = f.get("time") if f.get("time") is not None else f.get("detected")
        event = {"time": float(t or 0.0), "kind": kind, "words": words}
        if kind == "robot-loss" and f.get("point"):
            event.update(x=float(f["point"][0]), y=float(f["point"][1]), stops=f.get("robot"))
            event["words"] = f"{words} (stops at t={event['time']:.1f} s)"
        elif kind == "passage-closed" and f.get("barrier"):
            b = f["barrier"]
            event.update(x=float(b["x"]) + float(b["width"]) / 2, y=float(b["y"]) + float(b["depth"]) / 2,
                         barrier=[float(b["x"]), float(b["y"]), float(b["width"]), float(b["depth"])])
        elif kind == "surprise":
            where = ((f.get("surprise") or {}).get("places") or [None])[0]
            access = (places.get(where) or {}).get("access") if where else None
            if access:
                event.update(x=float(access[0]), y=float(access[1]))
            event["time"] = float(f.get("detected") if f.get("detected") is not None else 0.0)
            event["words"] = f"{words} (found at t={event['time']:.1f} s)"
        elif f.get("robot"):
            event["robot"] = f["robot"]
        events.append(event)
    for r in out.get("recoveries") or []:
        if not isinstance(r, dict):
            continue
        secs = f", {r['seconds']:.2f} s" if isinstance(r.get("seconds"), (int, float)) else ""
        events.append({"time": float(r.get("time") or 0.0), "kind": "recovery",
                       "words": f"recovery {r.get('round')}: {r.get('action')}{secs}: {_remainder(r) or r.get('learned', '')}"})
    return sorted(events, key=lambda e: (e["time"], e["kind"] == "recovery"))


def _remainder(r: dict) -> str:
    """What a recovery round did with the rest of the run, in words: who took which subtask, the
    new plan's steps (and what a repair kept), the refusal."""
    if r.get("action") == "re-allocate":
        return "; ".join(f"{a.get('subtask')} to {', '.join(a.get('robots') or [])}"
                         for a in r.get("allocation") or [] if isinstance(a, dict)) or "nothing left to allocate"
    if r.get("action") == "re-plan":
        who = {a.get("subtask"): ", ".join(a.get("robots") or []) for a in r.get("allocation") or [] if isinstance(a, dict)}
        steps = [f"{sid} ({' '.join(map(str, [p.get('action')] + list(p.get('args') or [])))})"
                 + (f" to {who[sid]}" if who.get(sid) else "")
                 for sid, p in zip(r.get("replanned") or [], r.get("plan") or [])]
        rep = r.get("repaired")
        kept = (f"repaired: kept {rep.get('kept')} step(s) of the old plan, dropped "
                f"{', '.join(rep.get('dropped') or []) or 'none'}; " if isinstance(rep, dict) else "plan made anew; ")
        return (f"set aside {', '.join(r.get('aborted') or []) or 'nothing'}; {kept}new: " + ("; ".join(steps) or "none"))
    if r.get("action") == "refuse":
        return str(r.get("refusal") or "")
    return str(r.get("why") or "")


def faults_section(executed: tuple[str, Path, dict] | None, world: dict | None, drawn: Pictures,
                   records: dict | None = None, sim_s: tuple[str, Path, dict] | None = None) -> str:
    """What went wrong and how the run recovered: the faults (what, to whom, when, when noticed),
    each recovery round (cause, what it learned, what it did with the rest of the run, its
    seconds, whether the goal was still reachable), the refusal if the goal went out of reach,
    the world as it really was against the records, and where on the map. Empty for a run
    without faults (or whose execution step was skipped)."""
    if executed is None:
        return ""
    out = executed[2]
    faults, rounds = out["faults"], out.get("recoveries") or []
    parts = ["<h2 id='faults'>Faults and recovery</h2>"]
    if out.get("refusal"):
        parts.append(f"<div class='cause'><p><b>Refused after a fault:</b> {esc(out['refusal'])}</p></div>")
    parts.append(table(["fault", "kind", "what", "struck at (s)", "noticed at (s)", "round"],
                        [[f.get("id"), f.get("name"), _fault_words(f), f.get("time"), f.get("detected"),
                          f.get("round")] for f in faults]))
    rows = [[r.get("round"), r.get("time"), (r.get("cause") or {}).get("words"), r.get("learned"),
             r.get("action"), _remainder(r), r.get("seconds"), r.get("feasible")] for r in rounds]
    parts.append("<h3>Recovery rounds</h3>" + table(
        ["round", "t (s)", "cause", "learned", "action", "the rest of the run", "seconds", "goal reachable"], rows))
    parts.append(_as_it_was(out, world))
    parts.append(_state_table(records, world, sim_s))
    schedule, graph_world = out.get("schedule"), out.get("world") or world
    if isinstance(schedule, dict) and isinstance(graph_world, dict):
        try:
            pictures.fault_map(graph_world, schedule, faults, rounds, drawn.path("faults-map.png"))
            parts.append(img(drawn.src("faults-map.png"), "where the faults struck"))
        except Exception as exc:  # a picture must never hide the rest of the report
            parts.append(f"<p class='bad'>could not draw the faults: {esc(exc)}</p>")
    return "\n".join(parts)


def not_applicable_section(found: tuple[str, Path, dict] | None) -> str:
    """The faults asked for that had nothing in this run to strike (the run went on without
    them): which, their kind, and why. Empty when every fault asked for applied."""
    skipped = [f for f in ((found[2] if found else {}).get("not_applicable") or []) if isinstance(f, dict)]
    if not skipped:
        return ""
    return ("<h3 id='faults-not-applicable'>Faults not applicable (the run was carried out without them)</h3>"
            + table(["fault", "kind", "asked for in", "why"],
                     [[f.get("id"), f.get("name"), f.get("where"), f.get("why")] for f in skipped]))


def _flat(state: Any, prefix: tuple = ()) -> dict[tuple, Any]:
    """A nested mapping's leaves by their path (``{("shelf4", "product3"): 12}``)."""
    if isinstance(state, dict):
        out: dict[tuple, Any] = {}
        for k, v in state.items():
            out.update(_flat(v, prefix + (str(k),)))
        return out
    return {prefix: state} if prefix else {}


def _count(state: dict, key: tuple) -> Any:
    """``state[key]``; a count the state leaves out under a place it does list is 0 (a state
    lists what is there: "shelf2 product3" gone from a listed shelf2 is none left, not unknown),
    while a place the state does not list at all stays unknown (None, drawn as a dash)."""
    if key in state:
        return state[key]
    siblings = [v for k, v in state.items() if k[:-1] == key[:-1] and len(k) == len(key)]
    counts = siblings and all(isinstance(v, int) and not isinstance(v, bool) for v in siblings)
    return 0 if len(key) > 1 and counts else None


#: the most rows the state table shows (a thousand shelves' worth would bury the report)
STATE_ROWS = 60


def _state_table(records: dict | None, world: dict | None, sim_s: tuple[str, Path, dict] | None) -> str:
    """The state where the records, the world as the run found it, and the end of the run differ
    (the task domain's ``initial_state`` of the loaded and of the real world, and its
    ``final_state`` of the simulation): what was really there and what the run left."""
    if not isinstance(records, dict) or not isinstance(world, dict) or sim_s is None:
        return ""
    try:
        domain = task_domain(world)
        before = _flat(domain.initial_state(records))
        found = _flat(domain.initial_state(world))
        end = _flat(domain.final_state(values.flat_simulation(sim_s[2]) or {}))
    except Exception:  # a state this table cannot read must never hide the rest of the report
        return ""
    if not end:
        return ""
    keys = sorted({k for k in (*before, *found, *end)
                   if not (before.get(k) == found.get(k) == end.get(k))}, key=lambda k: [pictures.natural_key(p) for p in k])
    if not keys:
        return ""
    rows = [[" ".join(k), *(_count(state, k) for state in (before, found, end))] for k in keys[:STATE_ROWS]]
    more = f"<p class='small'>and {len(keys) - STATE_ROWS} more</p>" if len(keys) > STATE_ROWS else ""
    return ("<h3>The state: records, as found, at the end</h3><p class='small'>Every entry that is not the same in "
            "all three: the world file's records, the world as the run really found it, and the final observed state "
            "(the simulation's).</p>" + table(["where, what", "records", "as found", "at the end"], rows) + more)


def _as_it_was(out: dict, world: dict | None) -> str:
    """The world as the run found it, where it differs from the records: what a surprise showed,
    the passages that closed, the robots that stopped and where what they carried lies."""
    rows = []
    for f in out.get("faults") or []:
        if not isinstance(f, dict) or f.get("occurred") is False:
            continue
        if f.get("kind") == "surprise":
            rows.append(["contents", _fault_words(f), f.get("detected")])
        elif f.get("kind") == "passage-closed":
            rows.append(["passage", _fault_words(f), f.get("time")])
        elif f.get("kind") == "robot-loss":
            where = f" at ({f['point'][0]:.1f}, {f['point'][1]:.1f})" if f.get("point") else ""
            drop = f"; what it carried lies on {f['drop']}" if f.get("drop") else ""
            rows.append(["robot", f"{f.get('robot')} out of service{where}{drop}", f.get("time")])
        elif f.get("kind") == "slowdown":
            rows.append(["robot", _fault_words(f), f.get("time")])
    if not rows:
        return ""
    return ("<h3>The world as it really was</h3><p class='small'>Where it differed from the records; the "
            "sections above (plan, schedule, replay, paths, goal) show the run in this world.</p>"
            + table(["what", "as it really was", "from t (s)"], rows))


def _fault_words(f: dict) -> str:
    if f.get("kind") == "surprise":
        return str((f.get("surprise") or {}).get("words") or "")
    who = f.get("robot") or " - ".join(f.get("between") or []) or ""
    extra = f" at {100 * f['factor']:.0f}% speed" if f.get("factor") else ""
    return f"{who}{extra}" + ("" if f.get("occurred", True) else " (did not happen before the run ended)")
