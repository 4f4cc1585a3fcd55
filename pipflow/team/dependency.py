"""From a totally ordered team plan to a DAG of subtasks (paper Sec. IV-B, Alg. 2).

Two plan actions interact when one writes a fluent that the other reads or writes. Read and
write sets are derived generically from the domain with unified-planning: each plan action is
grounded (parameters replaced by the plan's objects) and every fluent application occurring in
its preconditions, effect conditions and effect values is a read; every effect's fluent is a
write (``increase``/``decrease`` also read their fluent). Numeric fluents count like boolean
ones, which is what makes two moves that change the same shelf's load interact through the
shelf's capacity. No fluent name of any particular domain is assumed.

Modes:

* ``exact`` (:func:`build_graph`'s default): every interacting earlier action is a predecessor, then the DAG is
  transitively reduced. Any schedule that respects the edges runs conflicting actions in plan
  order, so it reaches the plan's final state and every precondition holds when it is needed.
* ``paper``: Alg. 2 as written - each action gets only its nearest interacting predecessor.
  When an action depends on two earlier, mutually independent actions, one of those edges is
  lost and a schedule may run the action too early; kept for the ablation.
* ``deorder`` (the ``graph.dependencies`` step's and the warehouse workflow's default): keep an ordering only where a precondition
  needs it; increments of one fluent commute, and stock and capacity bounds are checked for
  every order the graph allows (:mod:`pipflow.team.deorder`). Far fewer edges than ``exact`` when
  many moves share a shelf, so the schedule runs them in parallel.
"""
from __future__ import annotations

import json
from typing import Any, Iterable

from pipflow.errors import InputError, PDDLError, PlanningError
from pipflow.liberrors import UNIFIED_PLANNING, library_errors
from pipflow.pddl.common import parse
from pipflow.pddl.linear import key_of
from pipflow.team.deorder import deorder

MODES = ("exact", "paper", "deorder")
Key = tuple  # (fluent name, arg, arg, ...); "*" for a quantified variable


def _parse(domain_text: str, problem_text: str):
    """Parse with UP's PDDL reader; a parse failure is the user's input: :class:`PDDLError` (an
    InputError) naming UP and its complaint."""
    with library_errors(UNIFIED_PLANNING, PDDLError, "parsing the domain and problem for the dependency graph"):
        return parse(domain_text, problem_text)


class GroundAction:
    """One plan action with its parameters bound, and what it reads and writes."""

    def __init__(self, index: int, name: str, args: list[str], action, reads: set, writes: set,
                 binding: dict[str, str], mapping: dict | None = None):
        self.index = index
        self.name = name
        self.args = args
        self.action = action
        self.reads = reads
        self.writes = writes
        self.binding = binding  # "?param" -> object name
        self.mapping = mapping or {}  # UP parameter expression -> object expression (for grounding)
        self.objects: dict[str, str] = {}  # "?param" -> UP object name (the names in fluent keys)


def _object(problem, name: str):
    """PDDL names are case-insensitive and UP lower-cases them; plans keep the world's spelling."""
    for n in (name, name.lower()):
        if problem.has_object(n):
            return problem.object(n)
    return None


def _lifted_reads_writes(action) -> tuple[list[Key], list[Key]]:
    """What an action reads and writes, with parameters as ``?name`` (grounded by :func:`_bind`).
    Computed once per action: substituting every plan step's expressions costs far more."""
    reads: set = set()
    writes: set = set()

    def fluents(expr) -> None:
        stack = [expr]
        while stack:
            e = stack.pop()
            if e.is_fluent_exp():
                reads.add(key_of(e))
            stack.extend(e.args)

    for pre in getattr(action, "preconditions", []):
        fluents(pre)
    for eff in getattr(action, "effects", []):
        fluents(eff.value)
        fluents(eff.condition)
        for a in eff.fluent.args:  # fluent arguments are never fluents in PDDL, but be generic
            fluents(a)
        writes.add(key_of(eff.fluent))
        if eff.is_increase() or eff.is_decrease():
            reads.add(key_of(eff.fluent))
    return sorted(reads), sorted(writes)


