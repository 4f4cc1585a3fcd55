"""Planners come from the entry-point group ``pipflow.planners``: the warehouse's own
pipflow-transport is registered there (the generic PDDL tools import no domain's planner), any
package may add one the same way, and one that fails to load is the user's error naming it."""
from __future__ import annotations

from importlib.metadata import EntryPoint, entry_points

import pytest

from pipflow.errors import InputError, UserError
from pipflow.pddl import common
from pipflow.pddl.solver import check_engine, planner_names


def test_the_warehouse_planner_is_registered_by_entry_point_and_offered_by_name():
    registered = {ep.name: ep.value for ep in entry_points(group=common.PLANNERS)}
    assert registered.get("pipflow-transport") == "pipflow.warehouse.planner:TransportPlanner"
    assert "pipflow-transport" in planner_names()
    check_engine("pipflow-transport")  # does not raise


def test_a_plugin_planner_is_added_and_a_broken_one_is_named(monkeypatch):
    from unified_planning.environment import Environment

    common.environment()  # UP set up as pipflow sets it up
    env = Environment()  # a private one: the probe planner is not offered to the other tests
    plugin = EntryPoint(name="probe-planner", value="pipflow.warehouse.planner:TransportPlanner",
                        group=common.PLANNERS)
    monkeypatch.setattr(common, "entry_points", lambda group: [plugin])
    common.add_planners(env)
    assert "probe-planner" in env.factory.engines
    broken = EntryPoint(name="broken-planner", value="no_such_module:Engine", group=common.PLANNERS)
    monkeypatch.setattr(common, "entry_points", lambda group: [broken])
    with pytest.raises(UserError, match=r"planner 'broken-planner' \(no_such_module:Engine\).*failed to load"):
        common.add_planners(env)


def test_an_install_with_no_registered_planner_says_to_reinstall(monkeypatch):
    from pipflow.pddl import solver

    monkeypatch.setattr(solver, "entry_points", lambda group: [])
    with pytest.raises(InputError, match="reinstall pipflow"):
        check_engine("no-such-planner")
