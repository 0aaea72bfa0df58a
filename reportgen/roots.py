"""Scalar root finding and extreme search without scipy (whose import alone takes ~0.6 s, longer
than the whole solve of a variant).

- :func:`brent_root`: Brent's method (R. P. Brent, «Algorithms for Minimization without
  Derivatives», 1973, ch. 4, the procedure *zero*): bisection, secant and inverse quadratic
  interpolation, keeping a bracket [b, c] with f(b)·f(c) ≤ 0; stops when half the bracket is
  within ``xtol + rtol·|b|`` (scipy's ``brentq`` criterion). :func:`brent_roots` runs several
  searches in lockstep, one vectorised evaluation per step for all of them.
- :func:`extremes`: the largest / smallest value of continuous functions near the best grid node,
  refined on both neighbouring intervals by vectorised sampling: every round samples ``SAMPLES``
  points across each current bracket in *one* call of the (vectorised) function for all searches
  at once and keeps the two samples' spacing around the best; a unimodal function's extreme stays
  inside, and the bracket shrinks by (SAMPLES − 1)/2 per round, until it is ``EXTREME_XTOL`` wide
  or flat (all its samples equal to rounding, ``FLAT``).
"""
from __future__ import annotations

import math
from collections.abc import Callable, Generator, Sequence

import numpy as np

from .errors import ComputationError
from .tolerances import BRACKET_NODE_EPS, BRENT_RTOL, BRENT_XTOL, EXTREME_XTOL

#: Points sampled across each bracket per round of :func:`extremes`.
SAMPLES = 17
#: A bracket whose samples all agree with the best to this relative spread (a few ulps) is done:
#: the value is exact to rounding, and its abscissa cannot be resolved any further (≈ √ε·scale).
FLAT = 8 * np.finfo(float).eps


class RootNotBracketedError(ComputationError, ValueError):
    """f(a) and f(b) have the same sign: ``a``, ``b``, ``fa``, ``fb``."""

    def __init__(self, a: float, b: float, fa: float, fb: float) -> None:
        self.a, self.b, self.fa, self.fb = a, b, fa, fb
        super().__init__("Brent's method", f"f({a!r}) = {fa!r} and f({b!r}) = {fb!r} have the same sign")


def brent_root(f: Callable[..., float], a: float, b: float, args: tuple = (), *, xtol: float = BRENT_XTOL,
               rtol: float = BRENT_RTOL, maxiter: int = 200) -> float:
    """A root of f in [a, b] (f(a)·f(b) ≤ 0) by Brent's method, to ``xtol + rtol·|x|``."""
    steps = _brent(a, b, xtol, rtol, maxiter)
    x = next(steps)
    while True:
        try:
            x = steps.send(float(f(x, *args)))
        except StopIteration as done:
            return done.value


def brent_roots(f: Callable[[np.ndarray], np.ndarray], brackets: Sequence[tuple[float, float]], *,
                xtol: float = BRENT_XTOL, rtol: float = BRENT_RTOL, maxiter: int = 200,
                known: Sequence[tuple[float, float]] | None = None) -> list[float]:
    """:func:`brent_root` on several brackets in lockstep: each step evaluates the vectorised ``f``
    once, at the next abscissa of every search still running. Every search takes exactly the
    steps it would take alone, so the roots are the same bits as one by one when ``f`` computes
    each abscissa on its own (its value does not depend on the others of the call). ``known``:
    f at the ends of each bracket, when the caller has them (they are not evaluated again)."""
    searches = [_brent(a, b, xtol, rtol, maxiter, *(known[i] if known is not None else ())) for i, (a, b)
                in enumerate(brackets)]
    roots: list[float | None] = [None] * len(searches)
    asks = {i: next(sr) for i, sr in enumerate(searches)}
    while asks:
        idx = list(asks)
        vals = np.asarray(f(np.array([asks[i] for i in idx], dtype=float)), dtype=float)
        for i, v in zip(idx, vals):
            try:
                asks[i] = searches[i].send(float(v))
            except StopIteration as done:
                roots[i] = done.value
                del asks[i]
    return [float(r) for r in roots if r is not None]


