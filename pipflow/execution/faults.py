"""Faults injected into a run: what goes wrong, to whom, when; declared or drawn from the seed.

A workflow input (``faults``) or a bench option (``--faults``) names them, in one of two forms:

* **counts**, drawn reproducibly from the run's seed: ``robot-loss=1``, ``slowdown=1,
  passage-closed=1`` (``,`` or ``+`` between kinds; a kind alone means one of it). A drawn fault
  always bites: a robot among those the schedule gives work, at a time before its last leg
  ends; a passage on a path some robot drives, closed before it gets there; a surprise at a
  place the plan takes something from;
* **specs**, a mapping or a list of mappings (``--inputs file.yaml`` or ``-i 'faults=[...]'``),
  each with ``kind`` and what it fixes (a field left out is drawn):

  - ``{kind: robot-loss, robot: robot2, time: 12.5}`` or ``{..., after: 2}``: the robot stops
    for good at that time, or right after its 2nd subtask ends;
  - ``{kind: slowdown, robot: robot1, time: 5, factor: 0.5}``: from then on it drives at half
    the planned speed;
  - ``{kind: passage-closed, between: [shelf1, shelf3], time: 10, at: 0.5}``: at that time the
    passage half way along the shortest path between the two places closes (a barrier across
    it, out to the nearest obstacles); robots find it closed when they get there;
  - ``{kind: surprise, ...}`` (a domain names it its own way, e.g. ``stock-surprise``): a place
    holds other contents than the world file says; robots find out when one first arrives
    there. The other fields are the domain's (:meth:`~pipflow.execution.capability.ExecutionCapability.check_surprise`).
    A drawn surprise may come in ``parts`` (units missing here lie there): each part is a fault
    of its own (``f1a``, ``f1b``), found where and when a robot first arrives at its place.

``none`` (or nothing) means no faults. Every problem is a clear :class:`InputError` naming the
fault (``faults[2]``) and the cause: a fault that cannot be placed is never silently dropped.

**Not applicable**: a fault whose target is drawn (a count, or a spec that leaves its robot,
passage or place out) may find nothing in a run to strike: a plan that moves no object an object
surprise could matter to, a schedule that gives no robot work, no leg that passes a passage. Such
a run is carried out without that fault, and the fault is recorded as not applicable with the
reason (:class:`NotApplicable`; the bench counts such runs apart: one task where a fault does not
apply never ends a bench). A spec that names its target (``robot: robot9``, ``place: shelf2``) is
checked against the world instead: a target the world lacks stays an :class:`InputError`.
"""
from __future__ import annotations

import math
import random
import re
from dataclasses import asdict, dataclass, field
from typing import Any

from pipflow.errors import FaultNotApplicable, InputError
from pipflow.execution.motion import barrier_across, share_point
from pipflow.suggest import did_you_mean

ROBOT_LOSS, SLOWDOWN, PASSAGE, SURPRISE = "robot-loss", "slowdown", "passage-closed", "surprise"
#: the generic kinds; a domain may give the surprise a name of its own (``surprise_names``)
KINDS = (ROBOT_LOSS, SLOWDOWN, PASSAGE, SURPRISE)
#: what a spec of each kind may fix (a surprise's fields are its domain's)
FIELDS = {ROBOT_LOSS: ("robot", "time", "after"), SLOWDOWN: ("robot", "time", "factor"),
          PASSAGE: ("between", "at", "time"), SURPRISE: None}
#: words that mean "no faults"
NONE_WORDS = ("", "none", "no", "off", "false")
#: the most faults of one kind a count may ask for (a typo such as 100 is refused, not run)
MOST = 20
#: a drawn slowdown drives at a share of the planned speed in this range
SLOW_RANGE = (0.3, 0.7)


