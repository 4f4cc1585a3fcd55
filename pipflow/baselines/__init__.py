"""The baselines of the PIP-LLM paper's tables (Sec. V, Tables I-III): CoT, SMART-LLM and LaMMA-P,
each as its own paper does it, run through the same world, schedule, simulation and scoring as
PIP-LLM.

Each baseline has the model write a plan in which the *model* names the robots (CoT: numbered
steps; SMART-LLM: Python-like code with threads; LaMMA-P: an allocation summary and per-robot
PDDL problems that a planner solves). Nothing a model writes is executed: every answer goes
through a reader that treats it as data and refuses anything outside its format with line and
column. What a reader accepts becomes a :class:`~pipflow.baselines.robotplan.RobotStep` list (the
robot plan), and :func:`~pipflow.baselines.robotplan.schedule_input` turns that into the
dependency graph and allocation the ``schedule`` step times, so ``simulate`` and ``score`` judge
a baseline exactly like PIP-LLM.

Modules: ``located`` (located reader issues), ``skills`` (a PDDL domain's actions as the skills
a model may call), ``robotplan`` (the robot plan and its conversion), one reader per format:
``cot``, ``smartllm``, ``lammap`` (LaMMA-P's summary, its robot-level actions, the merge in time) and
``subplans`` (LaMMA-P's per-robot problems: asked, validated once, solved).
Generic code: a domain's words live in its prompts and robot-level PDDL domains (``prompts/``,
``domains/``), never here.
"""
