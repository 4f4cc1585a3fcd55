"""Answers in the baselines' formats (CoT plans, SMART-LLM code, LaMMA-P summaries and per-robot
problems) written from a known-good robot plan, and a responder for tests/fake_openai.py that
answers each baseline's questions by the command and the stage they ask about, so runs in
parallel (a bench) get the right answers whatever their order.

A gold robot plan is a list of :class:`Gold` steps: a team action, its robots, the steps it
waits for. Warehouse golds come from the offline PIP-LLM run of the task (its schedule: the
plan, the IP's robots, the dependency graph); household golds are written by hand in the tests.
The writers below put one plan into each format, the way a model that understood the task would.
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import Callable

import pipflow


@dataclass
class Gold:
    id: str
    action: str
    args: list[str]
    robots: list[str]
    after: list[str] = field(default_factory=list)


def gold_from_pip_llm(workflow: str, command: str, **inputs) -> list[Gold]:
    """The offline PIP-LLM run's plan as robot steps: the schedule's order and robots, the
    dependency graph's edges."""
    run = pipflow.run(workflow, command=command, **inputs)
    assert run.status == "succeeded", run.error
    preds: dict[str, list[str]] = {}
    for u, v in run.outputs["graph"]["edges"]:
        preds.setdefault(v, []).append(u)
    return [Gold(s["id"], s["action"], list(s["args"]), list(s["robots"]), preds.get(s["id"], []))
            for s in run.outputs["schedule"]["subtasks"]]


def levels(steps: list[Gold]) -> dict[str, int]:
    """1 + the longest chain of steps before each step (the steps come in an order that respects
    ``after``)."""
    level: dict[str, int] = {}
    for s in steps:
        level[s.id] = 1 + max((level[a] for a in s.after), default=0)
    return level


def call_name(action: str) -> str:
    return "".join(part[:1].upper() + part[1:] for part in re.split(r"[-_]+", action) if part)


def cot_answer(steps: list[Gold]) -> str:
    """Reasoning, then the plan by levels (each level after the one before)."""
    level = levels(steps)
    lines = [f"{level[s.id]}. {', '.join(s.robots)}: ({' '.join([s.action, *s.args])})"
             for s in sorted(steps, key=lambda s: level[s.id])]
    return ("Let me think step by step. I work out what must change and which robots can do each action.\n\n"
            "PLAN:\n" + "\n".join(lines) + "\nEND\n")


def smart_llm_answer(steps: list[Gold], team: list[str]) -> str:
    """One function per step (a team passes its whole robot_list, one robot robot_list[0]);
    each level's functions run as threads, joined before the next level; a level of one step is
    a plain call."""
    level = levels(steps)
    out = ["```python", "import threading", "import time", ""]
    for k, s in enumerate(steps, 1):
        robots = "robot_list" if len(s.robots) > 1 else "robot_list[0]"
        names = ", ".join(f"'{a}'" for a in s.args)
        out += [f"def subtask_{k}(robot_list):", f"    # SubTask {k}: {s.action} {' '.join(s.args)}",
                f"    {call_name(s.action)}({robots}, {names})", ""]
    for lv in sorted(set(level.values())):
        members = [(k, s) for k, s in enumerate(steps, 1) if level[s.id] == lv]
        if len(members) == 1:
            k, s = members[0]
            out.append(f"subtask_{k}([{', '.join(f'robots[{team.index(r)}]' for r in s.robots)}])")
            continue
        for k, s in members:
            out.append(f"task{k}_thread = threading.Thread(target=subtask_{k}, "
                       f"args=([{', '.join(f'robots[{team.index(r)}]' for r in s.robots)}],))")
        out += [f"task{k}_thread.start()" for k, _ in members]
        out += [f"task{k}_thread.join()" for k, _ in members]
    out += ["# Task done", "```"]
    return "\n".join(out) + "\n"


def summary_answer(steps: list[Gold], objects: Callable[[Gold], list[str]] | None = None) -> str:
    """LaMMA-P's problem content summary: one subtask per step, in its order."""
    number = {s.id: k for k, s in enumerate(steps, 1)}
    out = ["The allocation above, summed up.", "", "Problem content summary:"]
    for k, s in enumerate(steps, 1):
        out += [f"SubTask {k}: {s.action} {' '.join(s.args)}", f"Assigned Robot: {', '.join(s.robots)}",
                f"Objects Involved: {', '.join((objects or (lambda g: g.args))(s))}",
                f"After: {', '.join(str(number[a]) for a in s.after) or 'none'}"]
    return "\n".join(out) + "\n"


