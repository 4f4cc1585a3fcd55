"""The warehouse as a pipflow task domain: the one object the generic code talks to (registered
as ``warehouse`` in the entry-point group ``pipflow.task_domains``).

The core of :class:`pipflow.taskdomain.TaskDomain` and five capabilities (grounded decoding, the
checked loop's second opinion, pipflow's transport planner, goals compared by meaning, execution
under faults), each a thin face of a module that does the work: the world loader
(:mod:`pipflow.warehouse.world`), the command reader (:mod:`pipflow.warehouse.language.translator`,
the parser and resolver of the warehouse's order language), the stock-problem writer and checks
(:mod:`pipflow.warehouse.problem`, the debugger's and verifier's stock checks), the pybullet
simulation (:mod:`pipflow.warehouse.simulation`), the checks of a run
(:mod:`pipflow.warehouse.scoring`) and the side of faults (:mod:`pipflow.warehouse.faults`).
Scoring, the bench row and the understanding verdict are the protocol's own, the same as every
domain's.

Imports of the parser (lark), UP and pybullet are deferred into the methods on purpose: the
registry imports this module for every warehouse run, and a run pays only for what it uses.
"""
from __future__ import annotations

from pathlib import Path
from typing import Any, Callable, Mapping

from pipflow.execution.capability import ModuleExecution
from pipflow.goalcounts import describe, is_bound
from pipflow.pddl.common import share
from pipflow.resources import data_file
from pipflow.taskdomain import (ComparesGoals, Condition, Facts, GroundedDecoding, Reading, Reference, Save,
                                SecondOpinion, TaskDomain, TransportPlanning, pddl_domain_name)
from pipflow.warehouse import agreement, scoring
from pipflow.warehouse import faults as fault_model
from pipflow.warehouse import problem as writer
from pipflow.warehouse import world as worlds
from pipflow.warehouse.language import grounding
from pipflow.warehouse.meaning import goal_difference
from pipflow.warehouse.problem import goal_in_world_names, goal_problems, stock_goals, world_mismatches
from pipflow.warehouse.simulation import simulate
from pipflow.warehouse.starts import vary_starts


def _stock_goal(parsed: Any, world: dict | None) -> dict:
    """A problem's ``(stock s p)`` goals as ``{shelf: {product: value}}`` in the world's spelling."""
    return goal_in_world_names(stock_goals(parsed)[0], world)


