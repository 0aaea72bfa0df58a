"""A memory of the reduced quantities already computed at given θ, for one cycle.

The dynamics asks a cycle for M_red, J_red (and dJ_red/dθ) at the same angles many times: the
grid's nodes (Wittenbauer, the steady motion, the grid's ΔE), the refinement rounds of the steady
motion's extremes (its second pass repeats the first until the last round), the graphical replica
at a grid and then at that grid and its midpoints. Every value is a pure function of θ, so a value
kept is the value that would be computed again, bit for bit, when

- the very same array of angles is asked again (always), or
- the model computes every position on its own (``elementwise``: closed-form dyads; not a class III
  group, whose Newton iterations run until *every* position of the call converges, so one position's
  last bits depend on the others asked with it): then each angle is looked up on its own, and only
  the angles never seen are computed, in one call.
"""
from __future__ import annotations

from collections.abc import Callable

import numpy as np

from ..geometry import frozen

#: Calls kept (newest first searched); enough for the dynamics of one project.
KEEP = 48


class ReducedMemo:
    """M, J, dJ at angles already computed (``dJ`` may be absent: ``None``)."""

    def __init__(self, compute: Callable[[np.ndarray, bool], tuple[np.ndarray, np.ndarray, np.ndarray | None]],
                 elementwise: bool) -> None:
        self._compute = compute
        self.elementwise = elementwise
        self._calls: dict[tuple[bytes, bool], tuple[np.ndarray, np.ndarray, np.ndarray | None]] = {}
        # elementwise: (θ's bits as sorted int64 keys, M, J, dJ or None), in the keys' order, newest last
        self._known: list[tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray | None]] = []
        self.computed = 0            # angles computed (for tests and benchmarks)

    def __call__(self, theta: np.ndarray, with_dJ: bool) -> tuple[np.ndarray, np.ndarray, np.ndarray | None]:
        """(M, J, dJ) at ``theta`` (1-D floats); dJ is None unless ``with_dJ``."""
        key = (theta.tobytes(), with_dJ)
        hit = self._calls.get(key)
        if hit is None and not with_dJ:
            full = self._calls.get((key[0], True))
            hit = None if full is None else (full[0], full[1], None)
        if hit is not None:
            return hit
        out = self._elementwise(theta, with_dJ) if self.elementwise else self._fresh(theta, with_dJ)
        if len(self._calls) >= KEEP:
            self._calls.pop(next(iter(self._calls)))
        self._calls[key] = out
        return out

    def _fresh(self, theta: np.ndarray, with_dJ: bool):
        self.computed += theta.size
        M, J, dJ = self._compute(theta, with_dJ)
        return M, J, (dJ if with_dJ else None)

    def _elementwise(self, theta: np.ndarray, with_dJ: bool):
        # angles are matched by their bits (as int64 keys, sorted): −0.0 and 0.0 are two angles here
        keys = np.ascontiguousarray(theta, dtype=float).view(np.int64)
        n = theta.size
        M, J = np.empty(n), np.empty(n)
        dJ = np.empty(n) if with_dJ else None
        todo = np.arange(n)
        for ks, Mk, Jk, dJk in reversed(self._known):
            if todo.size == 0:
                break
            if with_dJ and dJk is None:
                continue
            k = keys[todo]
            pos = np.minimum(np.searchsorted(ks, k), ks.size - 1)
            found = ks[pos] == k
            if not found.any():
                continue
            at, src = todo[found], pos[found]
            M[at], J[at] = Mk[src], Jk[src]
            if dJ is not None:
                assert dJk is not None
                dJ[at] = dJk[src]
            todo = todo[~found]
        if todo.size:
            # each new angle once (a search may ask for the same angle twice in one call)
            uk, inv = np.unique(keys[todo], return_inverse=True)
            Mn, Jn, dJn = self._fresh(uk.view(float), with_dJ)
            M[todo], J[todo] = Mn[inv], Jn[inv]
            if dJ is not None:
                assert dJn is not None
                dJ[todo] = dJn[inv]
            self._known.append((uk, Mn, Jn, dJn))
            if len(self._known) > KEEP:
                self._known.pop(0)
        return frozen(M), frozen(J), (None if dJ is None else frozen(dJ))