@dataclass
class Fault:
    """One fault, resolved: every field the execution needs is known (``time`` of a loss ``after``
    a subtask is known only once that subtask ends: :meth:`stop_time`)."""

    id: str
    kind: str
    name: str
    robot: str | None = None
    time: float | None = None
    after: int | None = None
    factor: float | None = None
    between: list[str] | None = None
    at: float | None = None
    barrier: dict | None = None
    surprise: dict | None = None
    drawn: bool = False

    def to_json(self) -> dict:
        return {k: v for k, v in asdict(self).items() if v is not None}

    @classmethod
    def from_json(cls, data: dict) -> "Fault":
        return cls(**{k: data.get(k) for k in cls.__dataclass_fields__ if k in data})

    def describe(self) -> str:
        """The fault in words, for logs, refusals and the report."""
        when = f" at t={self.time:.1f} s" if self.time is not None else ""
        if self.kind == ROBOT_LOSS:
            after = f" after its subtask #{self.after}" if self.after is not None and self.time is None else ""
            return f"{self.robot} stops for good{when}{after}"
        if self.kind == SLOWDOWN:
            return f"{self.robot} drives at {100 * (self.factor or 1):.0f}% of its planned speed from t={self.time:.1f} s"
        if self.kind == PASSAGE:
            b = self.barrier or {}
            where = f" between {self.between[0]} and {self.between[1]}" if self.between else ""
            return (f"the passage{where} closes{when} (barrier {b.get('width', 0):.1f} x {b.get('depth', 0):.1f} m "
                    f"at ({b.get('x', 0):.1f}, {b.get('y', 0):.1f}))")
        return (self.surprise or {}).get("words") or f"{self.name} at {(self.surprise or {}).get('places')}"


@dataclass
class NotApplicable:
    """A fault asked for whose drawn target this run does not offer (module docstring): the run
    goes on without it; the record keeps which fault, its kind and why."""

    id: str
    kind: str
    name: str
    why: str
    where: str

    def to_json(self) -> dict:
        return asdict(self)

    def describe(self) -> str:
        return f"{self.name} ({self.where}) not applicable to this run: {self.why}"


@dataclass
class Placement:
    """What :func:`resolve` made of the specs: the faults placed in the run, in order, and those
    that did not apply to it."""

    faults: list[Fault] = field(default_factory=list)
    not_applicable: list[NotApplicable] = field(default_factory=list)


@dataclass
class Spec:
    """A fault as written, before it is placed in a run: its kind, the name it was given, the
    fields it fixes, and where it came from (for messages)."""

    kind: str
    name: str
    where: str
    given: dict[str, Any] = field(default_factory=dict)


# ------------------------------------------------------------------------------------------
# reading what the user wrote (no world needed: `pipflow validate` and the bench check it early)
# ------------------------------------------------------------------------------------------
def is_none(value: Any) -> bool:
    """Whether an input value asks for no faults at all."""
    if value is None or value == [] or value == {}:
        return True
    return isinstance(value, str) and value.strip().lower() in NONE_WORDS


def kind_of(name: str, surprise_names: tuple[str, ...] = (), where: str = "faults") -> str:
    """The generic kind a fault name stands for; a domain's surprise name (any ``...-surprise``
    when no domain is known yet) is a surprise. Unknown names are refused with a suggestion."""
    word = str(name).strip().lower()
    if word in KINDS:
        return word
    if word in surprise_names or (not surprise_names and word.endswith("-surprise")):
        return SURPRISE
    known = list(KINDS) + list(surprise_names)
    raise InputError(f"{where}: {name!r} is not a fault kind{did_you_mean(word, known)}; kinds: {', '.join(known)}")


def parse(value: Any, surprise_names: tuple[str, ...] = ()) -> list[Spec]:
    """The fault specs an input value asks for (module docstring), each count unrolled into
    that many specs; raises InputError for anything it cannot read."""
    if is_none(value):
        return []
    items = value if isinstance(value, list) else [value]
    specs: list[Spec] = []
    for k, item in enumerate(items):
        where = f"faults[{k + 1}]" if isinstance(value, list) else "faults"
        if isinstance(item, str):
            specs += _parse_counts(item, where, surprise_names)
        elif isinstance(item, dict):
            specs.append(_parse_mapping(item, where, surprise_names))
        else:
            raise InputError(f"{where}: expected 'kind=count' text or a mapping with `kind`, got {item!r}")
    return specs


