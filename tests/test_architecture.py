"""The layer rule of docs/architecture.md, read from the code: the imports of pipflow/, engine/
and steps/ (ast; imports inside functions count too, since a deferred import is still an arrow)
form no circle; every module sits in one group of one layer (groups are sub-packages or root
modules, named by prefix); every arrow points into the module's own group or a lower layer, never
up and never across to a peer group; the engine imports nothing of pipflow's library but the few
neutral modules below it. Task domains: no generic module imports a domain package or spells a
domain's name (outside comments and docstrings), and the domain packages do not borrow from each
other."""
from __future__ import annotations

import ast
import io
import tokenize
from pathlib import Path

import networkx as nx

ROOT = Path(__file__).resolve().parent.parent
#: source folder -> the package it is installed as (pyproject's package-dir)
PACKAGES = {"pipflow": "pipflow", "engine": "pipflow.engine", "steps": "pipflow.steps"}
#: what the engine may import of pipflow's library (everything else sits above it)
ENGINE_MAY_IMPORT = {"pipflow.errors", "pipflow.resources", "pipflow.yamlsource", "pipflow.suggest"}
#: the layers of docs/architecture.md, top down: each a tuple of groups, a group a tuple of
#: package prefixes (a prefix is a sub-package or a root module, and covers what is below it).
#: A module imports its own group or a group of a lower layer; two groups of one layer are
#: peers and import nothing of each other. Every module must be in a group: a new sub-package or
#: root module is placed here (and in docs/architecture.md), which is how the tree keeps showing
#: the architecture.
LAYERS: list[tuple[str, tuple[tuple[str, ...], ...]]] = [
    ("faces", (("pipflow.api", "pipflow.commands"),)),
    ("experiments", (("pipflow.experiments",),)),
    ("records", (("pipflow.records",),)),
    ("steps", (("pipflow.steps",),)),
    ("task domains", (("pipflow.warehouse",), ("pipflow.household",))),
    ("plugin face", (("pipflow.plugin",),)),
    ("language, pictures", (("pipflow.language",), ("pipflow.pictures",))),
    ("team coordination", (("pipflow.team",),)),
    ("PDDL tools", (("pipflow.pddl",),)),
    ("neutral helpers", (("pipflow.taskdomain", "pipflow.taskdomains", "pipflow.goalcounts",
                          "pipflow.worldfile", "pipflow.floorplan", "pipflow.bullet", "pipflow.llmslot",
                          "pipflow.liberrors", "pipflow.metrics", "pipflow.meaning", "pipflow.values",
                          "pipflow.taskfile", "pipflow.worldcheck", "pipflow.scoring"),)),
    ("engine", (("pipflow.engine",),)),
    ("base", (("pipflow.errors", "pipflow.resources", "pipflow.yamlsource", "pipflow.version", "pipflow.suggest"),)),
]
#: ``from pipflow import step, Doc`` is the step author's API: the package face eagerly imports
#: only the engine's step contract and the errors (its ``run``/``bench`` load lazily), so an arrow
#: into it is allowed from any layer, and it is in no layer itself
FACE = "pipflow"


def _covers(prefix: str, module: str) -> bool:
    return module == prefix or module.startswith(prefix + ".")


def place(module: str) -> tuple[int, int] | None:
    """(layer, group) of a module, layer 0 at the top; None for a module in no group."""
    for rank, (_, groups) in enumerate(LAYERS):
        for index, group in enumerate(groups):
            if any(_covers(prefix, module) for prefix in group):
                return rank, index
    return None


def may_import(importer: str, imported: str) -> bool:
    """The rule: own group, or a lower layer (a higher rank); never a peer group, never up."""
    if imported == FACE:
        return True
    (layer_a, group_a), (layer_b, group_b) = place(importer), place(imported)
    return layer_b > layer_a or (layer_b == layer_a and group_b == group_a)


def modules() -> dict[str, Path]:
    found = {}
    for folder, package in PACKAGES.items():
        for path in (ROOT / folder).rglob("*.py"):
            parts = list(path.relative_to(ROOT / folder).with_suffix("").parts)
            if parts[-1] == "__init__":
                parts = parts[:-1]
            found[".".join([package, *parts])] = path
    return found


