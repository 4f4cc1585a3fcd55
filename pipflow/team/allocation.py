"""Skill-based multi-robot task allocation (paper Sec. IV-C, eq. 3) and its baselines.

For one subtask with requirement vector Y, skill matrix Q (robots x skills) and costs c, the
paper solves the lexicographic IP

    min ( max_i c_i x_i ,  sum_i c_i x_i )   s.t.  Q^T x >= Y,  x binary,  custom constraints.

The cost c_i comes from the walk's :class:`~pipflow.team.scheduling.Timeline` (``cost``, one of
``scheduling.COSTS``): by default the paper's, robot i's total travel once it has done the
subtask (its metres so far, the approach and the route), so the max objective balances the
team's work; with ``cost="subtask"``, the approach and route of this subtask only (nearest
robots, less driving in total, but one robot may do most subtasks). Every solver below takes c
as given and is the same for both.

Fast first stage. Skills are non-negative, so with only per-robot exclusions (the `only` and
`never` rules) the robots with c_i <= t can cover Y iff *all* of them together cover Y. The
optimal max cost is therefore the smallest sorted cost at which the cumulative skill sum covers
Y: one sort and one cumsum, no solver. With extra linear constraints feasibility is still
monotone in t (a larger t only adds robots), so a binary search over the sorted costs with a
SCIP feasibility check finds the same threshold. The second stage is then SCIP on the robots
with c_i <= t only, which is usually a handful. ``method="naive"`` solves both stages as full
SCIP models, for comparison and tests.

Rules. ``constraints`` items ``{only|never: [robots], <field>: value, ...}`` narrow by the
subtask's ``fields`` (and ``action``); ``linear`` items add ``sum coef_i x_i (<=|>=|==) rhs``:

    {robots: [robot4, robot5] | all, coef: 1 | {robot: c}, skill: carry?, sense: "<=", rhs: 1,
     name: "...", <field>: value ...}

``skill`` multiplies each coefficient by the robot's level of that skill. Nothing is evaluated.
"""
from __future__ import annotations

import itertools
import math
import time
from dataclasses import dataclass, field
from enum import Enum
from typing import Any

import numpy as np

from pipflow.errors import AllocationError, InputError, TeamLacksSkill
from pipflow.team.nearest import nearest_costs, straight_bounds
from pipflow.team.scheduling import DEFAULT_COST, Standing, Timeline, check_cost, predecessors

EPS = 1e-7
#: SCIP reads any number this large as infinite (its default ``numerics/infinity``)
SCIP_INFINITY = 1e20
SENSES = ("<=", ">=", "==")
_RULE_KEYS = {"only", "never"}
_LINEAR_KEYS = {"robots", "coef", "skill", "sense", "rhs", "name"}


# ====================================================================== the core IP
@dataclass
class Linear:
    """One extra linear constraint over the robots of one subtask: a . x (sense) rhs."""

    coef: np.ndarray
    sense: str
    rhs: float
    label: str

    def holds(self, x: np.ndarray) -> bool:
        lhs = float(self.coef @ x)
        if self.sense == "<=":
            return lhs <= self.rhs + 1e-9
        if self.sense == ">=":
            return lhs >= self.rhs - 1e-9
        return abs(lhs - self.rhs) <= 1e-9


@dataclass
class Solution:
    robots: list[int]
    max_cost: float
    sum_cost: float
    stats: dict = field(default_factory=dict)


def covers(Q: np.ndarray, Y: np.ndarray, x: np.ndarray) -> bool:
    return bool(np.all(Q.T @ x >= Y - 1e-9))


def _scip(quiet: bool = True, time_limit: float | None = None):
    from pyscipopt import Model

    m = Model()
    if quiet:
        m.hideOutput()
    m.setParam("display/verblevel", 0)
    if time_limit is not None:
        m.setParam("limits/time", max(0.01, float(time_limit)))
    return m


def _add_rows(m, x: dict[int, Any], Q: np.ndarray, Y: np.ndarray, lin: list[Linear]) -> None:
    from pyscipopt import quicksum

    for u in range(Q.shape[1]):
        if Y[u] > 0:
            m.addCons(quicksum(float(Q[i, u]) * x[i] for i in x if Q[i, u] > 0) >= float(Y[u]))
    for L in lin:
        expr = quicksum(float(L.coef[i]) * x[i] for i in x if L.coef[i] != 0)
        if L.sense == "<=":
            m.addCons(expr <= L.rhs)
        elif L.sense == ">=":
            m.addCons(expr >= L.rhs)
        else:
            m.addCons(expr == L.rhs)


