"""The shared solver plumbing (handbook.design.solvers): which constraints bind, read from IPOPT's multipliers,
on a problem whose binding constraint is known by hand; and the error a spec nothing meets raises."""
import casadi
import numpy as np

from handbook.design.solvers import IPOPT_OPTIONS, Infeasible, Solution


def test_binding_names_the_active_constraint_of_a_known_problem():
    """min x + y subject to x >= 1 (active at the optimum, multiplier 1), y >= 2 (active, multiplier 1) and
    x + y <= 10 (slack): by hand the optimum is (1, 2) and the first two bind, equally."""
    x = casadi.MX.sym("x", 2)
    g = casadi.vertcat(x[0], x[1], x[0] + x[1])
    solver = casadi.nlpsol("s", "ipopt", {"x": x, "f": x[0] + x[1], "g": g}, IPOPT_OPTIONS)
    r = solver(x0=[5, 5], lbg=[1, 2, -np.inf], ubg=[np.inf, np.inf, 10])
    sol = Solution(np.array(r["x"]).ravel(), np.array(r["lam_g"]).ravel(), ["x >= 1", "y >= 2", "x + y <= 10"],
                   bool(solver.stats()["success"]))
    assert sol.success and np.allclose(sol.x, [1, 2], atol=1e-7)
    assert sorted(sol.binding()) == ["x >= 1", "y >= 2"]
    assert sol.binding(threshold=2.0) == []  # both multipliers are 1


def test_binding_orders_by_the_size_of_the_multiplier():
    sol = Solution(np.zeros(2), np.array([1e-9, -3.0, 0.5]), ["a", "b", "c"], True)
    assert sol.binding() == ["b", "c"]


def test_infeasible_carries_its_table_and_what_can_be_met():
    exc = Infeasible("current_limiter", "no R7 meets the window", {"min_margin_max": 0.01})
    assert str(exc) == "no R7 meets the window" and exc.table == "current_limiter"
    assert exc.achievable == {"min_margin_max": 0.01}
