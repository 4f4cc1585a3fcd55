"""Steps of the ``graph`` family: the subtask dependency DAG (paper Alg. 2), thin faces of
:mod:`pipflow.team.dependency`."""
from __future__ import annotations

from typing import Annotated, Any

from pipflow import Choices, Doc, StepContext, step
from pipflow.pictures import dependency_graph
from pipflow.team.dependency import build_graph, to_dot
from pipflow.values import GraphOutputs


def _read_text(ctx: StepContext, value: str) -> str:
    """Accept PDDL text or a path to it: workflows pass either (a domain file, a generated problem)."""
    if "(" in value:
        return value
    return ctx.resolve_path(value).read_text()


@step(
    "graph.dependencies",
    doc="Build the subtask dependency DAG of a team plan (minimal deordering, exact read/write, or paper Alg. 2).",
    cacheable=True,
)
def dependencies(
    ctx: StepContext,
    domain: Annotated[str, Doc("team domain: PDDL text or a path")],
    problem: Annotated[str, Doc("team problem: PDDL text or a path")],
    plan: Annotated[list, Doc("ordered plan: [{action, args}]")],
    actions: Annotated[Any, Doc("action metadata: path of domains/*.actions.yaml, or its content")],
    mode: Annotated[str, Choices("deorder", "exact", "paper"),
                    Doc("deorder: only the orders a precondition needs (increments commute; counts and room "
                        "checked for every allowed order); exact: every read/write interaction, transitively "
                        "reduced; paper: Alg. 2's single nearest parent")] = "deorder",
    picture: Annotated[bool, Doc("also draw graph.png (workflows pass pictures == 'always'; see "
                                 "pipflow.pictures)")] = True,
) -> GraphOutputs:
    """Ground the plan with unified-planning and link actions whose fluents interact."""


    graph = build_graph(_read_text(ctx, domain), _read_text(ctx, problem), plan,
                        ctx.read_yaml(actions, "action metadata file"), mode=mode)
    ctx.write_artifact("graph.json", graph)
    ctx.write_artifact("graph.dot", to_dot(graph))
    if picture:
        dependency_graph(graph, ctx.artifact_path("graph.png"))
    ctx.metrics.update({"subtasks": len(graph["nodes"]), "edges": len(graph["edges"])})
    ctx.log(f"dependency graph ({mode}): {len(graph['nodes'])} subtasks, {len(graph['edges'])} edges")
    return {"graph": graph}