class IPStatus(str, Enum):
    """How SCIP ended one model: its own words (pyscipopt's ``Model.getStatus()``). A ``str`` so
    that the allocation's JSON stats and comparisons with the plain words keep working."""

    OPTIMAL = "optimal"
    INFEASIBLE = "infeasible"
    UNBOUNDED = "unbounded"
    INFEASIBLE_OR_UNBOUNDED = "inforunbd"
    TIME_LIMIT = "timelimit"
    GAP_LIMIT = "gaplimit"
    SOLUTION_LIMIT = "sollimit"
    BEST_SOLUTION_LIMIT = "bestsollimit"
    NODE_LIMIT = "nodelimit"
    TOTAL_NODE_LIMIT = "totalnodelimit"
    STALL_NODE_LIMIT = "stallnodelimit"
    MEMORY_LIMIT = "memlimit"
    RESTART_LIMIT = "restartlimit"
    PRIMAL_LIMIT = "primallimit"
    DUAL_LIMIT = "duallimit"
    USER_INTERRUPT = "userinterrupt"
    UNKNOWN = "unknown"

    def __str__(self) -> str:  # the word itself in messages and f-strings
        return self.value

    @classmethod
    def _missing_(cls, value: object) -> "IPStatus":
        return cls.UNKNOWN  # a word of a newer SCIP: reported as unknown, never a crash

    @classmethod
    def of(cls, model: Any) -> "IPStatus":
        return cls(model.getStatus())


#: outcomes whose best solution is used: the optimum, or the best found when a limit stopped SCIP
USABLE_OUTCOMES = frozenset({IPStatus.OPTIMAL, IPStatus.TIME_LIMIT, IPStatus.GAP_LIMIT, IPStatus.SOLUTION_LIMIT})


def _solved(m) -> bool:
    return IPStatus.of(m) in USABLE_OUTCOMES and m.getNSols() > 0


def _ip_feasible(Q, Y, idx: np.ndarray, lin: list[Linear]) -> bool:
    """Is there a coalition among ``idx`` that covers Y and meets ``lin``? (SCIP)"""
    if not np.all(Q[idx].sum(axis=0) >= Y - 1e-9):
        return False
    if not lin:
        return True
    m = _scip()
    x = {int(i): m.addVar(vtype="B") for i in idx}
    _add_rows(m, x, Q, Y, lin)
    m.setParam("limits/solutions", 1)
    m.optimize()
    return m.getNSols() > 0


def first_stage_fast(Q: np.ndarray, Y: np.ndarray, c: np.ndarray, allowed: np.ndarray,
                     lin: list[Linear] = ()) -> float | None:
    """Smallest t such that the allowed robots with c_i <= t admit a feasible coalition."""
    cand = np.flatnonzero(allowed)
    if cand.size == 0:
        return 0.0 if np.all(Y <= 1e-9) and all(L.holds(np.zeros(len(c))) for L in lin) else None
    order = cand[np.argsort(c[cand], kind="stable")]
    cum = np.cumsum(Q[order], axis=0)
    ok = np.all(cum >= Y - 1e-9, axis=1)
    if not ok.any():
        return None
    k = int(np.argmax(ok))  # first prefix that covers Y
    if np.all(Y <= 1e-9) and not lin:
        return 0.0
    # ties: every robot with the same cost joins the prefix
    if not lin:
        return float(c[order[k]])
    sc = c[order]
    thresholds = np.unique(sc[k:])

    def feasible(t: float) -> bool:
        return _ip_feasible(Q, Y, order[sc <= t + 1e-12], list(lin))

    if not feasible(float(thresholds[-1])):
        return None
    lo, hi = 0, len(thresholds) - 1  # answer index in [lo, hi]
    while lo < hi:
        mid = (lo + hi) // 2
        if feasible(float(thresholds[mid])):
            hi = mid
        else:
            lo = mid + 1
    return float(thresholds[lo])


#: Metres added per robot in the second stage: among coalitions of equal summed cost (e.g. robots
#: that cost 0: at a one-place subtask's place, not yet moved), prefer the one with fewer robots.
#: Small enough (1e-4 m over 1000 robots) never to change which total is optimal by more than
#: rounding.
TIE_BREAK = 1e-7


def second_stage(Q, Y, c, eligible: np.ndarray, lin: list[Linear], time_limit: float | None = None) -> list[int]:
    """min sum c_i x_i over the eligible robots (SCIP)."""
    from pyscipopt import quicksum

    idx = np.flatnonzero(eligible)
    m = _scip(time_limit=time_limit)
    x = {int(i): m.addVar(vtype="B", obj=float(c[i])) for i in idx}
    _add_rows(m, x, Q, Y, lin)
    m.setObjective(quicksum((float(c[i]) + TIE_BREAK) * x[i] for i in x), "minimize")
    m.optimize()
    if not _solved(m):
        return []
    sol = m.getBestSol()
    return sorted(i for i in x if m.getSolVal(sol, x[i]) > 0.5)


