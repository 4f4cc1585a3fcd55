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
import json
import re
import tokenize
from collections import Counter
from pathlib import Path

import networkx as nx
import yaml

from pipflow.taskdomains import domain_named, known_domains

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
    ("baselines", (("pipflow.baselines",),)),
    ("plugin face", (("pipflow.plugin",),)),
    ("language, pictures, execution", (("pipflow.language",), ("pipflow.pictures",), ("pipflow.execution",))),
    ("team coordination", (("pipflow.team",),)),
    ("PDDL tools", (("pipflow.pddl",),)),
    ("neutral helpers", (("pipflow.taskdomain", "pipflow.taskdomains", "pipflow.goalcounts",
                          "pipflow.worldfile", "pipflow.floorplan", "pipflow.placelabels", "pipflow.bullet", "pipflow.llmslot",
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
# task domains' vocabulary (issue 22): generic code speaks no domain's words, not only its name
# ---------------------------------------------------------------------------------------------
#: where each task domain's own words are read: its PDDL domain (types, predicates, functions,
#: actions) and the sections of its world files (the world schema's top level, or a world file's).
#: The test plugin's garden counts as a domain: a plugin's words are banned too. Installed
#: third-party domains add their PDDL domain's words (:func:`domain_vocabularies`).
VOCABULARY_SOURCES = {
    "warehouse": ("domains/warehouse.pddl", "schemas/world.schema.json"),
    "household": ("domains/household.pddl", "schemas/household.schema.json"),
    "garden": ("tests/plugins/pipflow_garden/pipflow_garden/data/garden.pddl",
               "tests/plugins/pipflow_garden/pipflow_garden/data/world.yaml"),
}
#: words of those files that generic code may say anyway, and why (a word two domains share is
#: generic by itself: robots, floor, name, domain, store)
COMMON_WORDS = {
    **dict.fromkeys(("at", "on", "off", "is", "open", "close", "clear", "switch"),
                    "English function words and everyday verbs that a PDDL domain also uses as predicates "
                    "(and Python's open, close, clear)"),
    **dict.fromkeys(("amount", "load", "capacity", "room", "weight", "move"),
                    "what any robot team carries, and how much fits (allocation and planners say them; "
                    "yaml's safe_load)"),
    **dict.fromkeys(("entity", "item", "object", "objects", "place", "places", "categories", "teams"),
                    "pipflow's generic picture of a world: named places (floor plans, travel) and items, "
                    "robot teams; Python's object"),
    **dict.fromkeys(("stored", "prune", "slice"), "words of computing: a stored row, pruning a cache, a slice"),
}
#: generic modules allowed to speak a domain's words for now, and why (keep it short)
SPEAKS_A_DOMAIN = {
    "pipflow.records.report": "finds the simulation by the warehouse's legacy key final_stock and spells its rule "
                              "fields: issue 22 point 3 (the report reads declared shapes) replaces both",
}


def _words(text: str) -> list[str]:
    """The lower-case words of a name or a string: ``final_stock`` and ``finalStock`` are
    final, stock; ``move-product`` is move, product."""
    return [w.lower() for part in re.findall(r"[A-Za-z]+", text)
            for w in re.findall(r"[A-Z]?[a-z]+|[A-Z]+(?![a-z])", part)]


def _file_words(path: Path) -> set[str]:
    """A PDDL domain's types, predicates, functions and actions, or a world file's (a schema's)
    top-level sections, as words."""
    text = path.read_text(encoding="utf-8")
    if path.suffix == ".pddl":
        text = re.sub(r";[^\n]*", "", text)
        types = re.search(r"\(\s*:types(.*?)\)", text, re.DOTALL)
        names = {w for w in types.group(1).split() if w != "-"} if types else set()
        names |= set(re.findall(r"\(\s*([A-Za-z][\w-]*)\s+\?", text))  # predicates, functions
        names |= set(re.findall(r"\(\s*:action\s+([\w-]+)", text, re.IGNORECASE))
    elif path.suffix == ".json":
        names = set(json.loads(text).get("properties", {}))
    else:
        names = set(yaml.safe_load(text) or {})
    return {w for name in names for w in _words(name)}


def domain_vocabularies() -> dict[str, set[str]]:
    """Each task domain's words: :data:`VOCABULARY_SOURCES`, and the PDDL domain of every other
    task domain installed (a third-party plugin's)."""
    out = {name: set().union(*(_file_words(ROOT / f) for f in files)) for name, files in VOCABULARY_SOURCES.items()}
    for name in known_domains():
        if name not in out:
            out[name] = _file_words(Path(domain_named(name).pddl_domain()))
    return out


def banned_words() -> set[str]:
    """The words generic code may not say: each domain's own (not shared with another domain, not
    in :data:`COMMON_WORDS`), in the singular and the plural ("shelf", "shelves")."""
    vocabularies = domain_vocabularies()
    counts = Counter(w for words in vocabularies.values() for w in words)
    own = {w for words in vocabularies.values() for w in words if counts[w] == 1 and w not in COMMON_WORDS}
    forms = set(own)
    for w in own:
        forms |= {w + "s", w + "es"} | ({w[:-1] + "ves"} if w.endswith("f") else set()) | (
            {w[:-1] + "ies"} if w.endswith("y") else set())
    return forms


def vocabulary_lines(path: Path, banned: set[str]) -> list[tuple[int, str]]:
    """(line, word) of the names and string literals of a module that speak a domain's words.
    Left out: comments and docstrings (they explain), and attributes of modules from outside
    pipflow (``itertools.product`` is that library's word, not the warehouse's)."""
    source = path.read_text(encoding="utf-8")
    tree = ast.parse(source)
    docstrings = {(node.lineno, node.col_offset) for node in ast.walk(tree)
                  if isinstance(node, ast.Expr) and isinstance(node.value, ast.Constant)
                  and isinstance(node.value.value, str)}
    outside = {(alias.asname or alias.name).split(".")[0] for node in ast.walk(tree) if isinstance(node, ast.Import)
               for alias in node.names if alias.name.split(".")[0] != "pipflow"}
    theirs = {(node.end_lineno, node.end_col_offset - len(node.attr)) for node in ast.walk(tree)
              if isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name) and node.value.id in outside}
    found = []
    for tok in tokenize.generate_tokens(io.StringIO(source).readline):
        if tok.type in (tokenize.NAME, tokenize.STRING) and tok.start not in docstrings and tok.start not in theirs:
            found += [(tok.start[0], w) for w in _words(tok.string) if w in banned]
    return found


def test_generic_modules_speak_no_domain_vocabulary():
    banned = banned_words()
    found = {name: sorted(set(words)) for name, path in modules().items()
             if _is_generic(name) and name not in SPEAKS_A_DOMAIN and (words := vocabulary_lines(path, banned))}
    assert not found, ("generic modules that speak a task domain's words outside comments and docstrings "
                       f"(ask the TaskDomain for what the code needs; the words belong in the domain's package): {found}")


def test_the_vocabulary_check_sees_what_it_must(tmp_path):
    """The banned words are each domain's own (shelves, stock, fridge-like receptacles, a
    plugin's beds) and not what every domain shares; the scan finds them in code and strings and
    not in comments, docstrings or another library's names (a check that found nothing would pass
    every module)."""
    banned = banned_words()
    assert {"shelf", "shelves", "stock", "product", "receptacle", "sliced", "bed", "beds", "crop"} <= banned
    assert not {"robots", "floor", "place", "open", "load", "name"} & banned
    probe = tmp_path / "probe.py"
    probe.write_text('"""Counts stock on shelves."""\nimport itertools\n# the shelf\n'
                     'x = itertools.product([1], [2])\nfinal_stock = 1\ny = world["shelves"]\n'
                     'def f():\n    """per shelf"""\n    return f"{x} units on each receptacle"\n')
    assert [line for line, _ in vocabulary_lines(probe, banned)] == [5, 6, 9]


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


# ---------------------------------------------------------------------------------------------
# short rooms (issue 22): no function over 80 lines or 8 parameters without a reason
# ---------------------------------------------------------------------------------------------
MAX_LINES = 80
MAX_PARAMETERS = 8
#: why a step function may take more parameters (any function decorated with ``@step``)
STEP_REASON = ("a step's parameters are its declared inputs, each one a workflow names "
               "(engine/step.py: the signature is the contract)")
#: functions allowed over the limits, by qualified name, and why (keep it short)
LONG_ROOMS = {
    **dict.fromkeys(("pipflow.taskdomain.TaskDomain.simulate", "pipflow.taskdomain.TaskDomain.score",
                     "pipflow.warehouse.domain.WarehouseDomain.simulate",
                     "pipflow.household.domain.HouseholdDomain.simulate",
                     "pipflow.warehouse.simulation.simulate", "pipflow.scoring.score_run"),
                    "the TaskDomain protocol's simulate/score keywords (and the functions behind them: the "
                    "warehouse's simulation, the one score of every domain): a run's parts, each a value "
                    "the steps pass by name"),
    **dict.fromkeys(("pipflow.team.allocation.allocate", "pipflow.team.allocation.AllocationWalk.__init__"),
                    "the allocate steps' inputs passed through one keyword each (steps/allocate.py); the "
                    "concurrent baselines work builds on this signature, so it is regrouped after that merges"),
    "pipflow.engine.step.StepContext.__init__": "built by the executor and by hand in tests and notebooks (the "
                                                "step author's API): its keyword arguments are public",
}


def _is_step(function: ast.FunctionDef | ast.AsyncFunctionDef) -> bool:
    return any(isinstance(d, ast.Call) and getattr(d.func, "id", getattr(d.func, "attr", "")) == "step"
               for d in function.decorator_list)


def long_rooms(path: Path, module: str) -> dict[str, str]:
    """``{qualified name: what is over}`` for the functions of a module over :data:`MAX_LINES`
    lines or :data:`MAX_PARAMETERS` parameters (``self``/``cls`` not counted; ``*args`` and
    ``**options`` count one each; a step function's parameters are not counted)."""
    found: dict[str, str] = {}

    def visit(node: ast.AST, prefix: str) -> None:
        for child in ast.iter_child_nodes(node):
            if isinstance(child, ast.ClassDef):
                visit(child, f"{prefix}.{child.name}")
            elif isinstance(child, (ast.FunctionDef, ast.AsyncFunctionDef)):
                name = f"{prefix}.{child.name}"
                a = child.args
                params = [p for p in a.posonlyargs + a.args + a.kwonlyargs if p.arg not in ("self", "cls")]
                count = len(params) + (a.vararg is not None) + (a.kwarg is not None)
                lines = child.end_lineno - child.lineno + 1
                over = ([f"{lines} lines"] if lines > MAX_LINES else []) + (
                    [f"{count} parameters"] if count > MAX_PARAMETERS and not _is_step(child) else [])
                if over:
                    found[name] = ", ".join(over)
                visit(child, name)

    visit(ast.parse(path.read_text(encoding="utf-8")), module)
    return found


def test_no_function_is_over_80_lines_or_8_parameters_without_a_reason():
    found = {name: over for module, path in modules().items() for name, over in long_rooms(path, module).items()
             if name not in LONG_ROOMS}
    assert not found, ("functions over 80 lines or 8 parameters: split them, or group parameters that travel "
                       f"together into a small value object (or list the function in LONG_ROOMS with why): {found}")
    stale = sorted(set(LONG_ROOMS) - {name for module, path in modules().items() for name in long_rooms(path, module)})
    assert not stale, f"LONG_ROOMS lists functions that are short now (remove them): {stale}"


def test_the_room_check_sees_what_it_must(tmp_path):
    """The check counts lines and parameters (not self, a step's inputs), names nested functions
    and methods by their qualified names, and passes short ones (a check that found nothing
    would pass every module)."""
    probe = tmp_path / "probe.py"
    body = "\n".join("    x = 1" for _ in range(80))
    probe.write_text(f"def long():\n{body}\n"
                     "def short(a, b, c, d, e, f, g, h):\n    pass\n"
                     "def wide(a, b, c, d, e, f, g, h, *rest):\n    pass\n"
                     "class C:\n    def m(self, a, b, c, d, e, f, g, h, i):\n        def inner():\n            pass\n"
                     "@step('s')\ndef s(ctx, a, b, c, d, e, f, g, h, i):\n    pass\n")
    assert long_rooms(probe, "probe") == {"probe.long": "81 lines", "probe.wide": "9 parameters",
                                          "probe.C.m": "9 parameters"}
