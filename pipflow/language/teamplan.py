"""The paper's "w/o D" ablation: a team plan a model writes with actions it designed itself,
read as data and mapped onto the robots' executable team actions where they match.

The paper (Sec. V, Table III): "we exclude the PDDL domain D and allow the LLMs to design
team-level actions autonomously, performing planning without generating explicit PDDL
problems". The model is shown the command and the world, not the domain; it answers with the
actions it designed and a plan that uses them (JSON, :func:`read_team_plan`). The robots can only
execute the task domain's team actions, so each plan step is mapped onto one of them, by rules
that use the domain's action *schemas* (never the model's intent as we guess it):

1. every argument is a thing of the world (a name, case aside) or a whole number; a number
   stands for the object of a type whose objects are no things of the world and each carry a
   distinct number in a one-argument numeric fluent that no action changes (the warehouse's
   ``(amount magnitude3) = 3``);
2. an action *takes* the arguments when it has exactly that many parameters and they bind to
   them by type (subtypes allowed), keeping the step's order among arguments of one type (the
   first of two places is the first place parameter: "from" before "to"), in exactly one way;
   it *fits* when, besides, its static preconditions (facts no action changes, such as "is a
   garbage can", and inequalities such as "from is not to") hold for them in the world;
3. when one action of the domain takes arguments of these kinds at all, a step that fits it is
   that action, whatever its name (the warehouse's one four-argument action); when several take
   them, the step's action name must say which: the one that fits whose name's words all appear
   in it (``switch_off_lamp`` is ``switch-off``), else the one that shares a word with it
   (``turn_off`` is ``switch-off``, not ``switch-on``). Static facts never choose between
   actions on their own: ``put(watermelon, fridge)`` fits only ``slice`` of the home's
   two-argument actions, and is still not executed, because nothing says the model meant that.
   Otherwise the step is not executable, and says why.

A plan with a step that is not executable is not executed at all (robots do not start a plan
that has a step nobody can carry out); every such step is reported, located by its number.
Nothing of the answer is run: it is JSON, and every name in it is looked up in the world.
"""
from __future__ import annotations

import itertools
import re
from dataclasses import dataclass, field
from typing import Any

from pipflow.language.jsonanswer import json_object
from pipflow.language.parsing import ParseIssue, validate_constraints
from pipflow.pddl.common import parse
from pipflow.pddl.names import pddl_name, world_spelling
from pipflow.suggest import did_you_mean

#: the most arguments a step may have (bindings are enumerated: 6! = 720 at most)
MAX_ARGS = 6
#: the most steps a plan may have (a model that loops is stopped with a clear error)
MAX_STEPS = 500


@dataclass
class TeamPlan:
    """What :func:`read_team_plan` learned from one answer."""

    plan: list[dict] = field(default_factory=list)       # executable: [{"action", "args"}] (the domain's)
    designed: list[dict] = field(default_factory=list)   # the model's own actions, as declared
    steps: list[dict] = field(default_factory=list)      # each model step and what it mapped to, or why not
    problems: list[str] = field(default_factory=list)    # why the plan cannot be executed (empty: it can)
    constraints: list[dict] = field(default_factory=list)  # the robot-use rules the answer states
    refusal: str | None = None                           # the model said the command cannot be done


def words(name: str) -> list[str]:
    """The lower-case words of a name: ``switchOffLamp``, ``switch_off-lamp`` -> switch, off, lamp."""
    spaced = re.sub(r"([a-z0-9])([A-Z])", r"\1 \2", str(name))
    return [w for w in re.split(r"[^A-Za-z0-9]+", spaced.lower()) if w]