def solve_naive(Q, Y, c, allowed, lin: list[Linear] = (), time_limit: float | None = None) -> Solution:
    """Both stages as full SCIP models over every allowed robot (the textbook formulation)."""
    from pyscipopt import quicksum

    t0 = time.perf_counter()
    idx = np.flatnonzero(allowed)
    m = _scip(time_limit=time_limit)
    x = {int(i): m.addVar(vtype="B") for i in idx}
    z = m.addVar(lb=0.0, vtype="C")
    _add_rows(m, x, Q, Y, list(lin))
    for i in x:
        m.addCons(z >= float(c[i]) * x[i])
    m.setObjective(z, "minimize")
    m.optimize()
    if not _solved(m):
        return Solution([], math.inf, math.inf, {"status": IPStatus.of(m)})
    zstar = m.getObjVal()
    t1 = time.perf_counter()
    m.freeTransform()
    m.addCons(z <= zstar + 1e-6 * max(1.0, zstar))
    m.setObjective(quicksum((float(c[i]) + TIE_BREAK) * x[i] for i in x), "minimize")
    m.optimize()
    sol = m.getBestSol()
    robots = sorted(i for i in x if m.getSolVal(sol, x[i]) > 0.5)
    return Solution(robots, max((c[i] for i in robots), default=0.0), float(sum(c[i] for i in robots)),
                    {"stage1_s": t1 - t0, "stage2_s": time.perf_counter() - t1})


def solve_lexicographic(Q: np.ndarray, Y: np.ndarray, c: np.ndarray, allowed: np.ndarray,
                        lin: list[Linear] = (), method: str = "fast") -> Solution:
    """The paper's eq. 3 for one subtask; robots as row indices of Q. Empty robots = infeasible."""
    if method == "naive":
        return solve_naive(Q, Y, c, allowed, lin)
    t0 = time.perf_counter()
    t = first_stage_fast(Q, Y, c, allowed, list(lin))
    t1 = time.perf_counter()
    if t is None:
        return Solution([], math.inf, math.inf, {"stage1_s": t1 - t0})
    eligible = allowed & (c <= t + 1e-9)
    robots = second_stage(Q, Y, c, eligible, list(lin))
    return Solution(robots, max((float(c[i]) for i in robots), default=0.0), float(sum(c[i] for i in robots)),
                    {"stage1_s": t1 - t0, "stage2_s": time.perf_counter() - t1,
                     "threshold": t, "eligible": int(eligible.sum())})


def brute_force(Q, Y, c, allowed, lin: list[Linear] = ()) -> tuple[float, float] | None:
    """Lexicographic optimum by enumeration (tests; tiny teams only)."""
    idx = list(np.flatnonzero(allowed))
    best = None
    for k in range(len(idx) + 1):
        for combo in itertools.combinations(idx, k):
            x = np.zeros(len(c))
            x[list(combo)] = 1
            if covers(Q, Y, x) and all(L.holds(x) for L in lin):
                key = (max((c[i] for i in combo), default=0.0), float(sum(c[i] for i in combo)))
                if best is None or key[0] < best[0] - 1e-9 or (abs(key[0] - best[0]) <= 1e-9 and key[1] < best[1] - 1e-9):
                    best = key
    return best


def greedy(Q, Y, c, allowed, lin: list[Linear] = ()) -> list[int]:
    """Cheapest capable robots first, until every skill is covered: the nearest ones with the
    subtask cost, the ones with the least travel once they have done it with the total cost."""
    order = [int(i) for i in np.flatnonzero(allowed)]
    order.sort(key=lambda i: (c[i], i))
    have = np.zeros(Q.shape[1])
    chosen = []
    for i in order:
        if np.all(have >= Y - 1e-9):
            break
        if np.any((Q[i] > 0) & (have < Y - 1e-9)):
            chosen.append(i)
            have += Q[i]
    return chosen if np.all(have >= Y - 1e-9) else []


def blind(Q, Y, c, allowed, lin: list[Linear] = ()) -> list[int]:
    """Cost-blind (pipflow's ablation of the cost; the paper's w/o AS, an allocation by a language
    model, is :mod:`pipflow.language.allocator`): fewest robots, ties broken by robot order.

    SCIP, so extra linear constraints are honoured; costs are never looked at."""
    n = len(c)
    weights = 1.0 + np.arange(n) / (10.0 * max(n, 1))
    return second_stage(Q, Y, weights, allowed, list(lin))


# ====================================================================== rules
@dataclass(frozen=True)
class RobotRule:
    """One `only`/`never` rule: on the subtasks whose fields equal ``match``, keep only (or
    exclude) ``robots``. ``label`` names the rule in an infeasibility message."""

    kind: str  # "only" | "never"
    robots: frozenset[str]
    match: dict[str, Any]
    label: str

    def applies(self, node: dict) -> bool:
        return _matches(self.match, node)

    def excludes(self, robot: str) -> bool:
        return (robot in self.robots) if self.kind == "never" else (robot not in self.robots)