def imports(name: str, path: Path, known: dict[str, Path]) -> set[str]:
    """The pipflow modules ``name`` imports, anywhere in the file."""
    is_package = path.name == "__init__.py"
    out: set[str] = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"), str(path))):
        if isinstance(node, ast.Import):
            targets = [a.name for a in node.names]
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                anchor = name.split(".") if is_package else name.split(".")[:-1]
                anchor = anchor[: len(anchor) - (node.level - 1)]
                base = ".".join(anchor + ([base] if base else []))
            # `from pipflow.pddl import debugger` imports a module; `from pipflow import step` a name
            targets = [f"{base}.{a.name}" if f"{base}.{a.name}" in known else base for a in node.names]
        else:
            continue
        for target in targets:
            while target and target not in known:  # a name inside a module: the module
                target = target.rpartition(".")[0]
            if target and target != name:
                out.add(target)
    return out


def import_graph() -> nx.DiGraph:
    known = modules()
    graph = nx.DiGraph()
    graph.add_nodes_from(known)
    for name, path in known.items():
        graph.add_edges_from((name, target) for target in imports(name, path, known))
    return graph


def test_the_graph_is_read():
    """The reader sees the arrows it must see (a reader that saw none would pass every rule)."""
    graph = import_graph()
    assert len(graph) > 60
    assert graph.has_edge("pipflow.steps.allocate", "pipflow.team.allocation")  # inside a function
    assert graph.has_edge("pipflow.engine.executor", "pipflow.engine.step")  # relative
    assert graph.has_edge("pipflow.team.allocation", "pipflow.team.scheduling")


def test_every_module_has_a_place_in_the_layers():
    unplaced = sorted(name for name in modules() if name != FACE and place(name) is None)
    assert not unplaced, f"modules in no layer (add their package to LAYERS and docs/architecture.md): {unplaced}"


def test_every_arrow_points_down_or_stays_in_its_group():
    graph = import_graph()
    wrong = sorted((a, b) for a, b in graph.edges
                   if a != FACE and place(a) is not None and place(b) is not None and not may_import(a, b))
    named = [f"{a} ({LAYERS[place(a)[0]][0]}) -> {b} ({LAYERS[place(b)[0]][0]})" for a, b in wrong]
    assert not wrong, f"imports that reach up a layer or across to a peer: {named}"


def test_the_layer_rule_sees_what_it_must():
    """The rule refuses what it must (a rule that allowed everything would pass every import)."""
    assert not may_import("pipflow.team.allocation", "pipflow.steps.allocate")      # up
    assert not may_import("pipflow.warehouse.world", "pipflow.household.world")     # a peer domain
    assert not may_import("pipflow.pictures", "pipflow.language.llm")               # a peer library group
    assert not may_import("pipflow.engine.cli", "pipflow.records.report")           # the engine under records
    assert not may_import("pipflow.records.report", "pipflow.experiments.benchstats")  # records under experiments
    assert may_import("pipflow.team.dependency", "pipflow.pddl.common")             # down
    assert may_import("pipflow.language.llm", "pipflow.language.cache")             # own group
    assert may_import("pipflow.steps.allocate", FACE)                               # the step author's API


def test_no_import_circles():
    graph = import_graph()
    circles = [set(c) for c in nx.strongly_connected_components(graph) if len(c) > 1]
    assert not circles, f"import circles: {[sorted(c) for c in circles]}"


def test_the_engine_imports_only_the_neutral_modules_of_the_library():
    graph = import_graph()
    engine = [n for n in graph if n == "pipflow.engine" or n.startswith("pipflow.engine.")]
    wrong = sorted((n, t) for n in engine for t in graph.successors(n)
                   if not t.startswith("pipflow.engine") and t not in ENGINE_MAY_IMPORT)
    assert not wrong, f"the engine reaches up into the library: {wrong}"


# ---------------------------------------------------------------------------------------------
# task domains (docs/architecture.md, "Task domains"): generic code names no domain
# ---------------------------------------------------------------------------------------------
#: the task-domain packages: only they (with their own steps, in their ``steps`` module) may know a domain
DOMAIN_PACKAGES = ("pipflow.warehouse", "pipflow.household")
#: generic modules allowed to spell a domain's name, and why (keep this list short; steps/ has none)
NAMES_A_DOMAIN = {
    "pipflow.taskdomain": "DEFAULT_DOMAIN: the one place that says which domain a world without `domain:` is",
    "pipflow.language.grounding": "the JSON schema's name 'warehouse_order' is part of recorded requests' cache "
                                  "keys: renaming it would orphan every recorded model answer",
}


def _is_generic(module: str) -> bool:
    return not module.startswith(DOMAIN_PACKAGES)


