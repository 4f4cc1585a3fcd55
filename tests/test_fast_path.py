"""The fast main path: no ConfigSpace/scipy.stats unless used, one shared read-only parse per
problem text, and pictures only when asked (real UP, real planner, real validator)."""
from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest
import yaml

from pipflow.team.dependency import build_graph
from pipflow.pddl.common import parse
from pipflow.pddl.debugger import debug_problem
from pipflow.pddl.solver import solve_problem
from pipflow.pddl.verifier import verify_plan
from pipflow.warehouse.problem import write_problem

ROOT = Path(__file__).resolve().parents[1]
DOMAIN = ROOT / "domains" / "warehouse.pddl"
WORLD = yaml.safe_load((ROOT / "benchmarks" / "warehouse" / "world.yaml").read_text())
META = yaml.safe_load((ROOT / "domains" / "warehouse.actions.yaml").read_text())
GOAL = {"shelf4": {"product3": 12, "product1": 5}}


def _snapshot(problem) -> str:
    """Everything a consumer could change: objects, fluents, actions, initial values, goals."""
    return "\n".join([str(problem), repr(sorted(map(str, problem.explicit_initial_values.items())))])


def test_consumers_share_one_parse_and_leave_it_unchanged():
    text = write_problem(WORLD, GOAL)
    report = debug_problem(text, str(DOMAIN), WORLD)
    assert report.ok, report.messages
    shared = parse(DOMAIN, text)
    assert shared is report.problem  # the debugger's parse is the one everybody gets
    assert parse(str(DOMAIN), text) is shared and parse(DOMAIN.read_text(), text) is shared
    before = _snapshot(shared)
    robots = {n: r["skills"]["carry"] for n, r in WORLD["robots"].items()}
    result = solve_problem(shared, "pipflow-transport", {"robots": robots, "rules": []})
    assert result.status == "solved" and result.plan
    assert verify_plan(shared, result.plan, WORLD).ok
    graph = build_graph(DOMAIN.read_text(), text, result.plan, META)
    assert len(graph["nodes"]) == len(result.plan)
    assert _snapshot(shared) == before  # nobody mutated the memoised problem
    other = write_problem(WORLD, {"shelf4": {"product3": 11}})
    assert parse(DOMAIN, other) is not shared  # content, not the path, is the key


def test_a_failed_parse_is_not_memoised():
    bad = write_problem(WORLD, GOAL).replace("(:goal", "(:goal (", 1)
    for _ in range(2):
        report = debug_problem(bad, str(DOMAIN), WORLD)
        assert not report.ok and "line" in report.messages[0]


def test_planning_does_not_import_scipy_stats_until_asked():
    """UP's engine base class imports ConfigSpace (and so scipy.stats, ~1 s) at import time;
    pipflow defers it. A whole debug/solve/verify pass must not load it, and asking an engine
    for its configuration space must still give the real object."""
    code = f"""
import sys
import yaml
from pipflow.pddl.debugger import debug_problem
from pipflow.pddl.solver import solve_problem
from pipflow.pddl.verifier import verify_plan
from pipflow.warehouse.problem import write_problem
world = yaml.safe_load(open({str(ROOT / 'benchmarks' / 'warehouse' / 'world.yaml')!r}))
report = debug_problem(write_problem(world, {GOAL!r}), {str(DOMAIN)!r}, world)
robots = {{n: r["skills"]["carry"] for n, r in world["robots"].items()}}
res = solve_problem(report.problem, "pipflow-transport", {{"robots": robots, "rules": []}})
assert verify_plan(report.problem, res.plan, world).ok
assert "scipy.stats" not in sys.modules, "scipy.stats was imported"
from unified_planning.engines import Engine
space = Engine.get_configuration_space()
import ConfigSpace
assert type(space).__name__ == "ConfigurationSpace" and isinstance(space, ConfigSpace.ConfigurationSpace)
print("ok")
"""
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=300)
    assert out.returncode == 0 and out.stdout.strip().endswith("ok"), out.stderr[-2000:]