@dataclass(frozen=True)
class LinearRule:
    """One extra linear constraint as written, with its coefficients over the whole team; it
    becomes a :class:`Linear` for each subtask whose fields equal ``match``."""

    coef: np.ndarray = field(compare=False)
    sense: str
    rhs: float
    label: str
    match: dict[str, Any]

    def applies(self, node: dict) -> bool:
        return _matches(self.match, node)

    def linear(self) -> Linear:
        return Linear(self.coef, self.sense, self.rhs, self.label)


def _matches(match: dict[str, Any], node: dict) -> bool:
    have = dict(node.get("fields") or {})
    have.setdefault("action", node.get("action"))
    return all(have.get(k) == v for k, v in match.items())


class Rules:
    """The workflow's `only`/`never` rules and extra linear constraints, validated once."""

    def __init__(self, robots: list[str], skills: list[str], Q: np.ndarray,
                 constraints: list | None, linear: list | None, nodes: list[dict]):
        self.robots = robots
        self.index = {r: i for i, r in enumerate(robots)}
        self.skills = skills
        self.Q = Q
        known_fields = {"action"}
        for n in nodes:
            known_fields |= set((n.get("fields") or {}).keys())
        self.rules: list[RobotRule] = []
        for k, rule in enumerate(constraints or []):
            where = f"constraint #{k + 1} {rule!r}"
            if not isinstance(rule, dict) or len(_RULE_KEYS & set(rule)) != 1:
                raise InputError(f"{where}: needs exactly one of `only` or `never`")
            kind = "only" if "only" in rule else "never"
            names = rule[kind]
            if isinstance(names, str):
                names = [names]
            self._check_robots(names, where)
            keys = [key for key in rule if key not in (kind, "words")]  # words: where the rule came from
            self._check_fields(keys, known_fields, where)
            self.rules.append(RobotRule(kind, frozenset(names), {key: rule[key] for key in keys},
                                        f"rule #{k + 1} {_show(rule)}"))
        self.linear: list[LinearRule] = []
        for k, item in enumerate(linear or []):
            where = f"linear constraint #{k + 1} {item!r}"
            if not isinstance(item, dict):
                raise InputError(f"{where}: must be a mapping")
            sense = item.get("sense", "<=")
            if sense not in SENSES:
                raise InputError(f"{where}: sense must be one of {', '.join(SENSES)}")
            if "rhs" not in item or isinstance(item["rhs"], bool) or not isinstance(item["rhs"], (int, float)):
                raise InputError(f"{where}: `rhs` must be a number")
            if not abs(item["rhs"]) < SCIP_INFINITY:  # NaN too: SCIP would drop or misread the row
                raise InputError(f"{where}: `rhs` must be a finite number smaller than {SCIP_INFINITY:g} in size, "
                                 f"got {item['rhs']}")
            coef = np.zeros(len(robots))
            raw = item.get("coef", 1)
            members = item.get("robots", "all")
            if isinstance(raw, dict):
                self._check_robots(list(raw), where)
                for r, v in raw.items():
                    if isinstance(v, bool) or not isinstance(v, (int, float)):
                        raise InputError(f"{where}: coefficient of {r} must be a number")
                    coef[self.index[r]] = float(v)
            elif isinstance(raw, (int, float)) and not isinstance(raw, bool):
                if members == "all":
                    coef[:] = float(raw)
                else:
                    if not isinstance(members, list):
                        raise InputError(f"{where}: `robots` must be a list of robot names or `all`")
                    self._check_robots(members, where)
                    for r in members:
                        coef[self.index[r]] = float(raw)
            else:
                raise InputError(f"{where}: `coef` must be a number or a mapping robot -> number")
            if "skill" in item:
                if item["skill"] not in skills:
                    raise InputError(f"{where}: unknown skill {item['skill']!r}; skills: {', '.join(skills)}")
                coef = coef * Q[:, skills.index(item["skill"])]
            if not np.all(np.abs(coef) < SCIP_INFINITY):
                raise InputError(f"{where}: coefficients must be finite numbers smaller than {SCIP_INFINITY:g} in size")
            keys = [key for key in item if key not in _LINEAR_KEYS]
            self._check_fields(keys, known_fields, where)
            label = item.get("name") or f"linear #{k + 1} {_show(item)}"
            self.linear.append(LinearRule(coef, sense, float(item["rhs"]), label, {key: item[key] for key in keys}))

    def _check_robots(self, names, where: str) -> None:
        if not isinstance(names, list) or not names:
            raise InputError(f"{where}: robots must be a non-empty list")
        unknown = [r for r in names if r not in self.index]
        if unknown:
            raise InputError(f"{where}: unknown robots {unknown}; robots: {', '.join(self.robots)}")

    @staticmethod
    def _check_fields(keys: list[str], known: set[str], where: str) -> None:
        unknown = [k for k in keys if k not in known]
        if unknown:
            raise InputError(f"{where}: subtasks have no field {unknown}; fields: {', '.join(sorted(known))}")

    def mask(self, node: dict) -> tuple[np.ndarray, dict[str, str]]:
        """Allowed robots for ``node`` and, for the excluded ones, which rule excluded them."""
        allowed = np.ones(len(self.robots), dtype=bool)
        why: dict[str, str] = {}
        for rule in self.rules:
            if not rule.applies(node):
                continue
            for r, i in self.index.items():
                if rule.excludes(r) and allowed[i]:
                    allowed[i] = False
                    why[r] = rule.label
        return allowed, why

    def lin(self, node: dict) -> list[Linear]:
        return [rule.linear() for rule in self.linear if rule.applies(node)]