def _bind(key: Key, objects: dict[str, str]) -> Key:
    return (key[0], *(objects.get(x, x) for x in key[1:]))


def ground_plan(problem, plan: list[dict]) -> list[GroundAction]:
    """Ground every plan action of a parsed UP problem and compute its read/write sets."""
    em = problem.environment.expression_manager
    lifted: dict[str, tuple[list[Key], list[Key]]] = {}
    out = []
    for idx, step_ in enumerate(plan):
        if not isinstance(step_, dict) or "action" not in step_:
            raise InputError(f"plan step {idx + 1} is not {{action, args}}: {step_!r}")
        name, args = str(step_["action"]), [str(a) for a in step_.get("args", [])]
        uname = name if problem.has_action(name) else name.lower()
        if not problem.has_action(uname):
            raise PlanningError(f"plan step {idx + 1}: unknown action {name!r}")
        action = problem.action(uname)
        if len(action.parameters) != len(args):
            raise PlanningError(
                f"plan step {idx + 1}: {name} takes {len(action.parameters)} arguments, got {len(args)}")
        mapping, binding, objects = {}, {}, {}
        for p, a in zip(action.parameters, args):
            obj = _object(problem, a)
            if obj is None:
                raise PlanningError(f"plan step {idx + 1}: unknown object {a!r} in {name}")
            mapping[em.ParameterExp(p)] = em.ObjectExp(obj)
            binding["?" + p.name] = a
            objects["?" + p.name] = obj.name
        if uname not in lifted:
            lifted[uname] = _lifted_reads_writes(action)
        reads_l, writes_l = lifted[uname]
        reads = {_bind(k, objects) for k in reads_l}
        writes = {_bind(k, objects) for k in writes_l}
        g = GroundAction(idx, name, args, action, reads, writes, binding, mapping)
        g.objects = objects
        out.append(g)
    return out


def _match(a: Key, b: Key) -> bool:
    return len(a) == len(b) and a[0] == b[0] and all(x == y or "*" in (x, y) for x, y in zip(a[1:], b[1:]))


def _meets(xs: Iterable[Key], ys: Iterable[Key]) -> bool:
    ys = list(ys)
    return any(_match(x, y) for x in xs for y in ys)


def interacts(earlier: GroundAction, later: GroundAction) -> bool:
    """True when ``later`` cannot be reordered with ``earlier``: write-read, read-write or
    write-write on a common fluent."""
    return (_meets(earlier.writes, later.reads | later.writes)
            or _meets(earlier.reads, later.writes))


def _last_writer_edges(grounded: list[GroundAction]) -> list[tuple[int, int]]:
    """The exact mode's order with the same transitive closure as "every interacting pair", from
    far fewer pairs: per fluent, the last writer before an action and the readers since it.
    (A writer after i on the same fluent follows i through the chain of writers, a reader
    precedes the next writer.) Ground fluents only; quantified ones take the pairwise path."""
    last_writer: dict[Key, int] = {}
    readers: dict[Key, list[int]] = {}
    edges = set()
    for j, g in enumerate(grounded):
        for k in g.reads | g.writes:
            if k in last_writer:
                edges.add((last_writer[k], j))
        for k in g.writes:
            edges.update((r, j) for r in readers.get(k, ()) if r != j)
        for k in g.writes:
            last_writer[k] = j
            readers[k] = []
        for k in g.reads - g.writes:
            readers.setdefault(k, []).append(j)
    return sorted(edges)


def _resolve(value: Any, binding: dict[str, str], where: str) -> Any:
    if isinstance(value, str) and value.startswith("?"):
        if value not in binding:
            raise InputError(f"{where}: {value} is not a parameter of the action ({', '.join(binding)})")
        return binding[value]
    return value