def test_main_job_imports_neither_matplotlib_nor_scipy_stats(tmp_path):
    """The main job with the default pictures=auto draws nothing, so it must not pay for
    matplotlib (unit colours come from a table) nor for scipy.stats (ConfigSpace deferred); its
    travel graph is small, so it does not pay for scipy.sparse either (pipflow.team.travel.SMALL_GRAPH)."""
    code = f"""
import sys
from pipflow.engine.cli import main
code = main(["run", {str(ROOT / 'workflows' / 'warehouse.yaml')!r}, "--runs-dir", {str(tmp_path)!r}, "--no-cache", "-q"])
assert code == 0, code
heavy = [m for m in ("matplotlib", "scipy.stats", "ConfigSpace.hyperparameters", "scipy.sparse") if m in sys.modules]
assert not heavy, heavy
print("ok")
"""
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=300)
    assert out.returncode == 0 and out.stdout.strip().endswith("ok"), out.stdout[-1000:] + out.stderr[-2000:]


def test_common_colours_match_matplotlib():
    from matplotlib.colors import to_rgba

    from pipflow.bullet import colour_rgba

    for name in ("red", "Green", "blue", "magenta", "yellow", "cyan", "black", "white", "orange",
                 "purple", "grey", "gray", "brown", "teal", "#ff8800"):
        assert colour_rgba(name) == pytest.approx(to_rgba(name)), name
    assert colour_rgba("no-such-colour") == (0.5, 0.5, 0.5, 1.0)


def test_workflow_pictures_input(tmp_path):
    """auto (the default) draws nothing in the run; always draws the graph, Gantt and path map."""
    from pipflow.engine.cli import main

    for mode, drawn in (("auto", False), ("always", True)):
        runs = tmp_path / mode
        code = main(["run", str(ROOT / "workflows" / "warehouse.yaml"), "--runs-dir", str(runs), "--no-cache",
                     "-q", "-i", f"pictures={mode}"])
        assert code == 0
        run = next(runs.iterdir())
        pngs = sorted(p.name for p in run.rglob("*.png"))
        assert pngs == (["gantt.png", "graph.png", "paths.png"] if drawn else []), pngs


def test_picture_policy_by_mode_and_size():
    from pipflow import pictures

    schedule = {"robots": {f"r{i}": {"legs": [{"subtask": "s1"}] if i < 3 else []} for i in range(500)},
                "subtasks": [{"id": "s1", "robots": ["r0", "r1", "r2"]}]}
    assert pictures.size_of("gantt", schedule) == 3  # rows are the robots that work, not the fleet
    assert pictures.wanted("auto", "gantt", 3) and pictures.wanted(None, "graph", 80)
    assert not pictures.wanted("auto", "graph", 81) and pictures.wanted("always", "graph", 10_000)
    assert not pictures.wanted("never", "paths", 1)
    with pytest.raises(ValueError, match="pictures must be one of"):
        pictures.wanted("sometimes", "gantt", 1)


# --- the built command parser, cached (pipflow/language/earley.py) ------------------------------------
COMMANDS = ["shelf4 stores a dozen product3 and a quintet of product1.",
            "Move 3 product1 from shelf1 to shelf2 and shelf3.",  # ambiguous: readings kept as _ambig
            "shelf2 to hold 6 product3, and shelf4 too",  # ambiguous
            "Robot 0 must not move product1. Move 2 product2 to shelf1.",
            "four product1 to shelf2 and three to shelf3, taking them from shelf1"]


@pytest.fixture
def grammar_cache(tmp_path, monkeypatch):
    """A private parser cache folder and an empty in-memory cache (restored afterwards)."""
    from pipflow.language import earley

    folder = tmp_path / "grammar"
    monkeypatch.setenv(earley.ENV_DIR, str(folder))
    monkeypatch.setattr(earley, "_MEMORY", {})
    return folder


def _command_parser():
    from pipflow.language import earley
    from pipflow.language.optionals import nullable_optionals
    from pipflow.warehouse.language.grammar import GRAMMAR

    return earley.earley_parser(nullable_optionals(GRAMMAR), lexer=earley.ListLexer, keep_all_tokens=True,
                                ambiguity="explicit")


def _sentences():
    from pipflow.warehouse.language.lexicon import Lexicon
    from pipflow.warehouse.language.parser import keywords

    for command in COMMANDS:
        yield from Lexicon(WORLD, keywords()).sentences(command)