def warehouse_problems(steps: list[Gold], world: dict) -> dict[int, str]:
    """One robot-level problem per step (domains/warehouse-robots.pddl): the shelves, product and
    robots it uses, their stock and load when the step starts (the steps applied in their order),
    the goal the step's units on its target shelf."""
    stock = {s: dict(items) for s, items in world["stock"].items()}
    out = {}
    for k, s in enumerate(steps, 1):
        src, dst, product, magnitude = s.args
        units = int(magnitude.removeprefix("magnitude"))
        for sh in (src, dst):  # a shelf the world lacks (a model's mistake) starts empty
            stock.setdefault(sh, {})
        load = {sh: sum(stock[sh].values()) for sh in (src, dst)}
        have = {sh: stock[sh].get(product, 0) for sh in (src, dst)}
        mags = " ".join(f"magnitude{m}" for m in range(1, 7))
        carry = " ".join(f"(= (carry {r}) {world['robots'][r]['skills']['carry']})" for r in s.robots)
        amounts = " ".join(f"(= (amount magnitude{m}) {m})" for m in range(1, 7))
        out[k] = (f"```pddl\n(define (problem subtask{k}) (:domain warehouse-robots)\n"
                  f"  (:objects {src} {dst} - shelf {product} - product {mags} - magnitude {' '.join(s.robots)} - robot)\n"
                  f"  (:init (= (stock {src} {product}) {have[src]}) (= (stock {dst} {product}) {have[dst]})\n"
                  f"         (= (load {src}) {load[src]}) (= (load {dst}) {load[dst]})\n"
                  f"         (= (capacity {src}) {world['shelves'].get(src, {}).get('capacity', 30)}) "
                  f"(= (capacity {dst}) {world['shelves'].get(dst, {}).get('capacity', 30)})\n"
                  f"         {amounts}\n         {carry})\n"
                  f"  (:goal (= (stock {dst} {product}) {have[dst] + units})))\n```\n")
        stock[src][product] = have[src] - units
        stock[dst][product] = have[dst] + units
    return out


# ---------------------------------------------------------------------------------------------
# which question a prompt asks (the baselines' templates in prompts/)
# ---------------------------------------------------------------------------------------------
def stage_of(text: str) -> tuple[str, int | None]:
    """The stage a rendered prompt asks for, and for a LaMMA-P problem its subtask number."""
    m = re.search(r"Write the problem of SubTask (\d+)", text)
    if m:
        return ("validate" if "The PDDL validator found these problems" in text else "problem"), int(m.group(1))
    if "It cannot be read:" in text and "Write the whole problem content summary again" in text:
        return "summary-fix", None
    if "Finish the problem content summary" in text:
        return "summary", None
    if "Allocate the subtasks:" in text:
        return "allocate", None
    if "Decompose the task into subtasks" in text:
        return "decompose", None
    if text.rstrip().endswith("# CODE Solution"):
        return "code", None
    if text.rstrip().endswith("# SOLUTION"):
        return "allocate", None
    if "# Task Description:" in text.rstrip().rsplit("\n", 1)[-1]:
        return "decompose", None
    if "Then write a line PLAN:" in text:
        return "plan", None
    if "team-level PDDL problem" in text:
        return "pip-llm", None
    raise AssertionError(f"no baseline stage in the prompt: {text[-300:]!r}")


def method_of(text: str) -> str:
    if "Write the problem of SubTask" in text or "problem content summary" in text.lower() \
            or "Robot-level PDDL domain" in text or "Allocate the subtasks:" in text:
        return "lamma-p"
    if "Python-like code" in text or "# TASK ALLOCATION" in text or "from skills import" in text:
        return "smart-llm"
    if "Then write a line PLAN:" in text:
        return "cot"
    return "pip-llm"


def responder(answers: dict[str, dict[str, dict]]) -> Callable[[dict], str]:
    """``answers[command][method]``: ``{stage: text}`` (``problem``/``validate``: ``{n: text}``). The
    prompt's command is the longest command of ``answers`` it contains."""
    def respond(body: dict) -> str:
        text = "\n".join(m.get("content") or "" for m in body.get("messages", []))
        command = max((c for c in answers if c in text), key=len, default=None)
        assert command is not None, f"no known command in the prompt: {text[-300:]!r}"
        stage, number = stage_of(text)
        entry = answers[command][method_of(text) if stage != "pip-llm" else "pip-llm"]
        got = entry.get(stage, "")
        return got[number] if isinstance(got, dict) else got
    return respond