def _skills(spec: dict, g: GroundAction, problem, where: str) -> dict[str, float]:
    """Requirement vector Y of one subtask: a number, or a fluent's initial value."""
    em = problem.environment.expression_manager
    out = {}
    for skill, need in (spec or {}).items():
        if isinstance(need, (int, float)):
            out[skill] = float(need)
            continue
        if not isinstance(need, dict) or "fluent" not in need:
            raise InputError(f"{where}: skill {skill!r} must be a number or {{fluent, args}}, got {need!r}")
        fname = need["fluent"]
        fname = fname if problem.has_fluent(fname) else str(fname).lower()
        if not problem.has_fluent(fname):
            raise InputError(f"{where}: skill {skill!r} names unknown fluent {fname!r}")
        fl = problem.fluent(fname)
        objs = [_object(problem, _resolve(a, g.binding, where)) for a in need.get("args", [])]
        if any(o is None for o in objs):
            raise InputError(f"{where}: skill {skill!r} names an unknown object in {need.get('args')}")
        value = problem.initial_value(em.FluentExp(fl, [em.ObjectExp(o) for o in objs]))
        if value is None or not value.is_constant():
            raise InputError(f"{where}: fluent {fname}{objs} has no initial value in the problem")
        v = value.constant_value()
        out[skill] = float(v.numerator) / float(v.denominator) if hasattr(v, "numerator") else float(v)
    return out


def subtask_node(g: GroundAction, problem, actions_meta: dict, node_id: str, index: int) -> dict:
    """One node of the ``graph`` contract for grounded action ``g``: its requirement vector Y
    (``skills``, fluent values read from ``problem``'s initial state), its ``route`` and rule
    ``fields``, from the action metadata (``{name: {skills, route, fields}}``). Shared by
    :func:`build_graph` and by plans whose order is given rather than derived (the baselines)."""
    meta = actions_meta.get(g.name)
    where = f"action metadata for {g.name!r} (plan step {index + 1})"
    if meta is None:
        raise InputError(f"no action metadata for {g.name!r}; known: {', '.join(sorted(actions_meta))}")
    return {
        "id": node_id,
        "index": index,
        "action": g.name,
        "args": g.args,
        "skills": _skills(meta.get("skills", {}), g, problem, where),
        "route": [_resolve(p, g.binding, where) for p in meta.get("route", [])],
        "fields": {k: _resolve(v, g.binding, where) for k, v in (meta.get("fields") or {}).items()},
    }


def build_graph(
    domain_text: str,
    problem_text: str,
    plan: list[dict],
    metadata: dict,
    mode: str = "exact",
    parsed: Any = None,
) -> dict:
    """The ``graph`` contract of docs/architecture.md for ``plan``.

    ``metadata`` is the parsed ``*.actions.yaml`` (``{"actions": {name: {skills, route, fields}}}``).
    ``parsed``: the problem already parsed (read only), when the caller has it (a recovery builds
    its problem without the text parser: :mod:`pipflow.execution.recovery`).
    """
    import networkx as nx

    if mode not in MODES:
        raise InputError(f"unknown dependency mode {mode!r}; use one of {', '.join(MODES)}")
    problem = parsed if parsed is not None else _parse(domain_text, problem_text)
    grounded = ground_plan(problem, plan)
    actions_meta = (metadata or {}).get("actions", metadata or {})

    nodes = [subtask_node(g, problem, actions_meta, f"s{g.index + 1}", g.index) for g in grounded]

    dag = nx.DiGraph()
    dag.add_nodes_from(n["id"] for n in nodes)
    if mode == "deorder":
        dag.add_edges_from((nodes[i]["id"], nodes[j]["id"]) for i, j in deorder(problem, grounded))
    elif mode == "exact" and not any("*" in k for g in grounded for k in g.reads | g.writes):
        dag.add_edges_from((nodes[i]["id"], nodes[j]["id"]) for i, j in _last_writer_edges(grounded))
    else:
        touching: dict[Key, list[int]] = {}  # ground fluent -> earlier actions reading or writing it
        wild: list[int] = []  # actions with a quantified ("*") fluent: checked against every later one
        for j in range(len(grounded)):
            mine = grounded[j].reads | grounded[j].writes
            if any("*" in k for k in mine):
                candidates = set(range(j))
            else:
                candidates = {i for k in mine for i in touching.get(k, ())} | set(wild)
            parents = [i for i in sorted(candidates, reverse=True) if interacts(grounded[i], grounded[j])]
            if any("*" in k for k in mine):
                wild.append(j)
            else:
                for k in mine:
                    touching.setdefault(k, []).append(j)
            if mode == "paper":
                parents = parents[:1]  # Alg. 2: the nearest earlier interacting action only
            for i in parents:
                dag.add_edge(nodes[i]["id"], nodes[j]["id"])
    if mode in ("exact", "deorder"):
        dag = nx.transitive_reduction(dag)
    order = {n["id"]: n["index"] for n in nodes}
    edges = sorted(([u, v] for u, v in dag.edges()), key=lambda e: (order[e[1]], order[e[0]]))
    return {"mode": mode, "nodes": nodes, "edges": edges}


