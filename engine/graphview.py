"""Draw a workflow's DAG: as indented text, as Graphviz DOT, or as a PNG (matplotlib)."""
from __future__ import annotations

from pathlib import Path

import networkx as nx

from pipflow.errors import UserError

from .model import LoopSpec, Workflow
from .validate import dependency_graph


def _labels(wf: Workflow) -> dict[str, str]:
    labels = {}
    for node in wf.nodes:
        if isinstance(node, LoopSpec):
            labels[node.id] = f"{node.id} [loop, max {node.max}]"
            for inner in node.steps:
                labels[inner.id] = f"{inner.id} ({inner.uses})"
        else:
            labels[node.id] = f"{node.id} ({node.uses})"
    return labels


def render_graph(wf: Workflow, fmt: str, output: Path | None) -> str | None:
    graph = dependency_graph(wf)
    labels = _labels(wf)
    if fmt == "text":
        loop_of = {s.id: n.id for n in wf.nodes if isinstance(n, LoopSpec) for s in n.steps}
        lines = []
        for node in nx.topological_sort(graph):
            preds = sorted(graph.predecessors(node))
            indent = "    " if node in loop_of else ""
            lines.append(f"{indent}{labels.get(node, node)}" + (f"  <- {', '.join(preds)}" if preds else ""))
        return "\n".join(lines)
    if fmt == "dot":
        lines = [f'digraph "{wf.name}" {{', "  rankdir=LR;", "  node [shape=box, fontname=Helvetica];"]
        for node in wf.nodes:
            if isinstance(node, LoopSpec):
                lines.append(f'  subgraph "cluster_{node.id}" {{ label="{labels[node.id]}"; style=dashed;')
                lines += [f'    "{s.id}" [label="{labels[s.id]}"];' for s in node.steps]
                lines.append("  }")
            else:
                lines.append(f'  "{node.id}" [label="{labels[node.id]}"];')
        lines += [f'  "{a}" -> "{b}";' for a, b in graph.edges]
        lines.append("}")
        text = "\n".join(lines)
        if output:
            output.write_text(text + "\n", encoding="utf-8")
            return str(output)
        return text
    if fmt == "png":
        if output is None:
            raise UserError("pipflow graph --format png needs -o FILE.png")
        draw_png(wf, graph, labels, output)
        return str(output)
    raise UserError(f"unknown graph format {fmt!r}")