def _show(d: dict) -> str:
    return "{" + ", ".join(f"{k}: {v}" for k, v in d.items()) + "}"


# ====================================================================== team + walk
def skill_matrix(world: dict, nodes: list[dict]) -> tuple[list[str], list[str], np.ndarray]:
    """Robot names, skill names, and Q (robots x skills); a missing skill is level 0."""
    robots = list((world.get("robots") or {}).keys())
    if not robots:
        raise InputError("the world has no robots")
    skills: list[str] = []
    for r in robots:
        for s in (world["robots"][r].get("skills") or {}):
            if s not in skills:
                skills.append(s)
    for n in nodes:
        for s in n.get("skills") or {}:
            if s not in skills:
                skills.append(s)
    Q = np.zeros((len(robots), len(skills)))
    for i, r in enumerate(robots):
        for s, v in (world["robots"][r].get("skills") or {}).items():
            Q[i, skills.index(s)] = skill_level(v, f"robot {r}: skill {s!r}")
    for n in nodes:
        need_vector(n, skills)  # every subtask's needs checked once, before any walk
    return robots, skills, Q


def skill_level(value: Any, where: str) -> float:
    """A skill level or need as a number; refused unless finite and >= 0. Why: the fast first
    stage relies on skills being non-negative (more robots never cover less), and a NaN need
    would compare false with every level and silently drop its row from the model."""
    try:
        level = float(value)
    except (TypeError, ValueError):
        raise InputError(f"{where}: level {value!r} is not a number") from None
    if not 0 <= level < math.inf:
        raise InputError(f"{where}: level must be a finite number >= 0, got {value!r}")
    return level


def need_vector(node: dict, skills: list[str]) -> np.ndarray:
    Y = np.zeros(len(skills))
    for s, v in (node.get("skills") or {}).items():
        Y[skills.index(s)] = skill_level(v, f"subtask {node.get('id')}: needed skill {s!r}")
    return Y


def explain_infeasible(node: dict, robots, skills, Q, Y, allowed, why, lin: list[Linear]) -> AllocationError:
    """Name the subtask, the skill that falls short, and who was excluded by which rule."""
    have = Q[allowed].sum(axis=0) if allowed.any() else np.zeros(len(skills))
    total = Q.sum(axis=0)
    desc = f"{node['id']} ({node.get('action', '')} {' '.join(node.get('args', []))})".strip()
    short = [f"{skills[u]}: needs {Y[u]:g}, allowed robots have {have[u]:g} (short by {Y[u] - have[u]:g}; "
             f"the whole team has {total[u]:g})" for u in range(len(skills)) if have[u] < Y[u] - 1e-9]
    by_rule: dict[str, list[str]] = {}
    for r, label in why.items():
        by_rule.setdefault(label, []).append(r)
    excluded = "; ".join(f"{', '.join(rs)} excluded by {label}" for label, rs in by_rule.items())
    if short:
        msg = f"no feasible coalition for subtask {desc}: " + "; ".join(short)
    else:
        msg = (f"no feasible coalition for subtask {desc}: the allowed robots have the skills, but the "
               f"linear constraints leave no coalition: {'; '.join(L.label for L in lin)}")
    if excluded:
        msg += f". Excluded: {excluded}"
    lacking = [skills[u] for u in range(len(skills)) if Y[u] > 1e-9 and have[u] <= 1e-9]
    return TeamLacksSkill(msg) if lacking else AllocationError(msg)


METHODS = ("scip", "naive", "greedy", "blind")