def _parse_counts(text: str, where: str, surprise_names: tuple[str, ...]) -> list[Spec]:
    if is_none(text):
        return []
    out: list[Spec] = []
    for part in (p.strip() for p in re.split(r"[,+]", text)):
        if not part:
            continue
        name, sep, count = part.partition("=")
        n = 1
        if sep:
            try:
                n = int(count.strip())
            except ValueError:
                raise InputError(f"{where}: {part!r}: the count after '=' must be a whole number, got {count.strip()!r}") from None
        if not 1 <= n <= MOST:
            raise InputError(f"{where}: {part!r}: between 1 and {MOST} faults of a kind, got {n}")
        kind = kind_of(name, surprise_names, where)
        out += [Spec(kind, name.strip().lower(), where) for _ in range(n)]
    return out


def _parse_mapping(item: dict, where: str, surprise_names: tuple[str, ...]) -> Spec:
    if "kind" not in item:
        raise InputError(f"{where}: a fault mapping needs `kind` ({', '.join(KINDS)}), got keys {sorted(item)}")
    kind = kind_of(str(item["kind"]), surprise_names, where)
    given = {k: v for k, v in item.items() if k != "kind"}
    allowed = FIELDS[kind]
    if allowed is not None:
        unknown = sorted(k for k in given if k not in allowed)
        if unknown:
            raise InputError(f"{where}: a {kind} fault has no field {', '.join(map(repr, unknown))}"
                             f"{did_you_mean(unknown[0], allowed)}; its fields: {', '.join(allowed)}")
    spec = Spec(kind, str(item["kind"]).strip().lower(), where, given)
    _check_values(spec)
    return spec


def _number(spec: Spec, key: str, low: float, high: float = math.inf, *, open_low: bool = False) -> None:
    value = spec.given.get(key)
    if value is None:
        return
    ok = isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value)
    ok = ok and (value > low if open_low else value >= low) and value <= high
    if not ok:
        span = f"{'>' if open_low else '>='} {low:g}" + (f" and <= {high:g}" if high < math.inf else "")
        raise InputError(f"{spec.where}: {key} of a {spec.kind} fault must be a number {span}, got {value!r}")


def _check_values(spec: Spec) -> None:
    """The values a spec fixes, as far as they can be judged without a world."""
    g = spec.given
    if "robot" in g and not (isinstance(g["robot"], str) and g["robot"]):
        raise InputError(f"{spec.where}: robot must be a robot's name, got {g['robot']!r}")
    _number(spec, "time", 0.0)
    if spec.kind == ROBOT_LOSS:
        if "time" in g and "after" in g:
            raise InputError(f"{spec.where}: a robot-loss fault gives `time` or `after`, not both")
        after = g.get("after")
        if after is not None and (not isinstance(after, int) or isinstance(after, bool) or after < 1):
            raise InputError(f"{spec.where}: after must be a subtask count >= 1 (the robot stops once its "
                             f"n-th subtask ends), got {after!r}")
    if spec.kind == SLOWDOWN:
        _number(spec, "factor", 0.0, 1.0, open_low=True)
    if spec.kind == PASSAGE:
        _number(spec, "at", 0.0, 1.0)
        between = g.get("between")
        if between is not None and not (isinstance(between, list) and len(between) == 2
                                        and all(isinstance(x, str) for x in between) and between[0] != between[1]):
            raise InputError(f"{spec.where}: between must name two different places, e.g. [place1, place3], got {between!r}")


def check_input(value: Any, base_dir: Any = None) -> str | None:
    """The workflow input's check (``pipflow validate``, and before a run or a bench starts): the
    problem in words, or None. Domain names of surprises are judged later, with the world."""
    try:
        parse(value)
    except InputError as err:
        return str(err)
    return None


# ------------------------------------------------------------------------------------------
# placing faults in a run: a world, a schedule, a seed
# ------------------------------------------------------------------------------------------
def rng_for(seed: int | None) -> random.Random:
    """The faults' own random stream: the same seed draws the same faults, and the robots' start
    positions (drawn from the same seed) are not disturbed by it."""
    return random.Random(f"pipflow-faults-{0 if seed is None else int(seed)}")