def _no_build(monkeypatch):
    """Make building a parser fail, so that a test sees whether one came from the cache."""
    from pipflow.language import earley

    def refuse(*args, **kwargs):
        raise AssertionError("the parser was built, not loaded")

    monkeypatch.setattr(earley, "_build", refuse)


def test_parser_from_disk_reads_like_a_fresh_one(grammar_cache, monkeypatch):
    from lark import Lark

    from pipflow.language import earley

    fresh = _command_parser()  # built, and stored
    stored = list(grammar_cache.glob("[0-9a-f]*.earley"))
    assert len(stored) == 1 and (grammar_cache / "CACHEDIR.TAG").read_text().startswith("Signature: 8a477f")
    monkeypatch.setattr(earley, "_MEMORY", {})
    _no_build(monkeypatch)
    loaded = _command_parser()
    assert isinstance(loaded, Lark) and loaded is not fresh
    assert _command_parser() is loaded  # the second call in a process is the memory
    ambiguous = 0
    for lexed in _sentences():
        a, b = fresh.parse(lexed.tokens), loaded.parse(lexed.tokens)
        assert a == b, " ".join(t.text for t in lexed.source)
        ambiguous += any(t.data == "_ambig" for t in b.iter_subtrees())
    assert ambiguous >= 2  # the ambiguous sentences kept all their readings
    assert {t.name for t in loaded.terminals} == {t.name for t in fresh.terminals}


def test_parsed_command_is_the_same_with_a_loaded_parser(grammar_cache, monkeypatch):
    """The whole reading (order statements and rules), not only the tree."""
    from pipflow.warehouse.language import forest, parser

    forest.all_readings_parser.cache_clear()
    try:
        first = [parser.parse(c, WORLD) for c in COMMANDS[:1] + COMMANDS[3:]]
        forest.all_readings_parser.cache_clear()
        from pipflow.language import earley

        monkeypatch.setattr(earley, "_MEMORY", {})
        _no_build(monkeypatch)
        assert [parser.parse(c, WORLD) for c in COMMANDS[:1] + COMMANDS[3:]] == first
    finally:
        forest.all_readings_parser.cache_clear()  # later tests get the process's own parser back


@pytest.mark.parametrize("damage", ["garbage", "flipped byte", "truncated", "empty", "other key"])
def test_a_damaged_cache_file_is_rebuilt(grammar_cache, monkeypatch, damage):
    from pipflow.language import earley

    _command_parser()
    entry = next(grammar_cache.glob("*.earley"))
    raw = entry.read_bytes()
    head, _, body = raw.partition(b"\n")
    broken = {"garbage": b"not a parser at all",
              "flipped byte": head + b"\n" + body[:500] + bytes([body[500] ^ 0xFF]) + body[501:],
              "truncated": raw[: len(raw) // 2],
              "empty": b"",
              "other key": head.replace(entry.stem.encode(), b"0" * 64) + b"\n" + body}[damage]
    entry.write_bytes(broken)
    monkeypatch.setattr(earley, "_MEMORY", {})
    parser = _command_parser()  # rebuilt silently
    lexed = next(_sentences())
    assert parser.parse(lexed.tokens).data == "start"
    assert entry.read_bytes() != broken  # rewritten whole (it loads below)
    monkeypatch.setattr(earley, "_MEMORY", {})
    _no_build(monkeypatch)
    assert _command_parser().parse(lexed.tokens) == parser.parse(lexed.tokens)  # and loads again
    assert not list(grammar_cache.glob(".tmp-*"))


def test_a_parser_is_kept_out_of_the_garbage_collectors_sweeps(grammar_cache):
    """A parser lives as long as the process: its objects are frozen (``gc.freeze``), so the
    collections that reading commands sets off do not walk them again and again."""
    import gc

    from pipflow.language import earley

    gc.unfreeze()
    try:
        parser = earley.earley_parser('start: "a" b\nb: "b" | "c"\n')
        assert gc.get_freeze_count() > 0
        assert parser.parse("ab")   # a frozen parser reads as ever
    finally:
        gc.unfreeze()


def test_another_grammar_or_option_is_another_entry(grammar_cache):
    from lark import Token

    from pipflow.language import earley

    one = earley.earley_parser('start: "a" B\nB: "b"\n', lexer="dynamic")
    two = earley.earley_parser('start: "a" C\nC: "c"\n', lexer="dynamic")
    assert one is not two and len(list(grammar_cache.glob("*.earley"))) == 2
    assert one.parse("ab").children == [Token("B", "b")]
    assert two.parse("ac").children == [Token("C", "c")]
    with pytest.raises(Exception):
        two.parse("ab")
    kept = earley.earley_parser('start: "a" B\nB: "b"\n', lexer="dynamic", keep_all_tokens=True)
    assert kept is not one and len(kept.parse("ab").children) == 2
    assert len(list(grammar_cache.glob("*.earley"))) == 3
    assert earley.parser_key("x", {"a": 1}) != earley.parser_key("y", {"a": 1}) != earley.parser_key("x", {"a": 2})


def test_parser_cache_writes_only_into_its_own_folder(tmp_path, monkeypatch):
    """A folder holding the user's files is left alone (the parser is still built), and an
    empty string turns the disk cache off."""
    from pipflow.language import earley

    user = tmp_path / "mine"
    user.mkdir()
    (user / "thesis.tex").write_text("\\chapter{x}\n")
    for setting in (str(user), "", str(user / "thesis.tex")):
        monkeypatch.setenv(earley.ENV_DIR, setting)
        monkeypatch.setattr(earley, "_MEMORY", {})
        assert earley.earley_parser('start: "a"\n', lexer="dynamic").parse("a").data == "start"
    assert [p.name for p in user.iterdir()] == ["thesis.tex"]
    monkeypatch.delenv(earley.ENV_DIR)
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "xdg"))
    assert earley.cache_dir() == tmp_path / "xdg" / "pipflow" / "grammar"


