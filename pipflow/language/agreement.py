"""A second opinion on a model's reading of a command: does its goal say what the command says?

The debugger and the verifier check that a model's problem is well formed and possible in the
world; neither can see that it answers another command. A small model that writes product2 where
the command asked for product1 passes every check and robots move the wrong goods (issue 17,
wh-05). The checked loop (workflow ``pip-llm-checked``; the paper's loop, ``pip-llm``, has no such
check) compares the model's goal and robot rules with a reading of the command that does not come
from the model. Each task domain says how (:meth:`pipflow.taskdomain.TaskDomain.second_opinion`);
this module holds what every domain's check shares:

* **The offline reading** (the domain's parser and resolver) when the parser understands the
  command. It never guesses, so a goal that differs from it is wrong: a *firm* disagreement,
  never accepted. The feedback for the next round names *what* disagrees (which count, which
  object, which rule) and quotes the command's words it comes from, never the reading's value
  and never a ready-made entry to paste (:class:`Finding`): a model that copied the parser's
  answer would make an LLM experiment measure copying, and the rounds ablation measure nothing
  (issue 20).
* **The command's words** (its names and numbers) when the parser does not read the command.
  Words are not a reading: "whatever shelf4 has of product1, shelf3 should end up with 7 fewer"
  names shelf4 and says 7, and the right goal (8 on shelf3) changes neither. So what the words
  raise are *doubts*, never feedback: a goal is never accepted because it restates a name or a
  number of the command, nor rejected because it does not. An accepted goal carries its doubts
  as warnings (output ``disagreement``); with ``strict`` (the offline-first reader, for people who
  run robots) a goal with doubts is not executed at all.

The same comparison decides whether a verifier's refusal is final. A refusal is final only when
the *command* makes the goal impossible: the offline reading itself is a refusal, or the model's
impossible goal agrees with the reading. An impossible goal the model invented is feedback. When
the parser does not read the command, nothing can tell the two apart: the refusal is feedback
until the last round, and final there.
"""
from __future__ import annotations

import hashlib
import json
from dataclasses import dataclass, field
from typing import Any, Callable

from pipflow.errors import InputError, Refusal, TranslationError
from pipflow.taskdomains import task_domain

OFFLINE = "offline reading"
WORDS = "command's words"
NONE = "none"


@dataclass(frozen=True)
class Finding:
    """One way a model's reading differs from the offline reading. ``said``: for the run record
    and the log (it may name the reading's value); ``message``: for the model's next prompt (what
    disagrees and the command's words, never the reading's value: :func:`words_note`)."""

    said: str
    message: str


@dataclass
class Opinion:
    """``disagreement``: what the model's reading gets wrong (firm) or the doubts the command's
    words raise about it (loose), in words for the record. ``messages``: feedback for the next
    round (firm disagreements only). ``refusal``: the final refusal (the command makes the goal
    impossible), else None. ``firm``: the disagreement is with a full reading of the command
    (never accepted), not doubts from its words."""

    basis: str
    disagreement: list[str] = field(default_factory=list)
    messages: list[str] = field(default_factory=list)
    refusal: str | None = None
    firm: bool = False
    reading: Any = None  # the offline reading (goal and rules) when the parser understood; record only


def words_note(words: str) -> str:
    """The command's words a message is about, quoted: "(the command's words: '...')"."""
    text = " ".join(str(words).split())
    return f"(the command's words: '{text}')" if text else ""


_READINGS: dict[str, tuple[str, Any]] = {}


def remembered_reading(command: str, world: dict, read: Callable[[str, dict], Any],
                       label: str = "offline") -> tuple[str, Any]:
    """``("read", read(command, world))``, ``("refused", reason)`` or ``("unread", why)``,
    remembered per (label, command, world) in this process: the loop asks once per round."""
    key = hashlib.sha256(json.dumps([label, command, world], sort_keys=True, default=str).encode()).hexdigest()
    if key not in _READINGS:
        try:
            _READINGS[key] = ("read", read(command, world))
        except Refusal as exc:
            _READINGS[key] = ("refused", str(exc))
        except (TranslationError, InputError) as exc:
            _READINGS[key] = ("unread", str(exc))
    return _READINGS[key]


def _offline_goal(command: str, world: dict) -> dict:
    got = task_domain(world).read_command(command, world)  # the reading alone: no problem to write
    return {"goal": got.goal, "constraints": list(got.constraints), "explanation": got.explanation or []}


def offline_reading(command: str, world: dict) -> tuple[str, Any]:
    """The offline parser's reading of ``command`` through the world's task domain
    (:meth:`pipflow.taskdomain.TaskDomain.read_command`): ``("read", {"goal", "constraints",
    "explanation"})``, ``("refused", reason)`` or ``("unread", why)``."""
    return remembered_reading(command, world, _offline_goal)


def judge(reading: tuple[str, Any], compare: Callable[[Any], list[Finding]], doubts: Callable[[], list[str]],
          verifier_refusal: str | None, last: bool = False) -> Opinion:
    """The opinion on one round's reading, given the domain's offline ``reading`` (as from
    :func:`remembered_reading`), its comparison of the model's reading with it (``compare``) and
    the doubts the command's words raise about the model's reading (``doubts``, used only when
    the parser did not read the command). See the module docstring."""
    state, data = reading
    if state == "refused":  # the command itself is impossible, whatever the model wrote
        return Opinion(OFFLINE, refusal=f"the command cannot be done in this world: {data}", firm=True)
    if state == "read":
        found = compare(data)
        said, messages = [f.said for f in found], [f.message for f in found]
        if verifier_refusal and found:  # an impossible goal the model invented: feedback, not the end
            messages = ["the goal that cannot be done is your answer's, not the command's: the command asks "
                        "for something else (below)"] + messages
            return Opinion(OFFLINE, said, messages, None, True, data)
        return Opinion(OFFLINE, said, messages, verifier_refusal, bool(found), data)
    raised = doubts()
    if verifier_refusal and not last:  # the model's goal, or the command? the next round may tell
        return Opinion(WORDS, raised, [], None, False)
    return Opinion(WORDS, raised, [], verifier_refusal, False)


def refusal_opinion(command: str, world: dict, verifier_refusal: str | None, last: bool = False) -> Opinion:
    """For a domain whose goals are not compared: only whether a verifier's refusal is final.
    The offline reading refuses the command: final, with its reason. It reads the command (so
    the command can be done): the refusal is of a goal the model invented, and it is feedback.
    It does not read it: feedback until the last round, final there."""
    state, reading = offline_reading(command, world)
    if state == "refused":
        return Opinion(OFFLINE, refusal=f"the command cannot be done in this world: {reading}", firm=True)
    if state == "read" and verifier_refusal:
        why = verifier_refusal.split(": ", 1)[-1] if ": " in verifier_refusal else verifier_refusal
        return Opinion(OFFLINE, messages=[f"your goal cannot be done ({why}); the goal that cannot be done is "
                                          "your answer's, not the command's: the command can be done, write "
                                          "the goal it states"])
    if state != "read" and verifier_refusal and not last:
        return Opinion(NONE)
    return Opinion(NONE if state != "read" else OFFLINE, refusal=verifier_refusal)