def draw_png(wf: Workflow, graph: nx.DiGraph, labels: dict[str, str], output: Path) -> None:
    """A readable picture: top to bottom by dependency layer, boxes sized to their labels, each
    loop a dashed frame around its own steps only, and only the arrows that the others do not
    imply (the transitive reduction; `--format dot` has every edge)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.patches import FancyBboxPatch

    pos, width, frames = layout(wf, graph, labels)
    loops = {n.id for n in wf.nodes if isinstance(n, LoopSpec)}
    reduced = nx.transitive_reduction(nx.DiGraph(graph.subgraph([n for n in graph if n not in loops])))
    char_w, box_h = CHAR_W, BOX_H
    xs = [pos[n][0] + sign * width[n] / 2 for n in pos for sign in (-1, 1)] or [0.0, 1.0]
    xs += [x for (x0, _, x1, _) in frames.values() for x in (x0, x1)]
    ys = [y for _, y in pos.values()] or [0.0]
    fig_w = min(30.0, max(6.0, (max(xs) - min(xs)) + 1.5))
    fig_h = min(40.0, max(3.0, (max(ys) - min(ys)) + 1.8))
    fig, ax = plt.subplots(figsize=(fig_w, fig_h))
    xs_extra: list[float] = []
    for lid, (x0, y0, x1, y1) in frames.items():
        ax.add_patch(FancyBboxPatch((x0, y0), x1 - x0, y1 - y0, boxstyle="round,pad=0.02", fill=False,
                                    linestyle="--", edgecolor="#6a5acd", linewidth=1.2))
        ax.text(x0 + 0.08, y1 - 0.04, labels.get(lid, lid), ha="left", va="top", fontsize=8, color="#6a5acd")
        xs_extra.append(x0 + 0.2 + char_w * len(labels.get(lid, lid)))
    for a, b in reduced.edges:
        (xa, ya), (xb, yb) = pos[a], pos[b]
        ax.annotate("", xy=(xb, yb + box_h / 2), xytext=(xa, ya - box_h / 2),
                    arrowprops={"arrowstyle": "-|>", "color": "#555", "lw": 1.0, "shrinkA": 0, "shrinkB": 0,
                                "connectionstyle": "arc3,rad=0.0" if abs(xa - xb) < 1e-6 else "arc3,rad=0.08"})
    for n, (x, y) in pos.items():
        ax.add_patch(FancyBboxPatch((x - width[n] / 2, y - box_h / 2), width[n], box_h, boxstyle="round,pad=0.02",
                                    facecolor="#dde8f5", edgecolor="#4c78a8"))
        ax.text(x, y, labels.get(n, n), ha="center", va="center", fontsize=9)
    ax.set_xlim(min(xs) - 0.5, max(xs + xs_extra) + 0.5)
    ax.set_ylim(min(ys) - box_h - 0.4, max(ys) + box_h + 0.6)
    ax.set_aspect("equal")
    ax.axis("off")
    ax.set_title(f"workflow {wf.name}: arrows implied by others not drawn", fontsize=9, color="#555")
    fig.savefig(output, dpi=110, bbox_inches="tight")
    plt.close(fig)

CHAR_W, BOX_H = 0.095, 0.42  # inches per label character at font size 9; box height


def layout(wf: Workflow, graph: nx.DiGraph, labels: dict[str, str]
           ) -> tuple[dict[str, tuple[float, float]], dict[str, float], dict[str, tuple[float, float, float, float]]]:
    """Box centres and widths of the steps, and each loop's frame ``(x0, y0, x1, y1)``:
    layers top to bottom, each centred; a loop's steps first in their layers and any other step
    of those layers moved right of the frame, so that a frame encloses its own steps only."""
    loops = {n.id: [s.id for s in n.steps] for n in wf.nodes if isinstance(n, LoopSpec)}
    loop_of = {sid: lid for lid, members in loops.items() for sid in members}
    steps = nx.DiGraph(graph.subgraph([n for n in graph if n not in loops]))
    layers = list(nx.topological_generations(steps))
    char_w, box_h, gap_x, gap_y = CHAR_W, BOX_H, 0.5, 0.75
    width = {n: max(1.6, char_w * len(labels.get(n, n)) + 0.3) for n in steps}
    depth = {n: d for d, layer in enumerate(layers) for n in layer}
    y = {n: -depth[n] * (box_h + gap_y) for n in steps}

    def row(nodes: list[str], start: float | None) -> None:
        """Place ``nodes`` side by side from ``start`` (None: centred on 0)."""
        total = sum(width[n] for n in nodes) + gap_x * (len(nodes) - 1)
        x = -total / 2 if start is None else start
        for n in nodes:
            pos[n] = (x + width[n] / 2, y[n])
            x += width[n] + gap_x

    pos: dict[str, tuple[float, float]] = {}
    for layer in layers:  # first the loops' steps, each layer's members together and centred
        row(sorted((n for n in layer if n in loop_of), key=lambda n: (loop_of[n], n)), None)
    frames = {}
    for lid, members in loops.items():
        inner = [m for m in members if m in pos]
        if inner:  # wide enough on the left for the loop's label to clear the arrows down the middle
            centre = min(pos[m][0] for m in inner)
            frames[lid] = (min(min(pos[m][0] - width[m] / 2 for m in inner) - 0.25,
                               centre - 0.3 - 0.85 * char_w * len(labels.get(lid, lid))),
                           min(pos[m][1] for m in inner) - box_h / 2 - 0.2,
                           max(pos[m][0] + width[m] / 2 for m in inner) + 0.25,
                           max(pos[m][1] for m in inner) + box_h / 2 + 0.38)
    for layer in layers:  # then the other steps: right of any frame their row crosses
        others = sorted(n for n in layer if n not in loop_of)
        if not others:
            continue
        crossed = [x1 for (x0, y0, x1, y1) in frames.values() if y0 <= y[others[0]] <= y1]
        row(others, max(crossed) + 0.6 if crossed else None)
    return pos, width, frames
