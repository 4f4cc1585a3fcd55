"""The SMART-LLM baseline's reader: the model's Python-like plan read as data, never run.

SMART-LLM (Kannan et al., arXiv 2309.10062; code at SMARTlab-Purdue/SMART-LLM) asks the model,
in three few-shot prompts, to decompose the task into subtasks (functions of skill calls), to
form coalitions and allocate them (prose), and to write the allocated plan as Python: each
subtask a function whose skill calls name the robots (``robot_list[0]``, or the whole
``robot_list`` for a team), run one after another by plain calls or side by side by threads::

    def carry_crate(robot_list):
        Carry(robot_list, 'crate', 'dock', 'bay')

    def switch_off_light(robot_list):
        SwitchOff(robot_list[0], 'light', 'light')

    task1_thread = threading.Thread(target=carry_crate, args=([robots[0], robots[1]],))
    task2_thread = threading.Thread(target=switch_off_light, args=([robots[2]],))
    task1_thread.start()
    task2_thread.start()
    task1_thread.join()
    task2_thread.join()

Their pipeline executes that text in AI2-THOR. pipflow never executes it: :func:`read_smart_llm`
parses it with Python's ``ast`` (which builds a tree and runs nothing) and accepts exactly the
constructs of SMART-LLM's own examples: function definitions with positional parameters whose
bodies hold skill calls, ``time.sleep(N)`` (a wait, ignored) and docstrings; at the top level
calls of those functions, skill calls, ``t = threading.Thread(target=f, args=(...))``,
``t.start()``, ``t.join()``, ``time.sleep(N)``; robots as ``robots[i]`` (the team as the prompt
lists it), a function's parameter, ``param[i]``, or a list of these; the skill's other arguments
as names in quotes; the imports their prompt itself shows (``threading``, ``time``, ``skills``)
as no-ops. Everything else (other imports, ``exec``, ``open``, attribute access beyond
``threading.Thread``/``.start()``/``.join()``/``time.sleep``, lambdas, loops, conditionals,
comprehensions, assignments other than a thread, keyword arguments, ...) is refused with its
line and column: their examples use none of it, and a reader that accepted it would have to
evaluate it.

The order is Python's: a function's skill calls one after another; a plain call after what the
main program has waited for so far; a started thread from that moment, beside the main program;
``join`` makes the main program wait for the thread's last action. Robot indices past the team
are the world's business (the step cannot be placed: Exe < 1), not a format error.
"""
from __future__ import annotations

import ast
import re
from dataclasses import dataclass, field

from pipflow.baselines.located import Issue, Unreadable, snippet
from pipflow.baselines.robotplan import RobotStep
from pipflow.baselines.skills import Skill
from pipflow.suggest import did_you_mean_clause

#: the modules SMART-LLM's prompts import (``from skills import ...``, ``import time``, ``import threading``)
PRELUDE_MODULES = ("threading", "time", "skills")
#: the name of the team in SMART-LLM's prompts (``robots = [...]``)
TEAM = "robots"
FENCE = re.compile(r"^[ \t]*```[^\n]*$", re.MULTILINE)
#: what a statement of each kind is called in a message
CONSTRUCTS = {ast.For: "a `for` loop", ast.AsyncFor: "a `for` loop", ast.While: "a `while` loop", ast.If: "an `if`",
              ast.With: "a `with` block", ast.AsyncWith: "a `with` block", ast.Try: "a `try` block",
              ast.ClassDef: "a class", ast.Return: "a `return`", ast.Global: "a `global`",
              ast.Nonlocal: "a `nonlocal`", ast.Delete: "a `del`", ast.Raise: "a `raise`", ast.Assert: "an `assert`",
              ast.AugAssign: "an augmented assignment", ast.AnnAssign: "an annotated assignment",
              ast.AsyncFunctionDef: "an async function", ast.Lambda: "a lambda", ast.ListComp: "a comprehension",
              ast.SetComp: "a comprehension", ast.DictComp: "a comprehension", ast.GeneratorExp: "a generator",
              ast.Break: "a `break`", ast.Continue: "a `continue`"}
CALLS = ("a skill, a function defined above, threading.Thread(...), time.sleep(N), or a thread's "
         ".start() / .join()")


@dataclass
class _Call:
    """A skill call as written: the skill, the robot expression, the object names, where."""

    skill: Skill
    robots: ast.expr
    args: list[str]
    line: int
    column: int


@dataclass
class _Function:
    name: str
    params: list[str]
    calls: list[_Call] = field(default_factory=list)
    line: int = 0


