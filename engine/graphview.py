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
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        for layer, nodes in enumerate(nx.topological_generations(graph)):
            for n in nodes:
                graph.nodes[n]["layer"] = layer
        pos = nx.multipartite_layout(graph, subset_key="layer")
        fig, ax = plt.subplots(figsize=(max(6, 2 * len(graph)), 4))
        nx.draw_networkx(graph, pos, ax=ax, labels={n: labels.get(n, n) for n in graph}, node_color="#dde8f5",
                         node_shape="s", node_size=2500, font_size=7, arrows=True)
        ax.axis("off")
        fig.tight_layout()
        fig.savefig(output, dpi=120)
        plt.close(fig)
        return str(output)
    raise UserError(f"unknown graph format {fmt!r}")