def working_windows(schedule: dict) -> dict[str, tuple[float, float]]:
    """For each robot the schedule gives legs: (start of its first leg, end of its last)."""
    out = {}
    for r, info in (schedule.get("robots") or {}).items():
        legs = info.get("legs") or []
        if legs:
            out[r] = (min(float(l["start"]) for l in legs), max(float(l["end"]) for l in legs))
    return out


def check_robot(spec: Spec, world: dict) -> str:
    robot = spec.given["robot"]
    robots = list(world.get("robots") or {})
    if robot not in robots:
        raise InputError(f"{spec.where}: unknown robot {robot!r}{did_you_mean(robot, robots)}; robots: {', '.join(robots)}")
    return robot


def draw_robot(spec: Spec, windows: dict[str, tuple[float, float]], taken: set[str], rng: random.Random) -> str:
    """A robot with work in the schedule that no earlier loss took (so that the fault bites);
    :class:`FaultNotApplicable` when there is none."""
    free = sorted(r for r in windows if r not in taken)
    if not free:
        if not windows:
            raise FaultNotApplicable("the schedule gives no robot any work (nothing is left to carry out)")
        raise FaultNotApplicable(f"no robot with work left to fault: the {len(windows)} robot(s) the schedule gives "
                                 "work to are already stopped by earlier robot losses")
    return rng.choice(free)


def draw_time(window: tuple[float, float] | None, rng: random.Random) -> float:
    """A time in the robot's working window, before its last leg ends (0 when it has none)."""
    if window is None:
        return 0.0
    return round(rng.uniform(0.0, max(0.0, window[1]) * 0.98), 3)


def resolve(specs: list[Spec], world: dict, schedule: dict, graph: dict | None, seed: int | None,
            domain: Any, travel: Any = None) -> Placement:
    """Place each spec in this run: fields it fixes are checked against the world, the others are
    drawn (module docstring) from the seed's stream, in order. ``domain`` draws and checks its
    surprises; ``travel`` (a :class:`pipflow.team.travel.TravelMap` of the world) finds passages.
    A spec whose drawn target the run does not offer is not applicable (module docstring)."""
    rng = rng_for(seed)
    windows = working_windows(schedule)
    names = tuple(getattr(domain, "surprise_names", ()) or ())
    out = Placement()
    lost: set[str] = set()
    for k, spec in enumerate(specs, 1):
        fid = f"f{k}"
        if spec.kind == SURPRISE and spec.name != SURPRISE and spec.name not in names:
            own = ", ".join(names) or "none"
            raise InputError(f"{spec.where}: {spec.name!r} is not a fault of the {getattr(domain, 'name', '?')!r} "
                             f"task domain (its surprise: surprise, {own})")
        try:
            if spec.kind in (ROBOT_LOSS, SLOWDOWN):
                out.faults.append(_robot_fault(spec, fid, world, windows, lost, rng))
            elif spec.kind == PASSAGE:
                out.faults.append(_passage(spec, fid, world, schedule, rng, travel))
            else:
                out.faults += _surprise(spec, fid, world, schedule, graph, rng, domain)
        except FaultNotApplicable as why:
            if names_target(spec):  # the user chose the target: a fault that cannot strike it is their error
                raise InputError(f"{spec.where}: {why}") from None
            out.not_applicable.append(NotApplicable(fid, spec.kind, spec.name, str(why), spec.where))
    return out


def names_target(spec: Spec) -> bool:
    """Whether a spec names what its fault strikes (a robot, a passage's ends, a surprise's place
    and contents) rather than leaving it to be drawn: only a drawn target can be not applicable."""
    g = spec.given
    if spec.kind in (ROBOT_LOSS, SLOWDOWN):
        return "robot" in g
    if spec.kind == PASSAGE:
        return "between" in g
    return bool(g)