def test_concurrent_processes_share_one_cache(tmp_path):
    """Two processes building at once both get a working parser and leave one whole entry."""
    folder = tmp_path / "grammar"
    code = """
from pipflow.language import earley
p = earley.earley_parser('start: "a" B\\nB: "b"\\n', lexer="dynamic")
assert p.parse("ab").data == "start"
print("ok")
"""
    env = {**__import__("os").environ, "PIPFLOW_GRAMMAR_CACHE_DIR": str(folder)}
    procs = [subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                              text=True, env=env) for _ in range(3)]
    for proc in procs:
        out, err = proc.communicate(timeout=120)
        assert proc.returncode == 0 and out.strip() == "ok", err[-2000:]
    assert len(list(folder.glob("*.earley"))) == 1 and not list(folder.glob(".tmp-*"))


def test_old_parsers_are_pruned_and_other_files_kept(grammar_cache, monkeypatch):
    """Each grammar edit is a new key: only the newest KEEP parsers stay; a crashed writer's old
    temporary file goes; files of other names (and fresh temporary files) stay."""
    import os

    from pipflow.language import earley

    monkeypatch.setattr(earley, "KEEP", 2)
    grammars = [f'start: "a{i}"\n' for i in range(4)]
    for i, text in enumerate(grammars):
        earley.earley_parser(text, lexer="dynamic")
        for entry in grammar_cache.glob("[0-9a-f]*.earley"):  # distinct modification times, oldest first
            os.utime(entry, (entry.stat().st_mtime - 10, entry.stat().st_mtime - 10))
        if i == 1:
            old_tmp, new_tmp = grammar_cache / ".tmp-crashed.earley", grammar_cache / ".tmp-writing.earley"
            old_tmp.write_bytes(b"half")
            new_tmp.write_bytes(b"half")
            os.utime(old_tmp, (1, 1))
            (grammar_cache / "notes.txt").write_text("kept")
    kept = sorted(p.name for p in grammar_cache.glob("*.earley") if not p.name.startswith("."))
    newest = sorted(f"{earley.parser_key(t, {'parser': 'earley', 'lexer': 'dynamic'})}.earley" for t in grammars[2:])
    assert kept == newest
    assert not old_tmp.exists() and new_tmp.exists() and (grammar_cache / "notes.txt").exists()