def read_team_plan(text: str, domain_text: str, problem_text: str, world: dict | None = None,
                   rule_fields: tuple[str, ...] = ()) -> TeamPlan:
    """The model's answer read and mapped (module docstring). ``problem_text`` is a problem of
    the world (its objects and initial state; its goal is not read); ``rule_fields``: what a
    robot-use rule may narrow by (the task domain's). Raises :class:`ParseIssue` when the answer
    is not the JSON asked for (no plan can be read from it at all), or a rule it states is wrong
    (dropping a rule silently would let a forbidden robot work)."""
    data = json_object(text)
    reason = data.get("refuse", data.get("refusal"))
    if isinstance(reason, str) and reason.strip():
        return TeamPlan(refusal=reason.strip())
    rules = data.get("constraints") or []
    if not isinstance(rules, list):
        raise ParseIssue('"constraints" must be a list of rules {"only" or "never": [ROBOT, ...], ...}')
    constraints = validate_constraints(rules, world, tuple(rule_fields))
    designed = _designed(data)
    steps = data.get("plan")
    if not isinstance(steps, list):
        raise ParseIssue('the answer must hold "plan": a list of steps {"action": NAME, "args": [...]} '
                         '(or "refuse": "why" when the command cannot be done)')
    if len(steps) > MAX_STEPS:
        raise ParseIssue(f'"plan" has {len(steps)} steps; more than {MAX_STEPS} is no plan for one command')
    catalog = Catalog(domain_text, problem_text, world)
    out = TeamPlan(designed=designed, constraints=constraints)
    declared = {d["name"].lower(): d for d in designed}
    for k, step in enumerate(steps, 1):
        shown, name, args, problem = _step(step)
        design = declared.get(name.lower())
        if problem is None and declared and design is None:
            problem = (f"`{name}` is not one of the actions the answer designed "
                       f"({', '.join(d['name'] for d in designed)})")
        elif problem is None and design and design["parameters"] is not None and len(design["parameters"]) != len(args):
            problem = (f"`{name}` was designed with {len(design['parameters'])} parameter(s), the step gives "
                       f"{len(args)} argument(s)")
        mapped = None
        if problem is None:
            mapped, problem = catalog.map_step(name, args)
        record = {"step": k, "written": shown, **({"action": mapped["action"], "args": mapped["args"]}
                                                  if mapped else {"problem": problem})}
        out.steps.append(record)
        if mapped:
            out.plan.append(mapped)
        else:
            out.problems.append(f"plan step {k} ({shown}): {problem}")
    return out


def _designed(data: dict) -> list[dict]:
    """The actions the model declared (``actions``: name, parameters, description), checked for
    shape; an answer may leave the list out (its steps then name actions freely)."""
    raw = data.get("actions", [])
    if not isinstance(raw, list):
        raise ParseIssue('"actions" must be a list of {"name": ..., "parameters": [...], "description": ...}')
    out = []
    for k, a in enumerate(raw, 1):
        if not isinstance(a, dict) or not isinstance(a.get("name"), str) or not a["name"].strip():
            raise ParseIssue(f'"actions" entry {k} must be an object with a "name" (text)')
        params = a.get("parameters")
        if params is not None and not isinstance(params, list):
            raise ParseIssue(f'"actions" entry {k} ({a["name"]}): "parameters" must be a list')
        out.append({"name": a["name"].strip(), "parameters": [str(p) for p in params] if params is not None else None,
                    "description": str(a.get("description") or "")})
    return out


def _step(step: Any) -> tuple[str, str, list, str | None]:
    """(how the step reads, its action name, its arguments, a problem with its shape or None)."""
    if not isinstance(step, dict) or not isinstance(step.get("action"), str) or not step["action"].strip():
        return (repr(step)[:60], "", [], 'a step must be {"action": NAME, "args": [...]}')
    name = step["action"].strip()
    args = step.get("args", [])
    if not isinstance(args, list):
        return (f"`{name}`", name, [], '"args" must be a list of names and numbers')
    shown = f"`{name}({', '.join(str(a) for a in args)})`"
    bad = [a for a in args if isinstance(a, bool) or not isinstance(a, (str, int, float))]
    if bad:
        return (shown, name, args, f"arguments must be names or numbers, not {bad[0]!r}")
    if len(args) > MAX_ARGS:
        return (shown, name, args, f"{len(args)} arguments; no team action takes more than {MAX_ARGS}")
    return (shown, name, args, None)


