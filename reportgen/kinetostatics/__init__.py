"""Kinetostatics (section 2 of the note, sheet 2): loads, reactions group by group, the balancing
moment, Zhukovsky's lever, and the graphical replicas. See docs/kinetostatics.md."""
from .analysis import (BalancingCycle, Kinetostatics, balancing_cycle, balancing_moment_cycle, force_angle,
                       kinetostatics_at)
from .graphical import GraphicalReplica, round_scale
from .reactions import PairReaction, Reactions, pair_name, solve_reactions
from .zhukovsky import Lever, virtual_power_moment, zhukovsky_lever

__all__ = ["BalancingCycle", "Kinetostatics", "balancing_cycle", "balancing_moment_cycle", "force_angle",
           "kinetostatics_at", "GraphicalReplica", "round_scale", "PairReaction", "Reactions", "pair_name",
           "solve_reactions", "Lever", "virtual_power_moment", "zhukovsky_lever"]