def to_networkx(graph: dict):
    """The graph contract as a networkx DiGraph with node attributes."""
    import networkx as nx

    g = nx.DiGraph()
    for n in graph["nodes"]:
        g.add_node(n["id"], **n)
    g.add_edges_from(tuple(e) for e in graph["edges"])
    return g


def label(node: dict) -> str:
    return f"{node['action']} {' '.join(node['args'])}"


def to_dot(graph: dict) -> str:
    """Graphviz text; needs no graphviz to write."""
    lines = ["digraph subtasks {", "  rankdir=TB;", "  node [shape=box, fontsize=10];"]
    for n in graph["nodes"]:
        skills = ", ".join(f"{k}={v:g}" for k, v in n["skills"].items())
        text = f"{n['id']}: {label(n)}\\n{skills}"
        lines.append(f"  {json.dumps(n['id'])} [label={json.dumps(text)}];")
    for u, v in graph["edges"]:
        lines.append(f"  {json.dumps(u)} -> {json.dumps(v)};")
    lines.append("}")
    return "\n".join(lines) + "\n"


def draw(graph: dict, path) -> None:
    """A PNG of the DAG, layered by topological generation (matplotlib, Agg backend)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import networkx as nx

    g = to_networkx(graph)
    for layer, gen in enumerate(nx.topological_generations(g)):
        for n in gen:
            g.nodes[n]["layer"] = layer
    n_layers = max((d["layer"] for _, d in g.nodes(data=True)), default=0) + 1
    width = max((sum(1 for _, d in g.nodes(data=True) if d["layer"] == k) for k in range(n_layers)), default=1)
    fig, ax = plt.subplots(figsize=(max(4.0, 2.6 * width), max(3.0, 1.3 * n_layers)))
    if len(g):
        pos = {}
        xs = {}
        for k in g:
            xs.setdefault(g.nodes[k]["layer"], []).append(k)
        for layer, members in xs.items():
            members.sort(key=lambda k: g.nodes[k]["index"])
            for m_i, k in enumerate(members):
                pos[k] = (m_i - (len(members) - 1) / 2, -layer)
        labels = {k: f"{k}\n{label(g.nodes[k])}" for k in g}
        nx.draw_networkx_edges(g, pos, ax=ax, arrows=True, arrowsize=12, node_size=2500)
        nx.draw_networkx_labels(g, pos, labels=labels, ax=ax, font_size=7,
                                bbox=dict(boxstyle="round", fc="#eef4ff", ec="#5577aa"))
    ax.set_title(f"subtask dependencies ({graph['mode']})")
    ax.axis("off")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def critical_path(graph: dict, duration: dict[str, float]) -> float:
    """Longest path through the DAG with the given node durations (a makespan lower bound)."""
    import networkx as nx

    g = to_networkx(graph)
    finish: dict[str, float] = {}
    for n in nx.topological_sort(g):
        finish[n] = max((finish[p] for p in g.predecessors(n)), default=0.0) + duration.get(n, 0.0)
    return max(finish.values(), default=0.0) if finish else 0.0


__all__ = ["build_graph", "subtask_node", "ground_plan", "interacts", "to_networkx", "to_dot", "draw", "critical_path",
           "MODES"]
