"""Plane geometry shared by every layer: the 2-D vector type, read-only arrays, rotation,
perpendicular and cross product (the named tolerances: ``reportgen.tolerances``).

One home for each helper (issue 13 item 3): the solvers, scenes, note and sheets import these
instead of keeping their own copies. Arrays hold vectors in their last axis (shape ``(..., 2)``).
"""
from __future__ import annotations

from collections.abc import Iterable
from typing import Any

import numpy as np

__all__ = ["Vec2", "vec2", "readonly", "frozen", "shared", "rot", "rot_vec2", "perp", "cross", "dot"]

#: A point or vector of the plane as plain floats (m in the task, mm on a drawing).
Vec2 = tuple[float, float]

def vec2(v: Iterable[Any]) -> Vec2:
    """``(x, y)`` as two floats, from any pair (a tuple, a list, a numpy array of shape (2,))."""
    x, y = v
    return (float(x), float(y))


def readonly(a: Any, dtype: Any = float) -> np.ndarray:
    """A copy of ``a`` (floats unless ``dtype`` says otherwise) that cannot be written to (results
    are immutable)."""
    out = np.array(a, dtype=dtype)
    out.setflags(write=False)
    return out


def frozen(a: np.ndarray) -> np.ndarray:
    """``a`` itself made read-only, without a copy: for an array just computed and not shared
    (:func:`readonly` copies, for arrays that someone else may still write to)."""
    a.setflags(write=False)
    return a


def shared(a: np.ndarray) -> np.ndarray:
    """``a`` itself when it is read-only already (nobody can change it: a result's array), else a
    read-only copy (:func:`readonly`)."""
    return a if isinstance(a, np.ndarray) and not a.flags.writeable and a.dtype == float else readonly(a)


def rot(theta: Any, p: Vec2 | np.ndarray) -> np.ndarray:
    """R(θ)·p for an angle or an array of angles θ (rad): shape ``θ.shape + (2,)``."""
    c, s = np.cos(theta), np.sin(theta)
    out = np.empty(np.shape(c) + (2,))      # filled in place: faster than np.stack, same bits
    out[..., 0] = c * p[0] - s * p[1]
    out[..., 1] = s * p[0] + c * p[1]
    return out


def rot_vec2(theta: float, p: Vec2) -> Vec2:
    """R(θ)·p for one angle, as plain floats."""
    return vec2(rot(theta, p))


def perp(v: np.ndarray) -> np.ndarray:
    """v turned by +90° (counter-clockwise): (x, y) → (−y, x), over the last axis."""
    v = np.asarray(v, dtype=float)
    out = np.empty(v.shape[:-1] + (2,))
    out[..., 0] = -v[..., 1]
    out[..., 1] = v[..., 0]
    return out


def cross(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """The z component of a × b over the last axis."""
    return a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]


def dot(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """a · b over the last axis."""
    return a[..., 0] * b[..., 0] + a[..., 1] * b[..., 1]