@dataclass
class _Thread:
    function: _Function
    bound: list[list[str]]
    problems: list[str]
    started: bool = False
    last: list[str] = field(default_factory=list)


def code_of(text: str) -> str:
    """The code of an answer, line numbers kept: inside code fences when the answer has any
    (prose and fence lines blanked; a block left open runs to the end), else the whole answer."""
    fences = list(FENCE.finditer(text))
    if not fences:
        return text
    lines = text.split("\n")
    keep = [False] * len(lines)
    fence_lines = [text.count("\n", 0, m.start()) for m in fences]
    if len(fence_lines) % 2:  # the last block never closed (an answer cut off): it runs to the end
        fence_lines.append(len(lines))
    for open_, close in zip(fence_lines[0::2], fence_lines[1::2]):
        for k in range(open_ + 1, close):
            keep[k] = True
    return "\n".join(line if keep[k] else "" for k, line in enumerate(lines))


def _where(node: ast.AST) -> tuple[int, int]:
    return getattr(node, "lineno", 1), getattr(node, "col_offset", 0) + 1


def _source(code: str, node: ast.AST) -> str:
    return snippet(ast.get_source_segment(code, node) or ast.dump(node))


def _dotted(node: ast.expr) -> str | None:
    """``threading.Thread`` for an attribute chain of names, the name for a name, else None."""
    if isinstance(node, ast.Name):
        return node.id
    if isinstance(node, ast.Attribute):
        head = _dotted(node.value)
        return f"{head}.{node.attr}" if head else None
    return None