def test_a_parser_loaded_again_outlives_one_written_later_but_not_used(grammar_cache, monkeypatch):
    """Pruning keeps the parsers in use: loading one from disk counts as using it, so a world's
    parser read by every run is not pushed out by parsers built once for other worlds."""
    import os

    from lark import Token

    from pipflow.language import earley

    monkeypatch.setattr(earley, "KEEP", 2)
    grammars = [f"start: A{i}\n%declare A{i}\n" for i in range(3)]

    def entry(text: str):
        key = earley.parser_key(text, {"parser": "earley", "lexer": earley.ListLexer})
        return grammar_cache / f"{key}.earley"

    earley.earley_parser(grammars[0], lexer=earley.ListLexer)
    earley.earley_parser(grammars[1], lexer=earley.ListLexer)
    os.utime(entry(grammars[0]), (1000, 1000))   # the first written long before the second
    os.utime(entry(grammars[1]), (2000, 2000))
    monkeypatch.setattr(earley, "_MEMORY", {})    # a new process: the first comes from disk
    built, build = [], earley._build
    monkeypatch.setattr(earley, "_build", lambda text, options: built.append(text) or build(text, options))
    assert earley.earley_parser(grammars[0], lexer=earley.ListLexer).parse([Token("A0", "x")])
    earley.earley_parser(grammars[2], lexer=earley.ListLexer)
    assert built == [grammars[2]]
    assert entry(grammars[0]).exists() and entry(grammars[2]).exists()
    assert not entry(grammars[1]).exists()


def test_a_parser_file_others_may_write_is_not_loaded(grammar_cache, monkeypatch):
    """Unpickling runs code: a file writable by the group or others is rebuilt, not loaded."""
    from pipflow.language import earley

    earley.earley_parser('start: "a"\n', lexer="dynamic")
    entry = next(grammar_cache.glob("[0-9a-f]*.earley"))
    assert entry.stat().st_mode & 0o077 == 0  # written private
    entry.chmod(0o666)
    monkeypatch.setattr(earley, "_MEMORY", {})
    built = []
    monkeypatch.setattr(earley, "_build", lambda g, o: built.append(g) or earley.Lark(g, **o))
    assert earley.earley_parser('start: "a"\n', lexer="dynamic").parse("a").data == "start"
    assert built == ['start: "a"\n']  # rebuilt, and stored again private
    assert entry.stat().st_mode & 0o077 == 0


# --- unified-planning's configuration file, found without inspect.stack() (pipflow/pddl/upconfig.py) ---
def test_up_config_locations_are_ups_own():
    """The same candidate files as UP's function, from the main thread and from a step's thread."""
    import threading

    import unified_planning.engines.factory as factory

    from pipflow.pddl import upconfig
    from pipflow.pddl.common import environment

    environment()
    assert factory.get_possible_config_locations is upconfig.config_locations  # in place before the factory
    import inspect
    from pathlib import PurePath

    def ups() -> list[str]:  # UP's own code (unified_planning/engines/factory.py), kept here to compare
        files = []
        for p in PurePath(os.path.abspath(inspect.stack()[-1].filename)).parents:
            files += [os.path.join(p, "up.ini"), os.path.join(p, ".up.ini")]
        home = os.path.expanduser("~")
        return files + [os.path.join(home, n) for n in ("up.ini", ".up.ini", ".uprc")]

    seen = []
    assert upconfig.config_locations() == ups()
    worker = threading.Thread(target=lambda: seen.append(upconfig.config_locations() == ups()))
    worker.start()
    worker.join()
    assert seen == [True]


def test_an_up_ini_above_the_script_still_configures_the_planners(tmp_path):
    folder = tmp_path / "project" / "scripts"
    folder.mkdir(parents=True)
    (tmp_path / "project" / "up.ini").write_text("[global]\nengine_preference_list: enhsp\n")
    script = folder / "show.py"
    script.write_text("from pipflow.pddl.common import environment\n"
                      "print(environment().factory.preference_list)\n")
    out = subprocess.run([sys.executable, str(script)], capture_output=True, text=True, timeout=300, cwd=tmp_path)
    assert out.returncode == 0, out.stderr[-2000:]
    preferred = out.stdout.strip().strip("[]").replace("'", "").split(", ")
    assert preferred[0] == "enhsp" and "fast-downward" not in preferred  # the file's list, not UP's default