class WarehouseDomain(TaskDomain, GroundedDecoding, SecondOpinion, TransportPlanning, ComparesGoals,
                      ModuleExecution):
    """Pallets of products moved between shelves by robots that carry a few units each."""

    name = "warehouse"
    workflow = "warehouse"
    workflows = {"pip-llm": "pip-llm", "pip-llm-checked": "pip-llm-checked",
                 # the paper's ablations (Table III) and the w/o B (docs/paper.md, "Ablations")
                 **{name: name for name in ("pip-llm-no-domain", "pip-llm-no-debugger", "pip-llm-no-bv",
                                            "pip-llm-no-as", "pip-llm-n1", "pip-llm-n2", "pip-llm-n3",
                                            "pip-llm-n4")},
                 # the paper's baselines (Sec. V): pipflow/baselines/, docs/paper.md "Baselines"
                 "cot": "cot", "smart-llm": "smart-llm", "lamma-p": "lamma-p"}
    default_prompt = "warehouse_problem"
    rule_fields = ("product", "from", "to")
    name_sections = ("shelves", "products", "robots")
    simulate_options = ("picture", "animation")
    goal_example = "(= (stock shelf2 product1) 3)"
    fault_model = fault_model  # its side of execution under faults (ModuleExecution)

    # -- files ---------------------------------------------------------------------------------
    def pddl_domain(self) -> Path:
        return data_file("domains/warehouse.pddl")

    def action_metadata(self) -> Path:
        return data_file("domains/warehouse.actions.yaml")

    # -- worlds --------------------------------------------------------------------------------
    def load_world(self, path: str | Path, *, seed: int | None = None, **options: Any) -> dict:
        return vary_starts(worlds.load_world(path), seed)

    def describe(self, world: dict) -> str:
        return (f"{len(world['shelves'])} shelves, {len(world['products'])} products, "
                f"{len(world['robots'])} robots")

    def places(self, world: dict) -> Mapping[str, Mapping[str, Any]]:
        """The shelves: a footprint and an access point each."""
        return world.get("shelves") or {}

    def rule_names(self, world: dict) -> Mapping[str, tuple[Any, str]]:
        shelves = world.get("shelves", {})
        return {"product": (world.get("products", {}), "product"), "from": (shelves, "shelf"),
                "to": (shelves, "shelf")}

    # -- language ------------------------------------------------------------------------------
    def read_offline(self, command: str, world: dict, domain_text: str = "", save: Save | None = None) -> dict:
        """The protocol's offline round, and our own problem built for the debugger, planner and
        verifier to read without parsing its text (:func:`_share_built`)."""
        out = super().read_offline(command, world, domain_text, save)
        if domain_text:
            _share_built(out["problem"], world, out.get("concrete", out["goal"]), domain_text)
        return out

    def read_command(self, command: str, world: dict) -> Reading:
        # deferred: builds the lark parser (~300 ms; only offline reading needs it)
        from pipflow.warehouse.language.translator import understand

        result = understand(command, world)
        return Reading(result["goal"], list(result["constraints"]), order=result["order"],
                       explanation=list(result["explanation"]))

    def write_problem(self, world: dict, goal: Any, domain_name: str, name: str = "task") -> str:
        return writer.write_problem(world, goal, name=name, domain=domain_name)  # looked up per call: replaceable

    def example_problem(self, world: dict, domain_text: str = "") -> str | None:
        """The world's current stock as the goal: every name and number in the expected form."""
        stock = {s: dict(items) for s, items in world.get("stock", {}).items() if items}
        return self.write_problem(world, stock, "warehouse")

    def read_goal(self, parsed: Any, world: dict | None) -> tuple[Any, list[str]]:
        return _stock_goal(parsed, world), []

    def read_problem(self, parsed: Any, world: dict, constraints: list[dict]) -> dict:
        """The model's goal read back into an order, for the run summary (the paper's mode sets
        no ``goal``: the verifier reads it)."""
        # deferred: pulls lark and jsonschema (the resolver; only a problem's read-back needs it)
        from pipflow.warehouse.language.llm_orders import explain_goal

        return explain_goal(_stock_goal(parsed, world), constraints, world)

    def world_mismatches(self, parsed: Any, problem_text: str, world: dict) -> list[str]:
        return world_mismatches(parsed, problem_text, world)

    def goal_problems(self, world: dict, goal: Any) -> tuple[list[str], str | None]:
        """Unknown names and malformed counts (feedback), and the reasons no final stock of the
        world meets the goal (a refusal)."""
        messages, refusal = goal_problems(world, goal)
        return messages, ("; ".join(messages) if refusal else None)  # a refusal's messages are its reasons

    # -- capabilities --------------------------------------------------------------------------
    def grounding_gbnf(self, world: dict) -> str:
        return grounding.gbnf(world)

    def grounding_schema(self, world: dict) -> dict:
        return grounding.response_format(world)

    def read_grounded(self, text: str, world: dict) -> dict:
        """A grounded answer (an order in JSON) checked and resolved, its problem written."""
        # deferred: pulls lark and jsonschema (the resolver; only LLM-written orders need it)
        from pipflow.warehouse.language.llm_orders import read_grounded

        got = read_grounded(text, world)
        return {"problem": self.write_problem(world, got["goal"], "warehouse"), "goal": got["goal"],
                "constraints": got["constraints"], "order": got["order"], "explanation": got["explanation"],
                "errors": []}

    def answer_size(self, world: dict, reading: Any) -> tuple[int, int]:
        return grounding.answer_size(world, reading)

    def planner_params(self, world: dict, constraints: list[dict]) -> dict:
        """Each robot's ``carry`` skill (units per move) and the only/never rules."""
        robots = {name: r.get("skills", {}).get("carry", 0) for name, r in world.get("robots", {}).items()}
        return {"robots": robots, "rules": constraints or []}

    def feedback_facts(self, messages: list[str], world: dict) -> Facts:
        return worlds.feedback_facts(messages, world)

    def second_opinion(self, command: str, world: dict, goal: Any, constraints: list[dict],
                       refusal: str | None, last: bool = False) -> Any:
        return agreement.second_opinion(command, world, goal, constraints, refusal, last)

    def goal_difference(self, world: dict | None, gold: Any, run: Any) -> str | None:
        """Goals compared by the final stocks they accept (:mod:`pipflow.warehouse.understanding`)."""
        return goal_difference(world, gold, run)

    # -- simulation and scoring ----------------------------------------------------------------
    def simulate(self, world: dict, schedule: dict, graph: dict | None, goal: Any, *,
                 snapshots: bool = False, out_dir: Path | None = None,
                 log: Callable[[str], None] = print, save: Save | None = None, **options: Any) -> dict:
        """The pybullet run in the protocol's shape: the final stock is ``final_state``; the
        trajectories and event log (bulky) go to ``save("trajectories.json")`` when given (the
        report draws from it). Pictures go into ``out_dir`` only when asked: ``snapshots`` (key
        moments and the path map), ``options``: ``picture`` (the path map alone), ``animation``
        (a GIF, needs Pillow)."""
        animation = bool(options.get("animation"))
        drawn = snapshots or animation or bool(options.get("picture"))
        result = simulate(world, schedule, graph, goal, snapshots=snapshots, out_dir=out_dir if drawn else None,
                          log=log, animation=animation)
        result.pop("animation_skipped", None)
        result["final_state"] = result.pop("final_stock")
        if save is not None:
            save("trajectories.json", {"trajectories": result.pop("trajectories"), "events": result.pop("events")})
        return result

    def initial_state(self, world: dict) -> Any:
        return world.get("stock", {})

    def final_state(self, simulation: Mapping[str, Any]) -> Any:
        """``final_state``, or ``final_stock`` in the outputs of ``simulate.pybullet``."""
        return simulation.get("final_state", simulation.get("final_stock"))

    def goal_conditions(self, world: dict, state: Any, goal: Any) -> list[Condition]:
        return scoring.goal_conditions(state, goal)

    def reference(self, world: dict, goal: Any) -> Reference:
        """The fewest moves any plan needs (:func:`pipflow.warehouse.scoring.plan_lower_bound`)."""
        return Reference(scoring.plan_lower_bound(world, goal))

    def rule_violations(self, constraints: list[dict] | None, graph: dict | None,
                        schedule: dict | None, world: dict) -> list[str]:
        return scoring.constraint_violations(scoring.move_fields(graph, schedule), constraints)

    def extra_violations(self, world: dict, simulation: Mapping[str, Any], graph: dict | None,
                         schedule: dict | None) -> list[str]:
        """Units are conserved, no shelf ever held more than its capacity, every coalition had
        the skills its move needs."""
        final = self.final_state(simulation) or {}
        return (scoring.conservation_violations(world, final, int(simulation.get("stray_units", 0)))
                + scoring.capacity_violations(world, simulation.get("peak_load"), final)
                + scoring.skill_violations(scoring.move_fields(graph, schedule), world))

    # -- the bench -----------------------------------------------------------------------------
    def load_tasks(self, path: Path) -> dict:
        return worlds.load_tasks(path)

    # -- execution under faults: warehouse/faults.py through ModuleExecution, and a faster re-plan

    def observed_problem(self, parsed_problem: Any, world: dict, goal: Any, domain_text: str,
                         name: str) -> tuple[Any, str]:
        """The accepted problem with the observed stock (no text parse: fast at any size)."""
        fast = fault_model.updated_problem(parsed_problem, world)
        if fast is None:
            return super().observed_problem(parsed_problem, world, goal, domain_text, name)
        return fast, self.write_problem(world, goal, pddl_domain_name(domain_text, self.name), name=name)

    # -- the report ----------------------------------------------------------------------------
    def goal_words(self, goal: Any) -> list[str]:
        """``shelf4 product3: exactly 12``, ``shelf1 product2: at least 3``: a line per count."""
        if not isinstance(goal, Mapping):
            return super().goal_words(goal)
        return [f"{shelf} {product}: {describe(value) if is_bound(value) else f'exactly {value}'}"
                for shelf, items in goal.items() if isinstance(items, Mapping) for product, value in items.items()]


def _share_built(text: str, world: dict, goal: Any, domain_text: str) -> None:
    """The problem the offline reader wrote, built with UP's API and handed to the parse memo
    (:func:`pipflow.warehouse.problem.problem_object`): the debugger, planner and verifier read it
    without parsing the text. Only when ``text`` is exactly what this module's writer writes for
    the goal (a writer replaced by a plugin or a test may write something else: that text is
    parsed as any other), and only for a domain these names and fluents fit."""
    if _OUR_WRITER(world, goal, name="task", domain="warehouse") != text:
        return
    try:
        built = writer.problem_object(world, goal, domain_text)
    except Exception:  # not this writer's domain (another user's PDDL): the text is parsed
        return
    share(domain_text, text, built)


_OUR_WRITER = writer.write_problem  # captured at import: what the built object stands for