class _Reader:
    def __init__(self, code: str, skills: list[Skill], team: list[str]):
        self.code = code
        self.skills = {s.call: s for s in skills}
        self.team = team
        self.functions: dict[str, _Function] = {}
        self.threads: dict[str, _Thread] = {}
        self.issues: list[Issue] = []
        self.steps: list[RobotStep] = []
        self.main_after: list[str] = []

    # -- messages ---------------------------------------------------------------------------
    def issue(self, node: ast.AST, message: str) -> None:
        line, column = _where(node)
        self.issues.append(Issue(line, column, message))

    def refuse_construct(self, node: ast.AST, where: str) -> None:
        kind = CONSTRUCTS.get(type(node), f"`{type(node).__name__}`")
        self.issue(node, f"{kind} is not part of the SMART-LLM format ({where}): {_source(self.code, node)}; "
                         "the plan is read as data, never run")

    def unknown_call(self, node: ast.Call) -> None:
        name = _dotted(node.func)
        if name is None:
            self.issue(node, f"{_source(self.code, node.func)} is not something the format calls: call {CALLS}")
            return
        known = list(self.skills) + list(self.functions)
        self.issue(node, f"{name!r} is not a skill or a function defined above: call {CALLS} "
                         f"(skills: {', '.join(s.signature() for s in self.skills.values())})"
                         f"{did_you_mean_clause(name, known)}")

    # -- robots and names -------------------------------------------------------------------
    def robots_form(self, node: ast.expr, params: list[str]) -> bool:
        """Whether ``node`` is a robot expression of the format (checked where it is written)."""
        if isinstance(node, (ast.List, ast.Tuple)):
            return bool(node.elts) and all(self.robots_form(e, params) for e in node.elts)
        if isinstance(node, ast.Name):
            return node.id in params
        if isinstance(node, ast.Subscript) and isinstance(node.value, ast.Name):
            index = node.slice
            return (node.value.id == TEAM or node.value.id in params) and isinstance(index, ast.Constant) \
                and type(index.value) is int and index.value >= 0
        return False

    def robots_value(self, node: ast.expr, env: dict[str, list[str]], problems: list[str]) -> list[str]:
        """The robot names ``node`` stands for under ``env`` (a parameter's robots); an index past
        the list is a problem of the step (the world cannot place it), not of the format."""
        if isinstance(node, (ast.List, ast.Tuple)):
            return [r for e in node.elts for r in self.robots_value(e, env, problems)]
        if isinstance(node, ast.Name):
            return list(env.get(node.id, []))
        assert isinstance(node, ast.Subscript) and isinstance(node.value, ast.Name)
        index = node.slice.value  # type: ignore[union-attr]
        pool = self.team if node.value.id == TEAM else env.get(node.value.id, [])
        if index < len(pool):
            return [pool[index]]
        if not pool and problems:  # the parameter got no robot: that is said already
            return []
        what = f"{TEAM}[{index}]" if node.value.id == TEAM else f"{node.value.id}[{index}]"
        problems.append(f"{what} is past the {len(pool)} robot{'s' if len(pool) != 1 else ''} it indexes"
                        + (f" ({', '.join(pool)})" if pool else ""))
        return []

    def robots_hint(self, params: list[str]) -> str:
        names = [f"{TEAM}[i]"] + [p for p in params] + [f"{p}[i]" for p in params]
        return f"the robots are {', '.join(names)} or a list of these"

    # -- statements -------------------------------------------------------------------------
    def skill_call(self, node: ast.Call, params: list[str]) -> _Call | None:
        """A skill call checked as written (robots, names in quotes, the skill's arity)."""
        skill = self.skills.get(node.func.id)  # type: ignore[union-attr]
        assert skill is not None
        if node.keywords:
            self.issue(node.keywords[0], f"keyword arguments are not part of the format: {skill.signature()}")
            return None
        if not node.args:
            self.issue(node, f"{skill.call} needs the robots first: {skill.signature()}")
            return None
        if not self.robots_form(node.args[0], params):
            self.issue(node.args[0], f"{_source(self.code, node.args[0])} is not robots: {self.robots_hint(params)}")
            return None
        names = []
        for arg in node.args[1:]:
            if isinstance(arg, ast.Constant) and isinstance(arg.value, str):
                names.append(arg.value)
            else:
                self.issue(arg, f"{_source(self.code, arg)}: the arguments after the robots are names in quotes "
                                f"({skill.signature()})")
                return None
        if len(names) != len(skill.params):
            self.issue(node, f"{skill.call} takes the robots and {len(skill.params)} name"
                             f"{'s' if len(skill.params) != 1 else ''} ({skill.signature()}), got {len(names)}")
            return None
        line, column = _where(node)
        return _Call(skill, node.args[0], names, line, column)

    def sleep(self, node: ast.Call) -> bool:
        """``time.sleep(N)``: a wait in SMART-LLM's plans; ignored (the schedule times actions)."""
        if _dotted(node.func) != "time.sleep":
            return False
        if node.keywords or len(node.args) != 1 or not isinstance(node.args[0], ast.Constant) \
                or type(node.args[0].value) not in (int, float):
            self.issue(node, f"time.sleep takes one number of seconds: {_source(self.code, node)}")
        return True

    def function(self, node: ast.FunctionDef) -> None:
        a = node.args
        if node.decorator_list:
            self.issue(node.decorator_list[0], "decorators are not part of the format")
        if a.vararg or a.kwarg or a.kwonlyargs or a.defaults or a.kw_defaults or a.posonlyargs:
            self.issue(node, f"def {node.name}: only plain positional parameters (robot_list) are part of the format")
        if any(x.annotation for x in a.args) or node.returns:
            self.issue(node, f"def {node.name}: annotations are not part of the format")
        if node.name in self.skills or node.name == TEAM:
            self.issue(node, f"def {node.name}: the name is taken ({'a skill' if node.name in self.skills else 'the team'})")
        fn = _Function(node.name, [x.arg for x in a.args], line=node.lineno)
        for stmt in node.body:
            if isinstance(stmt, ast.Pass) or (isinstance(stmt, ast.Expr) and isinstance(stmt.value, ast.Constant)
                                              and isinstance(stmt.value.value, str)):
                continue
            if isinstance(stmt, ast.Expr) and isinstance(stmt.value, ast.Call):
                call = stmt.value
                if self.sleep(call):
                    continue
                if isinstance(call.func, ast.Name) and call.func.id in self.skills:
                    got = self.skill_call(call, fn.params)
                    if got is not None:
                        fn.calls.append(got)
                    continue
                if isinstance(call.func, ast.Name) and call.func.id in self.functions:
                    self.issue(call, f"{call.func.id}() inside {node.name}: a function holds skill calls only; "
                                     "call the functions at the top level")
                    continue
                self.unknown_call(call)
                continue
            self.refuse_construct(stmt, f"inside def {node.name}")
        self.functions[node.name] = fn

    def bound(self, fn: _Function, args: list[ast.expr], at: ast.AST) -> tuple[list[list[str]], list[str]] | None:
        """The robots each parameter of ``fn`` gets from a call's arguments (top-level names)."""
        if len(args) != len(fn.params):
            self.issue(at, f"{fn.name} takes {len(fn.params)} argument{'s' if len(fn.params) != 1 else ''} "
                           f"({', '.join(fn.params) or 'none'}), got {len(args)}")
            return None
        for arg in args:
            if not self.robots_form(arg, []):
                self.issue(arg, f"{_source(self.code, arg)} is not robots: pass {TEAM}[i] or a list of these")
                return None
        problems: list[str] = []
        return [self.robots_value(arg, {}, problems) for arg in args], problems

    def run(self, fn: _Function, values: list[list[str]], problems: list[str], after: list[str], called_at: int) -> list[str]:
        """Emit ``fn``'s skill calls, one after another, the first after ``after``; the ids of
        what the next action must wait for."""
        env = dict(zip(fn.params, values))
        last = list(after)
        for call in fn.calls:
            own = list(problems)
            robots = self.robots_value(call.robots, env, own)
            sid = f"a{len(self.steps) + 1}"
            self.steps.append(RobotStep(sid, call.skill.action, call.args, robots, last,
                                        f"line {call.line}, column {call.column} (called at line {called_at})", own))
            last = [sid]
        return last

    def thread(self, node: ast.Call, target_line: ast.AST) -> _Thread | None:
        """``threading.Thread(target=f, args=(...))`` checked; None after an issue."""
        if node.args:
            self.issue(node, "threading.Thread takes target=FUNCTION and args=(...) as keywords")
            return None
        kw = {k.arg: k.value for k in node.keywords}
        extra = sorted(set(kw) - {"target", "args"}, key=str)
        if extra:
            self.issue(node, f"threading.Thread takes target= and args= only, got {', '.join(map(str, extra))}=")
            return None
        target = kw.get("target")
        if not isinstance(target, ast.Name) or target.id not in self.functions:
            self.issue(target or node, f"the thread's target must be a function defined above, got "
                                       f"{_source(self.code, target) if target is not None else 'none'}")
            return None
        args = kw.get("args")
        if args is None:
            items: list[ast.expr] = []
        elif isinstance(args, (ast.Tuple, ast.List)):
            items = list(args.elts)
        else:
            self.issue(args, f"args= takes a tuple of the function's arguments, got {_source(self.code, args)}")
            return None
        got = self.bound(self.functions[target.id], items, node)
        if got is None:
            return None
        return _Thread(self.functions[target.id], got[0], got[1])

    def top(self, stmt: ast.stmt) -> None:
        if isinstance(stmt, ast.Import):
            for alias in stmt.names:
                if alias.name not in PRELUDE_MODULES or alias.asname:
                    self.issue(stmt, f"import {alias.name}: the plan may import only {', '.join(PRELUDE_MODULES)} "
                                     "(as the prompt does); it is read, never run")
            return
        if isinstance(stmt, ast.ImportFrom):
            if stmt.module not in PRELUDE_MODULES or stmt.level:
                self.issue(stmt, f"from {stmt.module} import ...: the plan may import only "
                                 f"{', '.join(PRELUDE_MODULES)} (as the prompt does); it is read, never run")
            return
        if isinstance(stmt, ast.FunctionDef):
            self.function(stmt)
            return
        if isinstance(stmt, ast.Pass) or (isinstance(stmt, ast.Expr) and isinstance(stmt.value, ast.Constant)
                                          and isinstance(stmt.value.value, str)):
            return
        if isinstance(stmt, ast.Assign):
            target = stmt.targets[0] if len(stmt.targets) == 1 else None
            value = stmt.value
            if not (isinstance(target, ast.Name) and isinstance(value, ast.Call)
                    and _dotted(value.func) == "threading.Thread"):
                self.issue(stmt, f"{_source(self.code, stmt)}: the only assignment of the format is "
                                 "NAME = threading.Thread(target=FUNCTION, args=(...))")
                return
            if target.id in (TEAM, *self.functions, *self.skills):
                self.issue(stmt, f"{target.id} = ...: the name is taken")
                return
            made = self.thread(value, stmt)
            if made is not None:
                self.threads[target.id] = made
            return
        if isinstance(stmt, ast.Expr) and isinstance(stmt.value, ast.Call):
            self.top_call(stmt.value)
            return
        self.refuse_construct(stmt, "at the top level")

    def top_call(self, call: ast.Call) -> None:
        if self.sleep(call):
            return
        func = call.func
        if isinstance(func, ast.Name) and func.id in self.skills:
            got = self.skill_call(call, [])
            if got is not None:
                problems: list[str] = []
                robots = self.robots_value(got.robots, {}, problems)
                sid = f"a{len(self.steps) + 1}"
                self.steps.append(RobotStep(sid, got.skill.action, got.args, robots, list(self.main_after),
                                            f"line {got.line}, column {got.column}", problems))
                self.main_after = [sid]
            return
        if isinstance(func, ast.Name) and func.id in self.functions:
            if call.keywords:
                self.issue(call.keywords[0], "keyword arguments are not part of the format")
                return
            got = self.bound(self.functions[func.id], list(call.args), call)
            if got is not None:
                self.main_after = self.run(self.functions[func.id], got[0], got[1], self.main_after, call.lineno)
            return
        if isinstance(func, ast.Attribute) and func.attr in ("start", "join"):
            if call.args or call.keywords:
                self.issue(call, f".{func.attr}() takes no arguments in the format")
                return
            if isinstance(func.value, ast.Call) and _dotted(func.value.func) == "threading.Thread" and func.attr == "start":
                made = self.thread(func.value, call)
                if made is not None:
                    made.last = self.run(made.function, made.bound, made.problems, self.main_after, call.lineno)
                return
            if isinstance(func.value, ast.Name) and func.value.id in self.threads:
                t = self.threads[func.value.id]
                if func.attr == "start":
                    if t.started:
                        self.issue(call, f"{func.value.id} is started twice (a thread starts once)")
                        return
                    t.started = True
                    t.last = self.run(t.function, t.bound, t.problems, self.main_after, call.lineno)
                else:
                    if not t.started:
                        self.issue(call, f"{func.value.id}.join() before {func.value.id}.start()")
                        return
                    self.main_after = sorted(set(self.main_after) | set(t.last), key=lambda s: int(s[1:]))
                return
            if isinstance(func.value, ast.Name):
                self.issue(call, f"{func.value.id!r} is not a thread assigned above "
                                 f"({', '.join(self.threads) or 'none'}){did_you_mean_clause(func.value.id, self.threads)}")
                return
        self.unknown_call(call)


