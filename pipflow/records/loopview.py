"""The run report's account of the refinement loop (generate, debug, solve, verify: its rounds and
what each said) and of what the command was understood to mean, in the task domain's words.
"""
from __future__ import annotations

from pathlib import Path
from typing import Any

from pipflow import values
from pipflow.errors import UserError
from pipflow.records.htmlparts import esc, read_json, table
from pipflow.records.runrecord import find_step
from pipflow.taskdomain import plain_words
from pipflow.taskdomains import domain_named, task_domain


#: the part each family of step outputs plays in a round of the refinement loop
_ROLES = {values.READING: "generate", values.DEBUG: "debug", values.PLAN: "solve", values.VERIFY: "verify",
          values.CHECK: "check"}


def loop_rounds(d: Path, shapes: dict[str, str]) -> list[dict]:
    """Every round of every loop in the record: ``{"loop", "n", "generate", "debug", "verify",
    "solve", "check"}``, each the outputs of the inner step that plays that part (found by the
    family its outputs declare, so any workflow's loop is shown) plus the step's artifact folder
    under ``_dir``."""
    rounds = []
    for it_dir in sorted((d / "steps").glob("*/iterations/*"), key=lambda p: (p.parent.parent.name, _int(p.name))):
        r: dict[str, Any] = {"loop": it_dir.parent.parent.name, "n": _int(it_dir.name)}
        for sd in sorted(p for p in it_dir.iterdir() if p.is_dir()):
            out = read_json(sd / "outputs.json")
            if not isinstance(out, dict):
                out = {}
            role = _ROLES.get(shapes.get(sd.name, ""))
            if role is not None:
                r[role] = {**out, "_dir": sd, "_id": sd.name}
        gen = r.get("generate")
        if gen is not None and not gen.get("messages"):  # a failed generate keeps its prompt as an artifact
            gen["messages"] = read_json(gen["_dir"] / "artifacts" / "messages.json", []) or []
        if gen is not None and not gen.get("response") and (gen["_dir"] / "artifacts" / "response.txt").is_file():
            gen["response"] = (gen["_dir"] / "artifacts" / "response.txt").read_text(encoding="utf-8", errors="replace")
        rounds.append(r)
    return rounds


def _int(text: str) -> int:
    return int(text) if text.isdigit() else 0


def _messages_of(r: dict, part: str) -> list[str]:
    out = r.get(part) or {}
    return [str(m) for m in (out.get("messages") or [])] if part != "generate" else \
        [str(m) for m in (out.get("errors") or [])]


def failure_cause(info: dict, last: dict) -> str:
    """The top of a failed run's report: what the last round's checks said, not only that the
    loop ran out of rounds."""
    lines = (_messages_of(last, "generate") + _messages_of(last, "debug") + _messages_of(last, "verify")
             + _messages_of(last, "check"))
    items = "".join(f"<li>{esc(m)}</li>" for m in lines) or "<li>(the round left no messages)</li>"
    return (f"<div class='cause'><h2>Why it failed</h2><p>{esc(info.get('error') or '')}</p>"
            f"<p>Round {last['n']} of loop <code>{esc(last['loop'])}</code> ended with:</p><ul>{items}</ul></div>")


def understood_section(steps, shapes: dict[str, str]) -> str:
    """The order as the run understood it, in plain words, before anything moved."""
    gen = find_step(steps, shapes, values.READING)
    ver = find_step(steps, shapes, values.VERIFY)
    explanation = (gen[2].get("explanation") if gen else None) or []
    lines = explanation.splitlines() if isinstance(explanation, str) else list(explanation)
    goal = (ver[2].get("goal") if ver else None) or (gen[2].get("goal") if gen else None)
    if not lines and isinstance(goal, dict):
        lines = _goal_lines(steps, shapes, goal)
    for rule in (gen[2].get("constraints") or []) if gen else []:
        if isinstance(rule, dict):
            lines.append(_rule_words(rule))
    if not lines:
        return ""
    return "<h2>Understood</h2><ul class='understood'>" + "".join(f"<li>{esc(x)}</li>" for x in lines) + "</ul>"


def _goal_lines(steps, shapes: dict[str, str], goal: dict) -> list[str]:
    """The goal in its task domain's words (``fridge holds pumpkin``, ``shelf4 product3: exactly
    12``), never a Python list; a domain no longer installed: the goal spelt out generically."""
    world = (find_step(steps, shapes, values.WORLD) or (None, None, {}))[2].get("world")
    try:
        domain = task_domain(world) if isinstance(world, dict) else domain_named(None)
    except UserError:
        return plain_words(goal)
    return list(domain.goal_words(goal))


def _rule_words(rule: dict) -> str:
    who = ", ".join(rule.get("only") or rule.get("never") or [])
    scope = " ".join(f"{k} {v}" for k, v in rule.items() if k not in ("only", "never", "words") and v)
    verb = "only" if "only" in rule else "never"
    text = f"rule: {verb} {who} in moves" + (f" of {scope}" if scope else "")
    return text + (f" (from '{rule['words']}')" if rule.get("words") else "")


def loop_section(rounds: list[dict]) -> str:
    """One card per round: the prompt as sent, the raw answer, the checks' messages, the cost."""
    cards = []
    for r in rounds:
        gen, ver = r.get("generate") or {}, r.get("verify") or {}
        usage = gen.get("usage") or {}
        ok = bool(ver.get("ok")) or bool(ver.get("refusal"))
        if r.get("check"):  # the second opinion decides whether a goal or a refusal stands
            ok = bool(ver.get("ok")) and bool(r["check"].get("ok")) or bool(r["check"].get("refusal"))
        head = (f"<h3>{esc(r['loop'])} round {r['n']} "
                f"<span class='{'ok' if ok else 'bad'}'>{'passed' if ok else 'rejected'}</span></h3>")
        facts = table(["tokens in", "tokens out", "latency (s)", "cost (USD)", "cached"],
                       [[usage.get("prompt_tokens"), usage.get("completion_tokens"), usage.get("latency_s"),
                         usage.get("cost_usd"), usage.get("cached")]]) if usage.get("calls") or gen.get("response") else ""
        msgs = "".join(f"<details><summary>{esc(m.get('role', '?'))} message ({len(str(m.get('content', '')))} chars)"
                       f"</summary><pre>{esc(m.get('content', ''))}</pre></details>"
                       for m in gen.get("messages") or [] if isinstance(m, dict))
        answer = gen.get("response")
        answer_html = (f"<h4>Answer</h4><pre class='answer'>{esc(answer)}</pre>" if answer else
                       "<p>(offline: no model answer; the parser wrote the problem)</p>" if gen else "")
        checks = []
        for label, part in (("generator", "generate"), ("debugger", "debug"), ("verifier", "verify"),
                            ("second opinion", "check")):
            m = _messages_of(r, part)
            if m:
                checks.append(f"<h4>{label}</h4><ul>" + "".join(f"<li>{esc(x)}</li>" for x in m) + "</ul>")
        if ver.get("refusal"):
            checks.append(f"<h4>verifier: refusal</h4><p>{esc(ver['refusal'])}</p>")
        cards.append(f"<div class='round'>{head}{facts}"
                     + (f"<h4>Prompt</h4>{msgs}" if msgs else "") + answer_html + "".join(checks) + "</div>")
    return "<h2 id='loop'>Refinement loop</h2>" + "".join(cards)