def _robot_fault(spec: Spec, fid: str, world: dict, windows: dict[str, tuple[float, float]], lost: set[str],
                 rng: random.Random) -> Fault:
    """A robot loss or a slowdown: of the robot it names, or of one drawn among those with work."""
    g = spec.given
    robot = check_robot(spec, world) if "robot" in g else draw_robot(spec, windows, lost, rng)
    fault = Fault(fid, spec.kind, spec.name, robot=robot, drawn=not g)
    if spec.kind == ROBOT_LOSS:
        lost.add(robot)
        if "after" in g:
            fault.after = int(g["after"])
        else:
            fault.time = float(g["time"]) if "time" in g else draw_time(windows.get(robot), rng)
    else:
        fault.time = float(g["time"]) if "time" in g else draw_time(windows.get(robot), rng)
        fault.factor = float(g["factor"]) if "factor" in g else round(rng.uniform(*SLOW_RANGE), 2)
    return fault


def _surprise(spec: Spec, fid: str, world: dict, schedule: dict, graph: dict | None, rng: random.Random,
              domain: Any) -> list[Fault]:
    """A state surprise as written (checked by the domain), or drawn by the domain where the plan
    takes something from; one fault per part (each found where a robot first arrives)."""
    g = spec.given
    surprise = (domain.check_surprise(world, g, spec.where) if g
                else domain.draw_surprise(world, schedule, graph, rng))
    if surprise is None:  # the domain gave no reason of its own
        raise FaultNotApplicable("this schedule takes nothing from any place, so no surprise can matter to it")
    parts = surprise.get("parts") or [surprise]
    return [Fault(fid if len(parts) == 1 else f"{fid}{chr(ord('a') + j)}", SURPRISE, spec.name,
                  surprise={**part, "how": surprise.get("how")} if surprise.get("how") else part, drawn=not g)
            for j, part in enumerate(parts)]


def _passage(spec: Spec, fid: str, world: dict, schedule: dict, rng: random.Random, travel: Any) -> Fault:
    """A closed passage: across the shortest path between two named places (``between``, ``at``
    a share of its length), or drawn across a leg some robot drives, closed before it gets there."""
    # deferred: pulls numpy/networkx (the travel map; only runs with a passage fault need it)
    from pipflow.team.travel import TravelMap

    g = spec.given
    travel = travel or TravelMap(world)
    if "between" in g:
        a, b = g["between"]
        for name in (a, b):
            if name not in travel.places:
                raise InputError(f"{spec.where}: unknown place {name!r}{did_you_mean(name, travel.places)}")
        share = float(g.get("at", 0.5))
        point, direction = share_point(travel.path(a, b), share)
        barrier = barrier_across(world, point, direction)
        if barrier is None:
            raise InputError(f"{spec.where}: no passage to close {100 * share:.0f}% of the way from {a} to {b} (the "
                             "path runs there along a footprint or next to an access point or a robot's start); "
                             "give another `at`")
        return Fault(fid, PASSAGE, spec.name, time=float(g.get("time", 0.0)), between=[a, b], at=share, barrier=barrier)
    legs = [(r, leg) for r, info in sorted((schedule.get("robots") or {}).items())
            for leg in info.get("legs") or [] if float(leg.get("distance", 0.0)) >= 3.0]
    rng.shuffle(legs)
    for robot, leg in legs:
        share = round(rng.uniform(0.3, 0.7), 3)
        point, direction = share_point(leg.get("path") or [leg["from"], leg["to"]], share)
        barrier = barrier_across(world, point, direction)
        if barrier is None:
            continue
        reach = float(leg["start"]) + share * (float(leg["end"]) - float(leg["start"]))
        time = float(g["time"]) if "time" in g else round(rng.uniform(0.0, 0.98 * reach), 3)
        ends = [_place_at(travel, leg["from"]), _place_at(travel, leg["to"])]
        return Fault(fid, PASSAGE, spec.name, time=time, between=ends if None not in ends else None,
                     at=share, barrier=barrier, drawn=True)
    raise FaultNotApplicable("no passage to close: no leg of this schedule runs 3 m or more through open floor "
                             "away from access points")


def _place_at(travel: Any, point: Any) -> str | None:
    """The name of the place at ``point`` (a fixture's access point), if any."""
    p = (float(point[0]), float(point[1]))
    robots = set((travel.world.get("robots") or {}))
    for name, q in travel.places.items():
        if name not in robots and math.dist(p, q) < 1e-6:
            return name
    return None