def _refused_anywhere(tree: ast.AST, code: str) -> list[Issue]:
    """Constructs refused wherever they stand, even inside an argument (a lambda, a comprehension,
    a double-underscore name or attribute): said once each, precisely, besides the statement's
    own issue."""
    out = []
    for node in ast.walk(tree):
        line, column = _where(node)
        if isinstance(node, (ast.Lambda, ast.ListComp, ast.SetComp, ast.DictComp, ast.GeneratorExp, ast.NamedExpr,
                             ast.Await, ast.Yield, ast.YieldFrom)):
            kind = CONSTRUCTS.get(type(node), f"`{type(node).__name__}`")
            out.append(Issue(line, column, f"{kind} is not part of the SMART-LLM format: {_source(code, node)}"))
        elif isinstance(node, ast.Attribute) and node.attr.startswith("__"):
            out.append(Issue(line, column, f"the attribute {node.attr!r} is not part of the format (only "
                                           "threading.Thread, .start(), .join() and time.sleep are)"))
        elif isinstance(node, ast.Name) and node.id.startswith("__"):
            out.append(Issue(line, column, f"{node.id!r} is not part of the format (the plan is read as data, "
                                           "never run)"))
    return out


def read_smart_llm(text: str, skills: list[Skill], team: list[str]) -> list[RobotStep]:
    """The robot plan of a SMART-LLM code answer (``team``: the robots as the prompt lists them,
    ``robots[0]`` first); :class:`Unreadable` lists every problem located. Nothing is run."""
    code = code_of(text)
    try:
        tree = ast.parse(code, mode="exec")
    except SyntaxError as exc:
        line = int(exc.lineno or 1)
        shown = code.split("\n")[line - 1] if 0 < line <= code.count("\n") + 1 else ""
        raise Unreadable([Issue(line, int(exc.offset or 1), f"Python syntax: {exc.msg}: {snippet(shown)}")]) from None
    except (ValueError, RecursionError, MemoryError) as exc:  # NUL bytes, absurd nesting
        raise Unreadable([Issue(1, 1, f"the answer is not Python-like code: {exc}")]) from None
    reader = _Reader(code, skills, team)
    for stmt in tree.body:
        reader.top(stmt)
    issues = list(dict.fromkeys(reader.issues + _refused_anywhere(tree, code)))
    if not reader.steps and not issues:
        issues.append(Issue(1, 1, "the code runs no skill: define the subtasks as functions of skill calls and "
                                  "call them (or start them as threads) at the top level"))
    if issues:
        raise Unreadable(issues)
    return reader.steps
