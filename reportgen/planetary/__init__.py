"""Planetary reducer synthesis (issue #7): schemes and Willis' ratio, the conditions (coaxiality,
undercut, adjacency, exact assembly), the tooth-number search, the drive motor → open pair →
planetary → crank, and Kutzbach's velocity triangle as pure geometry. No plotting, no templates.
"""
from .conditions import UndercutLimits
from .schemes import SCHEMES, Scheme, get_scheme, reducer_ratio, willis_u1h
from .search import Candidate, PlanetaryDesign, evaluate, nearest, search, synthesize

__all__ = ["SCHEMES", "Scheme", "get_scheme", "reducer_ratio", "willis_u1h", "UndercutLimits",
           "Candidate", "PlanetaryDesign", "evaluate", "nearest", "search", "synthesize"]