def domain_words(path: Path) -> list[tuple[int, str]]:
    """Names and string literals of a module that spell a domain (comments and docstrings,
    which explain, are left out)."""
    source = path.read_text(encoding="utf-8")
    docstrings = {(node.lineno, node.col_offset) for node in ast.walk(ast.parse(source))
                  if isinstance(node, ast.Expr) and isinstance(node.value, ast.Constant)
                  and isinstance(node.value.value, str)}
    return [(tok.start[0], tok.string) for tok in tokenize.generate_tokens(io.StringIO(source).readline)
            if tok.type in (tokenize.NAME, tokenize.STRING) and tok.start not in docstrings
            and any(word in tok.string.lower() for word in ("household", "warehouse"))]


def test_no_generic_module_imports_a_domain_package():
    graph = import_graph()
    wrong = sorted((a, b) for a, b in graph.edges if _is_generic(a) and b.startswith(DOMAIN_PACKAGES))
    assert not wrong, f"generic modules that import a task domain (ask pipflow.taskdomains instead): {wrong}"


def test_the_domain_packages_do_not_import_each_other():
    graph = import_graph()
    wrong = sorted((a, b) for a, b in graph.edges for mine in DOMAIN_PACKAGES
                   if a.startswith(mine) and b.startswith(DOMAIN_PACKAGES) and not b.startswith(mine))
    assert not wrong, f"a domain borrows from a peer (move the helper to a neutral module): {wrong}"


def test_generic_modules_name_no_domain():
    found = {name: words for name, path in modules().items()
             if _is_generic(name) and name not in NAMES_A_DOMAIN and (words := domain_words(path))}
    assert not found, f"generic modules that spell a domain's name outside comments and docstrings: {found}"


def test_the_domain_name_check_sees_what_it_must(tmp_path):
    """The scan finds a domain in code and strings, and not in comments or docstrings (a scan
    that found nothing would pass every module)."""
    probe = tmp_path / "probe.py"
    probe.write_text('"""For the warehouse."""\n# household\nx = "household"\nif kind == warehouse:\n    pass\n'
                     'def f():\n    """warehouse"""\n')
    assert [line for line, _ in domain_words(probe)] == [3, 4]
    assert graph_has_domain_edges()


def graph_has_domain_edges() -> bool:
    """The import graph does see the domain packages (their own steps import them)."""
    graph = import_graph()
    return graph.has_edge("pipflow.household.steps", "pipflow.household.domain")


# ---------------------------------------------------------------------------------------------
# imports at the module top (issue 14): an import of pipflow inside a function says why
# ---------------------------------------------------------------------------------------------
def _imports_pipflow(node: ast.stmt) -> bool:
    if isinstance(node, ast.ImportFrom):
        return node.level > 0 or (node.module or "").split(".")[0] == "pipflow"
    return isinstance(node, ast.Import) and any(a.name.split(".")[0] == "pipflow" for a in node.names)


def undeclared_function_imports(path: Path) -> list[int]:
    """Lines of the imports of pipflow inside a function that carry no ``deferred:`` comment on
    their line or the line above. Such an import hides an arrow from a reader of the module's top
    (and, once, hid circles): it is allowed only to defer a heavy import on purpose, and says so."""
    source = path.read_text(encoding="utf-8")
    lines = source.splitlines()
    found = set()
    for function in ast.walk(ast.parse(source, str(path))):
        if isinstance(function, (ast.FunctionDef, ast.AsyncFunctionDef)):
            for node in ast.walk(function):
                if _imports_pipflow(node) and not any(
                        "# deferred:" in lines[n - 1] for n in (node.lineno, node.lineno - 1) if n >= 1):
                    found.add(node.lineno)
    return sorted(found)


def test_imports_inside_functions_say_why_they_are_deferred():
    found = {f"{path.relative_to(ROOT)}:{line}": path.read_text(encoding="utf-8").splitlines()[line - 1].strip()
             for path in modules().values() for line in undeclared_function_imports(path)}
    assert not found, ("imports of pipflow inside functions: move them to the module top, or keep one that "
                       f"pulls a heavy package with '# deferred: pulls <package> (<why>)' on it: {found}")


def test_the_deferral_check_sees_what_it_must(tmp_path):
    """The check flags a bare import in a function (a check that flagged nothing would pass every
    module) and accepts a top-level one or one that says why it is deferred."""
    probe = tmp_path / "probe.py"
    probe.write_text("from pipflow import errors\n"
                     "def f():\n    from pipflow.pddl import common\n"
                     "    from .store import redact\n"
                     "    import json\n"
                     "def g():\n    # deferred: pulls networkx (the probe)\n    from pipflow.team import travel\n"
                     "    import pipflow.pictures  # deferred: pulls matplotlib (the probe)\n"
                     "class C:\n    def h(self):\n        import pipflow.language.llm\n")
    assert undeclared_function_imports(probe) == [3, 4, 12]