def allocate(graph: dict, world: dict, method: str = "scip", constraints: list | None = None,
             linear: list | None = None, mode: str = "subtask", travel=None, speed: float = 1.0,
             handling: float = 2.0, time_limit: float = 10.0, cost: str = DEFAULT_COST,
             standing: Standing | None = None) -> dict:
    """Walk the graph frontier (Alg. 1) and allocate every subtask; the allocation contract.

    ``mode="subtask"``: one IP per subtask (the paper); ``mode="frontier"`` (scip only): all ready
    subtasks in one IP minimising their latest finish, then (with ``cost="total"``) the largest
    cost and then the sum of costs, as the paper's objective does; (with ``cost="subtask"``) the
    sum of costs, the total distance. ``cost``: what c_i is (:data:`scheduling.COSTS`).
    ``standing``: continue from where a team stands (:class:`~pipflow.team.scheduling.Standing`):
    the subtasks it lists as ended are not allocated again, the rest are, from the robots'
    positions, free times and travel so far."""
    if method not in METHODS:
        raise InputError(f"unknown allocation method {method!r}; use one of {', '.join(METHODS)}")
    if mode not in ("subtask", "frontier"):
        raise InputError(f"unknown allocation mode {mode!r}; use subtask or frontier")
    if not 0 < time_limit < SCIP_INFINITY:  # NaN too
        raise InputError(f"time_limit must be a positive number of seconds, got {time_limit}")
    walk = AllocationWalk(graph, world, method, constraints, linear, travel=travel, speed=speed,
                          handling=handling, time_limit=time_limit, cost=check_cost(cost), standing=standing)
    t_start = time.perf_counter()
    if mode == "subtask" or method != "scip":
        walk.run_per_subtask()
    else:
        walk.run_by_waves()
    return walk.result(mode, time.perf_counter() - t_start)


