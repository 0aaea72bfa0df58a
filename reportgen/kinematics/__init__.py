"""Exact kinematics of planar linkages (positions, velocities, accelerations, extremes)."""
from .solve import KinematicModel, KinematicsResult, LinkMotion, PointMotion, build_model

__all__ = ["KinematicModel", "KinematicsResult", "LinkMotion", "PointMotion", "build_model"]