def test_a_new_process_loads_the_parser_another_one_stored(tmp_path):
    """Across processes (another hash seed, nothing in memory): the second process parses with the
    stored parser, builds nothing, and reads the commands exactly as the first one did."""
    code = f"""
import json, sys
import yaml
from pipflow.language import earley
from pipflow.warehouse.language import parser
if sys.argv[1] == "load":
    def refuse(*args, **kwargs):
        raise SystemExit("built, not loaded")
    earley._build = refuse
world = yaml.safe_load(open({str(ROOT / 'benchmarks' / 'warehouse' / 'world.yaml')!r}))
print(json.dumps([parser.parse(c, world) for c in {COMMANDS!r}], sort_keys=True))
"""
    env = {**os.environ, "PIPFLOW_GRAMMAR_CACHE_DIR": str(tmp_path / "grammar")}
    runs = []
    for mode, seed in (("build", "1"), ("load", "2")):
        out = subprocess.run([sys.executable, "-c", code, mode], capture_output=True, text=True, timeout=300,
                             env={**env, "PYTHONHASHSEED": seed})
        assert out.returncode == 0, out.stderr[-2000:]
        runs.append(out.stdout)
    assert runs[0] == runs[1] and '"statements"' in runs[0]


# --- travel: small graphs searched with networkx, large ones with scipy (pipflow/team/travel.py) ------------
def _grid_world(shelves: int, robots: int, seed: int) -> dict:
    import random

    rng = random.Random(seed)
    cols = 4
    out = {f"s{i}": {"x": 3 + 12 * (i % cols), "y": 4 + 7 * (i // cols), "width": 8, "depth": 2, "capacity": 10,
                     "access": [7 + 12 * (i % cols), 3 + 7 * (i // cols)]} for i in range(shelves)}
    width, height = 12 * cols + 4, 7 * ((shelves + cols - 1) // cols) + 6
    starts = {}
    while len(starts) < robots:
        p = [round(rng.uniform(0, width), 2), round(rng.uniform(0, height), 2)]
        if not any(s["x"] - 1 <= p[0] <= s["x"] + s["width"] + 1 and s["y"] - 1 <= p[1] <= s["y"] + s["depth"] + 1
                   for s in out.values()):
            starts[f"r{len(starts)}"] = {"start": p, "skills": {"carry": 1}}
    return {"floor": {"width": width, "height": height}, "shelves": out, "robots": starts}


@pytest.mark.parametrize("world", [WORLD, _grid_world(6, 15, 1), _grid_world(12, 20, 2)],
                         ids=["warehouse", "6 shelves", "12 shelves"])
def test_small_graph_search_gives_scipys_distances_and_paths(world, monkeypatch):
    """Both searches on the same visibility graph: the same distances (to 1e-9), and paths of
    those lengths that cross no shelf; and the small world really takes the networkx search."""
    import math

    from pipflow.team import travel

    results = {}
    for name, limit in (("networkx", 10**9), ("scipy", 0)):
        monkeypatch.setattr(travel, "_GEOMETRIES", type(travel._GEOMETRIES)())
        monkeypatch.setattr(travel, "SMALL_GRAPH", limit)
        tm = travel.TravelMap(world)
        places = list(world["shelves"])
        pairs = [(r, s) for r in world["robots"] for s in places] + [(a, b) for a in places for b in places if a < b]
        dist = [tm.distance(a, b) for a, b in pairs]
        paths = [tm.path(a, b) for a, b in pairs]
        for d, path in zip(dist, paths):
            assert sum(math.dist(path[k], path[k + 1]) for k in range(len(path) - 1)) == pytest.approx(d, abs=1e-9)
            assert not any(travel._rect_hits_segment(r, tuple(path[k]), tuple(path[k + 1]))
                           for r in tm.footprints.values() for k in range(len(path) - 1))
        results[name] = dist
        geo = tm.geometry()
        assert (geo._small is not None) == (name == "networkx")
    assert results["networkx"] == pytest.approx(results["scipy"], abs=1e-9)
