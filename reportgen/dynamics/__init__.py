"""Dynamics of the machine: reduced moment and inertia, work and kinetic energy, the Wittenbauer
diagram (exact, Мерцалов, graphical replica), the flywheel, and the steady motion with it."""
from .cycle import Cycle, FunctionCycle, ProjectCycle, Reduced
from .energy import EnergyProfile
from .errors import DynamicsInputError
from .flywheel import FlywheelSize, flywheel_size
from .graphical import GraphicalReplica, GraphLayout, graphical_replica
from .motion import SteadyMotion, integrate_ivp, steady_motion
from .result import DynamicsResult, MethodComparison, dynamics_block
from .solve import dynamics_of, solve_cycle, solve_dynamics
from .wittenbauer import Merzalov, WittenbauerExact, merzalov, wittenbauer_exact

__all__ = ["Cycle", "FunctionCycle", "ProjectCycle", "Reduced", "EnergyProfile", "DynamicsInputError",
           "FlywheelSize", "flywheel_size", "GraphicalReplica", "GraphLayout", "graphical_replica",
           "SteadyMotion", "integrate_ivp", "steady_motion", "DynamicsResult", "MethodComparison",
           "dynamics_block", "dynamics_of", "solve_cycle", "solve_dynamics", "Merzalov", "WittenbauerExact", "merzalov",
           "wittenbauer_exact"]