def _brent(a: float, b: float, xtol: float, rtol: float, maxiter: int, fa: float | None = None,
           fb: float | None = None) -> Generator[float, float, float]:
    """Brent's method as a coroutine: yields each abscissa to evaluate, is sent f there, returns
    the root (so that one search or several in lockstep share the same steps)."""
    if fa is None:
        fa = yield a
    if fb is None:
        fb = yield b
    if fa == 0.0:
        return a
    if fb == 0.0:
        return b
    if (fa > 0) == (fb > 0):
        raise RootNotBracketedError(a, b, fa, fb)
    c, fc = a, fa
    d = e = b - a
    for _ in range(maxiter):
        if (fb > 0) == (fc > 0):        # keep the root between b and c
            c, fc = a, fa
            d = e = b - a
        if abs(fc) < abs(fb):           # b is the best estimate
            a, fa = b, fb
            b, fb = c, fc
            c, fc = a, fa
        tol = 0.5 * (xtol + rtol * abs(b))
        m = 0.5 * (c - b)
        if abs(m) <= tol or fb == 0.0:
            return b
        if abs(e) >= tol and abs(fa) > abs(fb):
            s = fb / fa
            if a == c:                  # secant
                p, q = 2.0 * m * s, 1.0 - s
            else:                       # inverse quadratic interpolation
                qa, r = fa / fc, fb / fc
                p = s * (2.0 * m * qa * (qa - r) - (b - a) * (r - 1.0))
                q = (qa - 1.0) * (r - 1.0) * (s - 1.0)
            if p > 0:
                q = -q
            else:
                p = -p
            if 2.0 * p < min(3.0 * m * q - abs(tol * q), abs(e * q)):
                e, d = d, p / q         # interpolation accepted
            else:
                d = e = m               # bisection
        else:
            d = e = m
        a, fa = b, fb
        b += d if abs(d) > tol else (tol if m > 0 else -tol)
        fb = float((yield b))
    raise ComputationError("Brent's method", f"no convergence in {maxiter} steps on [{a}, {b}]")


Search = tuple[Callable[[tuple], np.ndarray], np.ndarray, str]


def extremes(evaluate: Callable[[np.ndarray], tuple], nodes: np.ndarray,
             searches: Sequence[Search], xtol: float = EXTREME_XTOL) -> list[tuple[float, float]]:
    """(θ, value) of each search's extreme over a periodic grid ``nodes`` (first = last position).

    ``evaluate(t)`` returns a tuple of arrays at the abscissae ``t`` (one call per round serves
    every search); a search is ``(value_of, values_at_nodes, kind)`` with ``value_of(evaluated)``
    the function searched and ``kind`` "max" or "min". The function is taken smooth and unimodal
    between neighbouring nodes (break angles must be nodes).
    """
    nodes = np.asarray(nodes, dtype=float)
    last = nodes.size - 1
    brackets: list[list[tuple[float, float]]] = []
    best: list[tuple[float, float]] = []
    signs: list[float] = []
    for _, values, kind in searches:
        s = 1.0 if kind == "max" else -1.0
        j = int(np.argmax(s * np.asarray(values)))
        best.append((float(nodes[j]), float(values[j])))
        signs.append(s)
        pairs = [(0, 1), (last - 1, last)] if j in (0, last) else [(j - 1, j), (j, j + 1)]
        brackets.append([(float(nodes[lo]), float(nodes[hi])) for lo, hi in pairs
                         if 0 <= lo and hi <= last and nodes[hi] - nodes[lo] > xtol])
    limits = [list(b) for b in brackets]
    u = np.linspace(0.0, 1.0, SAMPLES)
    while any(b - a > 2.0 * xtol for br in brackets for a, b in br):
        flat = [(k, i) for k, br in enumerate(brackets) for i, (a, b) in enumerate(br) if b - a > 2.0 * xtol]
        lo = np.array([brackets[k][i][0] for k, i in flat])
        hi = np.array([brackets[k][i][1] for k, i in flat])
        t = lo[:, None] + (hi - lo)[:, None] * u[None, :]
        state = evaluate(t.ravel())
        for row, (k, i) in enumerate(flat):
            v = searches[k][0](tuple(x.reshape(t.shape)[row] for x in state))
            jj = int(np.argmax(signs[k] * v))
            if signs[k] * v[jj] > signs[k] * best[k][1]:
                best[k] = (float(t[row, jj]), float(v[jj]))
            step = (hi[row] - lo[row]) / (SAMPLES - 1)
            if np.ptp(v) <= FLAT * max(abs(float(v[jj])), np.finfo(float).tiny):
                # every sample equals the extreme to rounding: no narrower bracket can tell them apart
                brackets[k][i] = (float(t[row, jj]), float(t[row, jj]))
                continue
            a0, b0 = limits[k][i]
            brackets[k][i] = (max(a0, t[row, jj] - step), min(b0, t[row, jj] + step))
        for k, br in enumerate(brackets):
            # after the first round only the bracket around the best sample so far is searched on:
            # the function is unimodal around its extreme, across the node between the intervals
            if len(br) > 1:
                # (a best sample on the node shared by both brackets keeps both sides, as one bracket:
                # the extreme may lie just beyond the node, closer than one sample spacing)
                keep = [i for i, (a, b) in enumerate(br) if a - BRACKET_NODE_EPS <= best[k][0] <= b + BRACKET_NODE_EPS]
                if keep:
                    brackets[k] = [(min(br[i][0] for i in keep), max(br[i][1] for i in keep))]
                    limits[k] = [(min(limits[k][i][0] for i in keep), max(limits[k][i][1] for i in keep))]
    for _t, v_best in best:
        if not math.isfinite(v_best):
            raise ComputationError("the search for an extreme", "a non-finite value")
    return best