class AllocationWalk:
    """One allocation of a graph: the robots, their skill matrix, the rules, the timeline of
    where each robot is and when it is free, and what has been allocated so far.

    An object rather than a function with closures so that the per-subtask and per-wave walks
    share their state openly (``assignments``, ``done``, ``stats``) instead of through a nested
    function and a dozen parameters."""

    def __init__(self, graph: dict, world: dict, method: str, constraints: list | None, linear: list | None,
                 *, travel=None, speed: float = 1.0, handling: float = 2.0, time_limit: float = 10.0,
                 cost: str = DEFAULT_COST, standing: Standing | None = None):
        self.method = method
        self.time_limit = time_limit
        self.nodes = {n["id"]: n for n in graph["nodes"]}
        self.preds = predecessors(graph)
        self.robots, self.skills, self.Q = skill_matrix(world, graph["nodes"])
        self.rules = Rules(self.robots, self.skills, self.Q, constraints, linear, graph["nodes"])
        # the one source of the costs: the IPs optimise what the schedule will report
        self.timeline = Timeline(world, travel=travel, speed=speed, handling=handling, cost=cost, standing=standing)
        for n in graph["nodes"]:
            self.timeline.check_route(n)
        self.order = sorted(self.nodes, key=lambda s: self.nodes[s]["index"])
        # where each robot stands and how far it has driven, as arrays: the costs' lower bounds
        # for the exact prefilter (pipflow.team.nearest), updated as subtasks are committed
        self.index = {r: i for i, r in enumerate(self.robots)}
        self.xy = np.array([self.timeline.travel.point(self.timeline.pos[r]) for r in self.robots], dtype=float)
        self.driven = np.zeros(len(self.robots))
        self.assignments: list[dict] = []
        # a walk that continues: what has ended (or runs to its end) is not allocated again
        self.done: set[str] = set(standing.ended) & set(self.nodes) if standing is not None else set()
        self.solve_s: list[float] = []
        self.waves: list[dict] = []

    # ------------------------------------------------------------------ the frontier
    def ready(self) -> list[str]:
        """Subtasks not yet allocated whose predecessors all are, in graph order."""
        return [s for s in self.order if s not in self.done and all(p in self.done for p in self.preds[s])]

    def run_per_subtask(self) -> None:
        queue = self.ready()  # on a fresh walk: the subtasks without predecessors
        while queue:
            sid = queue.pop(0)  # the frontier's next task, breadth first
            self.allocate_one(sid)
            for s in self.ready():
                if s not in queue:
                    queue.append(s)

    def run_by_waves(self) -> None:
        while len(self.done) < len(self.nodes):
            self.allocate_wave(self.ready())

    def _commit(self, sid: str, names: list[str], costs: dict[str, float]) -> None:
        self.assignments.append({"subtask": sid, "robots": names, "costs": costs})
        self.timeline.commit(self.nodes[sid], names, self.preds[sid])
        tl = self.timeline
        for r in names:
            self.xy[self.index[r]] = tl.travel.point(tl.pos[r])
            self.driven[self.index[r]] = tl.driven[r]
        self.done.add(sid)

    # ------------------------------------------------------------------ one subtask
    def allocate_one(self, sid: str) -> None:
        node = self.nodes[sid]
        robots, Q = self.robots, self.Q
        Y = need_vector(node, self.skills)
        allowed, why = self.rules.mask(node)
        lin = self.rules.lin(node)
        c = self.costs(node, Q, Y, allowed, lin)
        t0 = time.perf_counter()
        if self.method in ("scip", "naive"):
            chosen = solve_lexicographic(Q, Y, c, allowed, lin, "naive" if self.method == "naive" else "fast").robots
        elif self.method == "greedy":
            chosen = greedy(Q, Y, c, allowed, lin)
            if chosen and not all(L.holds(_x(chosen, len(robots))) for L in lin):
                bad = [L.label for L in lin if not L.holds(_x(chosen, len(robots)))]
                raise AllocationError(f"greedy allocation of {sid} violates {'; '.join(bad)}; use allocate.scip")
        else:
            chosen = blind(Q, Y, c, allowed, lin)
        self.solve_s.append(time.perf_counter() - t0)
        if not chosen:
            raise explain_infeasible(node, robots, self.skills, Q, Y, allowed, why, lin)
        self._commit(sid, [robots[i] for i in chosen], {robots[i]: float(c[i]) for i in chosen})

    def costs(self, node: dict, Q: np.ndarray, Y: np.ndarray, allowed: np.ndarray, lin: list[Linear]) -> np.ndarray:
        """c_i for the subtask's IP. Method ``scip``: exact for the robots that can be in the
        optimum and ``inf`` for the rest, proven to give the same optimum
        (:mod:`pipflow.team.nearest`); the other methods: every robot's exact cost."""
        tl, robots = self.timeline, self.robots
        if self.method != "scip":
            return np.array([tl.cost(r, node) for r in robots])
        route = tl.check_route(node)
        base = tl.route_length(node) + (self.driven if tl.cost_kind == "total" else 0.0)
        bounds = straight_bounds(self.xy, tl.travel.point(route[0]), np.broadcast_to(base, len(robots)))
        return nearest_costs(bounds, allowed, lambda i: tl.cost(robots[i], node),
                             lambda c: first_stage_fast(Q, Y, c, allowed, list(lin)))

    # ------------------------------------------------------------------ one wave
    def allocate_wave(self, wave: list[str]) -> None:
        """Allocate every ready subtask at once: each robot joins at most one of them; minimise the
        latest finish, then the costs (total cost: the largest, then their sum, the paper's
        objective over the wave; subtask cost: their sum, the metres driven). Time-limited; the
        best solution found is kept and the gap reported. If the wave cannot be covered by
        disjoint coalitions, the last subtask waits for the next wave; if SCIP finds nothing in
        time, the wave falls back to per-subtask IPs."""
        info: dict[str, Any] = {"subtasks": list(wave)}
        data = self._wave_needs(wave)
        sub = list(wave)
        deadline = time.perf_counter() + self.time_limit
        while sub:
            t0 = time.perf_counter()
            m, x, z, dist = self._wave_model(sub, data, max(0.05, deadline - t0))
            m.optimize()
            status = IPStatus.of(m)
            if status is IPStatus.INFEASIBLE and len(sub) > 1:
                sub = sub[:-1]  # the last ready subtask waits for the next wave
                continue
            if m.getNSols() == 0:
                # nothing found in time: fall back to one IP per subtask for this wave
                info.update({"status": status, "fallback": "per-subtask"})
                for sid in sub:
                    self.allocate_one(sid)
                self.waves.append(info)
                return
            info["status"] = status
            sol = self._wave_costs(m, x, z, dist, deadline, info)
            self.solve_s.append(time.perf_counter() - t0)
            chosen = {sid: [i for (i, s), v in sol.items() if s == sid and v > 0.5] for sid in sub}
            self._commit_wave(sub, data, chosen, dist)
            info["allocated"] = list(sub)
            self.waves.append(info)
            return

    def _wave_needs(self, wave: list[str]) -> dict[str, tuple]:
        """Each subtask's ``(node, need vector, allowed robots, linear rules)``, each checked on its
        own first, for a clear error when no coalition at all can do one."""
        robots, Q = self.robots, self.Q
        data = {}
        for sid in wave:
            node = self.nodes[sid]
            Y = need_vector(node, self.skills)
            allowed, why = self.rules.mask(node)
            lin = self.rules.lin(node)
            if first_stage_fast(Q, Y, np.zeros(len(robots)), allowed, lin) is None:
                raise explain_infeasible(node, robots, self.skills, Q, Y, allowed, why, lin)
            data[sid] = (node, Y, allowed, lin)
        return data

    def _wave_model(self, sub: list[str], data: dict[str, tuple], remaining: float) -> tuple:
        """``(model, x, z, dist)``: the wave's IP, minimising the latest finish ``z``; ``x[(robot
        index, subtask)]`` the binary choices (each robot in at most one coalition), ``dist`` their
        costs."""
        from pyscipopt import quicksum  # deferred: SCIP loads only when a model is built

        preds, robots, Q, tl = self.preds, self.robots, self.Q, self.timeline
        m = _scip(time_limit=remaining * 0.7)
        x: dict[tuple[int, str], Any] = {}
        T, dist, dur = {}, {}, {}
        for sid in sub:
            node, Y, allowed, lin = data[sid]
            ready_t = tl.ready(node, preds[sid])
            T[sid] = m.addVar(lb=ready_t, vtype="C")
            dur[sid] = tl.duration(node)
            for i in np.flatnonzero(allowed):
                r = robots[i]
                x[(int(i), sid)] = m.addVar(vtype="B")
                dist[(int(i), sid)] = tl.cost(r, node)
                m.addCons(T[sid] >= tl.arrival(r, node) * x[(int(i), sid)])
            xs = {i: x[(i, s)] for (i, s) in x if s == sid}
            _add_rows(m, xs, Q, Y, lin)
        z = m.addVar(lb=0.0, vtype="C")
        for sid in sub:
            m.addCons(z >= T[sid] + dur[sid])
        for i in range(len(robots)):
            mine = [x[k] for k in x if k[0] == i]
            if len(mine) > 1:
                m.addCons(quicksum(mine) <= 1)
        m.setObjective(z, "minimize")
        return m, x, z, dist

    def _wave_costs(self, m: Any, x: dict, z: Any, dist: dict, deadline: float, info: dict[str, Any]) -> dict:
        """The wave's choices at (about) the latest finish found: then the largest cost (total
        cost, the paper's first objective), then the sum of costs; the stages' outcomes go into
        ``info``."""
        from pyscipopt import quicksum  # deferred: SCIP loads only when a model is built

        zbest, gap = m.getObjVal(), m.getGap()
        info.update({"gap": float(gap), "latest_finish": float(zbest)})
        sol = {k: m.getSolVal(m.getBestSol(), v) for k, v in x.items()}
        m.freeTransform()
        m.addCons(z <= zbest + 1e-6 * max(1.0, zbest))
        if self.timeline.cost_kind == "total":
            # the paper's first objective at (about) that latest finish: the largest total travel
            w = m.addVar(lb=0.0, vtype="C")
            for k, v in x.items():
                m.addCons(w >= dist[k] * v)
            m.setObjective(w, "minimize")
            m.setParam("limits/time", max(0.05, (deadline - time.perf_counter()) * 0.5))
            m.optimize()
            info["max_cost_status"] = IPStatus.of(m)
            found = m.getNSols() > 0
            if found:
                sol = {k: m.getSolVal(m.getBestSol(), v) for k, v in x.items()}
                wbest = m.getObjVal()
                info["max_cost"] = float(wbest)
            m.freeTransform()
            if found:
                m.addCons(w <= wbest + 1e-6 * max(1.0, wbest))
        # then the sum of costs (with the subtask cost: the metres driven)
        m.setObjective(quicksum(dist[k] * v for k, v in x.items()), "minimize")
        m.setParam("limits/time", max(0.05, deadline - time.perf_counter()))
        m.optimize()
        if m.getNSols() > 0:
            sol = {k: m.getSolVal(m.getBestSol(), v) for k, v in x.items()}
            info["stage2_status"] = IPStatus.of(m)
        return sol

    def _commit_wave(self, sub: list[str], data: dict[str, tuple], chosen: dict[str, list[int]], dist: dict) -> None:
        """Commit the wave's coalitions in the order they start (then graph order)."""
        robots, tl = self.robots, self.timeline
        starts = {}
        for sid in sub:
            node = data[sid][0]
            starts[sid] = max([tl.ready(node, self.preds[sid])] + [tl.arrival(robots[i], node) for i in chosen[sid]])
        for sid in sorted(sub, key=lambda s: (starts[s], self.nodes[s]["index"])):
            picked = sorted(chosen[sid])
            self._commit(sid, [robots[i] for i in picked], {robots[i]: float(dist[(i, sid)]) for i in picked})

    # ------------------------------------------------------------------ the contract
    def result(self, mode: str, time_s: float) -> dict:
        predicted = self.timeline.result()
        stats: dict[str, Any] = {}
        if self.waves:
            stats["waves"] = self.waves
        stats.update({
            "subtasks": len(self.assignments), "mode": mode, "cost": self.timeline.cost_kind,
            "time_s": time_s,
            "solve_median_ms": 1000 * float(np.median(self.solve_s)) if self.solve_s else 0.0,
            # what `schedule` will report with the same speed and handling
            "predicted": {k: predicted[k] for k in ("makespan", "tc_max", "tc_avg")},
        })
        method = self.method if mode == "subtask" else f"{self.method}-frontier"
        return {"method": method, "cost": self.timeline.cost_kind, "assignments": self.assignments, "stats": stats}


def _x(chosen: list[int], n: int) -> np.ndarray:
    x = np.zeros(n)
    x[chosen] = 1
    return x