class Catalog:
    """The domain's team actions over one world: objects and their types, the numbers some types
    stand for, the static facts. Built once per answer (UP parses the world's problem)."""

    def __init__(self, domain_text: str, problem_text: str, world: dict | None):
        self.problem = parse(domain_text, problem_text)
        self.spelling = world_spelling(world)
        self.objects = {o.name.lower(): o for o in self.problem.all_objects}
        changed = {e.fluent.fluent().name for a in self.problem.actions for e in a.effects}
        self.static = {f.name for f in self.problem.fluents if f.name not in changed}
        self.numbers: dict[str, dict[int, Any]] = {}  # type name -> {number: object}
        for f in self.problem.fluents:
            if f.arity != 1 or f.name not in self.static or not (f.type.is_int_type() or f.type.is_real_type()):
                continue
            kind = f.signature[0].type
            members = [o for o in self.problem.all_objects if _is_a(o.type, kind)]
            if world and any(o.name in self.spelling for o in members):
                continue  # things of the world (shelves with capacities) are named, never numbered
            values = {}
            for o in members:
                try:
                    v = self.problem.initial_value(f(o))
                except Exception:  # no initial value: this fluent gives the type no numbers
                    values = {}
                    break
                number = v.constant_value() if v is not None and v.is_constant() else None
                if number is None or float(number) != int(number) or int(number) in values:
                    values = {}
                    break
                values[int(number)] = o
            if values and len(values) == len(members):
                self.numbers.setdefault(kind.name, values)

    # -- one step -------------------------------------------------------------------------------
    def map_step(self, name: str, args: list) -> tuple[dict | None, str | None]:
        """(``{"action", "args"}`` in the world's spelling, None) or (None, why not)."""
        values, problem = self._values(args)
        if problem:
            return None, problem
        typed = [a.name for a in self.problem.actions if self._bindings(a, values, statics=False)]
        fits: dict[str, list] = {}
        unclear: list[str] = []
        for action in self.problem.actions:
            bindings = self._bindings(action, values)
            if len(bindings) == 1:
                fits[action.name] = bindings[0]
            elif len(bindings) > 1:
                unclear.append(action.name)
        if not fits:
            if unclear:
                return None, (f"its arguments fit {', '.join(unclear)} in more than one order; no order "
                              "can be chosen for it")
            if typed:
                verb = "takes" if len(typed) == 1 else "take"
                return None, (f"no team action of the robots takes these arguments ({', '.join(sorted(typed))} {verb} "
                              "things of these kinds, but what never changes in this world rules these out)")
            return None, self._why_none(values)
        if len(typed) == 1:  # one action takes arguments of these kinds at all: the step is that action
            chosen = list(fits)
        else:  # several could: the step's name decides (all of an action's words in it, else one of them)
            said = set(words(name))
            named = [a for a in typed if set(words(a)) <= said] or [a for a in typed if set(words(a)) & said]
            chosen = [a for a in named if a in fits]
            kinds = f"the robots' actions {', '.join(sorted(typed))} take arguments of these kinds"
            if not named:
                return None, f"{kinds}, and its name `{name}` names none of them"
            if not chosen:
                return None, (f"its name says {' or '.join(named)}, and what never changes in this world rules "
                              "these arguments out for it")
            if len(chosen) > 1:
                return None, f"{kinds}, and its name `{name}` does not say which"
        action = chosen[0]
        return {"action": action, "args": [self.spelling.get(o.name, o.name) for o in fits[action]]}, None

    def _values(self, args: list) -> tuple[list, str | None]:
        """Each argument as ("object", UP object) or ("number", n); or a problem naming the first
        argument that is neither a world name nor a whole number."""
        out = []
        for a in args:
            if isinstance(a, (int, float)) or (isinstance(a, str) and re.fullmatch(r"\s*-?\d+(\.0+)?\s*", a)):
                n = float(a)
                if n != int(n):
                    return [], f"{a} is not a whole number"
                out.append(("number", int(n)))
                continue
            key = pddl_name(str(a).strip())
            if key not in self.objects:
                names = sorted(self.spelling.get(n, n) for n in self.objects)
                return [], f"`{a}` is no thing of this world{did_you_mean(str(a), names)}"
            out.append(("object", self.objects[key]))
        return out, None

    def _fits(self, value: tuple, param_type: Any) -> Any | None:
        """The object ``value`` stands for as a parameter of ``param_type``, or None."""
        kind, v = value
        if kind == "object":
            return v if _is_a(v.type, param_type) else None
        return self.numbers.get(param_type.name, {}).get(v)

    def _bindings(self, action: Any, values: list, statics: bool = True) -> list[list]:
        """Every way the values bind to the action's parameters (module docstring, rule 2);
        ``statics`` False: by types and order only."""
        params = action.parameters
        if len(params) != len(values):
            return []
        found = []
        for order in itertools.permutations(range(len(values))):
            # order[i]: the value bound to parameter i
            objs = [self._fits(values[order[i]], params[i].type) for i in range(len(params))]
            if any(o is None for o in objs):
                continue
            if not self._keeps_order(values, order):
                continue
            binding = dict(zip((p.name for p in params), objs))
            if statics and not self._static_holds(action, binding):
                continue
            if objs not in found:
                found.append(objs)
        return found

    @staticmethod
    def _keeps_order(values: list, order: tuple) -> bool:
        """Two values of one kind (the same type, or both numbers) keep the step's order."""
        position = {v: i for i, v in enumerate(order)}  # value index -> parameter index

        def kind(v: tuple) -> str:
            return "number" if v[0] == "number" else v[1].type.name

        for a, b in itertools.combinations(range(len(values)), 2):
            if kind(values[a]) == kind(values[b]) and position[a] > position[b]:
                return False
        return True

    def _static_holds(self, action: Any, binding: dict) -> bool:
        """The action's static preconditions (facts no action changes, and (in)equalities of its
        parameters) hold for ``binding`` in the world's initial state."""
        return all(self._holds(c, binding) is not False for c in action.preconditions)

    def _holds(self, node: Any, binding: dict) -> bool | None:
        """True / False for a static condition; None for what only the state at run time decides."""
        if node.is_and():
            parts = [self._holds(a, binding) for a in node.args]
            return False if False in parts else (None if None in parts else True)
        if node.is_not():
            inner = self._holds(node.arg(0), binding)
            return None if inner is None else not inner
        if node.is_equals() and all(a.is_parameter_exp() for a in node.args):
            left, right = (binding.get(a.parameter().name) for a in node.args)
            return None if left is None or right is None else left == right
        if node.is_fluent_exp() and node.fluent().name in self.static and node.fluent().type.is_bool_type():
            objs = []
            for a in node.args:
                if not a.is_parameter_exp() or a.parameter().name not in binding:
                    return None
                objs.append(binding[a.parameter().name])
            try:
                return bool(self.problem.initial_value(node.fluent()(*objs)).bool_constant_value())
            except Exception:  # no value in the initial state and no default: not decidable here
                return None
        return None

    def _why_none(self, values: list) -> str:
        """Why no action fits: a number no type stands for, or no action of that shape."""
        for kind, v in values:
            if kind == "number" and not any(v in m for m in self.numbers.values()):
                known = sorted({n for m in self.numbers.values() for n in m})
                return (f"no team action of the robots takes the number {v}"
                        + (f" (they take {known[0]} to {known[-1]})" if known else " (none takes a number)"))
        return "no team action of the robots takes these arguments"


def _is_a(t: Any, ancestor: Any) -> bool:
    """``t`` is ``ancestor`` or one of its subtypes (UP user types)."""
    while t is not None:
        if t == ancestor:
            return True
        t = getattr(t, "father", None)
    return False
