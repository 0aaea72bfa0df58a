"""Exception classes of reportgen. Each stores its fields and builds its message from them.

Exit status policy (RESULTS_FORMAT.md): a ``ReportgenInputError`` is bad input (exit 2), a
``BuildError`` is a failure of a build stage (exit 1).
"""
from __future__ import annotations


class ReportgenError(Exception):
    """Base class of every error raised on purpose by reportgen."""

    def __str__(self) -> str:  # the message as given, also for the KeyError subclasses
        return BaseException.__str__(self)


class ReportgenInputError(ReportgenError, ValueError):
    """Bad input: the task file, a command-line option, or a mechanism that cannot work."""


class TaskError(ReportgenInputError):
    """A task-file value is missing, of the wrong type, or out of range.

    ``path`` is the TOML path (``mechanism.link[3].length``), ``problem`` what is wrong and
    ``expected`` what would be valid.
    """

    def __init__(self, path: str, problem: str, expected: str | None = None) -> None:
        self.path = path
        self.problem = problem
        self.expected = expected
        msg = f"{path}: {problem}" if path else problem
        if expected:
            msg += f" (expected {expected})"
        super().__init__(msg)


class UnknownKeyError(TaskError):
    """A key that the task format does not know; ``suggestion`` is the nearest known key."""

    def __init__(self, path: str, key: str, known: list[str], suggestion: str | None) -> None:
        self.key = key
        self.known = list(known)
        self.suggestion = suggestion
        problem = f"unknown key '{key}'"
        if suggestion:
            problem += f"; did you mean '{suggestion}'?"
        super().__init__(path, problem, "one of: " + ", ".join(sorted(known)) if known else "no keys here")


class OptionError(ReportgenInputError):
    """A bad command-line option: ``option`` names it, ``expected`` says what is valid."""

    def __init__(self, option: str, problem: str, expected: str | None = None) -> None:
        self.option = option
        self.problem = problem
        self.expected = expected
        msg = f"{option}: {problem}"
        if expected:
            msg += f" (expected {expected})"
        super().__init__(msg)


class OutputFolderError(OptionError):
    """``build`` refuses its output folder: ``folder`` as given, ``problem`` why, ``expected`` what to do.

    Nothing is written or deleted when this is raised (see ``reportgen/commands/outdir.py``).
    """

    def __init__(self, option: str, folder, problem: str, expected: str | None = None) -> None:
        self.folder = str(folder)
        self.option = option
        self.problem = problem
        self.expected = expected
        msg = f"{option} {self.folder}: refused, {problem}; nothing was written or deleted"
        if expected:
            msg += f". Use {expected}"
        ReportgenInputError.__init__(self, msg)


class StructureError(ReportgenInputError):
    """The kinematic chain cannot be decomposed into a driver and Assur groups.

    ``leftover`` lists the links left over, ``cause`` the likely reason.
    """

    def __init__(self, problem: str, leftover: tuple[int, ...] = (), cause: str | None = None) -> None:
        self.problem = problem
        self.leftover = tuple(leftover)
        self.cause = cause
        msg = problem
        if self.leftover:
            msg += f"; links left over: {', '.join(map(str, self.leftover))}"
        if cause:
            msg += f"; likely cause: {cause}"
        super().__init__(msg)


class AssemblyError(ReportgenInputError):
    """A group cannot be assembled at a crank angle.

    ``group`` names the group (e.g. ``II(2,3) RRR``), ``phi_deg`` the crank angle, ``inequality``
    the violated condition written with its numbers, ``feasible`` the crank ranges (deg) where it
    assembles, if known.
    """

    def __init__(self, group: str, phi_deg: float, inequality: str,
                 feasible: tuple[tuple[float, float], ...] | None = None) -> None:
        self.group = group
        self.phi_deg = phi_deg
        self.inequality = inequality
        self.feasible = feasible
        msg = (f"the group {group} cannot be assembled at crank angle φ1 = {phi_deg:.2f}°: "
               f"{inequality}")
        if feasible is not None:
            if feasible:
                rng = ", ".join(f"{a:.1f}°…{b:.1f}°" for a, b in feasible)
                msg += f"; it assembles for φ1 in {rng}"
            else:
                msg += "; it assembles at no crank angle"
        super().__init__(msg)


class SingularPositionError(ReportgenError, ArithmeticError):
    """A linear system of a group is singular (a dead centre) at crank angle ``phi_deg``."""

    def __init__(self, group: str, phi_deg: float, detail: str = "") -> None:
        self.group = group
        self.phi_deg = phi_deg
        self.detail = detail
        msg = f"the group {group} is at a singular position at φ1 = {phi_deg:.4f}°"
        if detail:
            msg += f": {detail}"
        super().__init__(msg)


class BuildError(ReportgenError, RuntimeError):
    """A build stage failed; ``stage`` names it, ``kept`` says what was kept and where."""

    def __init__(self, stage: str, problem: str, kept: str | None = None) -> None:
        self.stage = stage
        self.problem = problem
        self.kept = kept
        msg = f"{stage} failed: {problem}"
        if kept:
            msg += f"\nkept: {kept}"
        super().__init__(msg)


class TaskSyntaxError(TaskError):
    """The task file cannot be read as TOML (or as UTF-8 text).

    ``path`` is the file, ``line`` and ``column`` (1-based) where the reader stopped, ``problem``
    what is wrong there.
    """

    def __init__(self, file: str, line: int, column: int, problem: str) -> None:
        self.file = file
        self.line = line
        self.column = column
        super().__init__(file, f"line {line}, column {column}: {problem}",
                         "TOML syntax, see https://toml.io")


class PlanetarySynthesisError(ReportgenInputError):
    """No planetary tooth set meets every condition for the target ratio.

    ``scheme``, ``target`` and ``tolerance`` repeat the request, ``satellites`` the K asked for
    ("auto" or a number), ``reasons`` say which conditions rejected the sets that gave the ratio,
    ``nearest`` lists the nearest ratios that do exist as ``(ratio, z, K)``.
    """

    def __init__(self, scheme: str, target: float, tolerance: float, satellites: int | str,
                 reasons: tuple[str, ...], nearest: tuple[tuple[float, tuple[int, ...], int], ...]) -> None:
        self.scheme = scheme
        self.target = target
        self.tolerance = tolerance
        self.satellites = satellites
        self.reasons = tuple(reasons)
        self.nearest = tuple(nearest)
        msg = (f"planetary.ratio: no {scheme} tooth set gives u = {target:g} within "
               f"±{tolerance * 100:g} % with satellites = {satellites}")
        if self.reasons:
            msg += ": " + "; ".join(self.reasons)
        if self.nearest:
            msg += "; nearest ratios that exist: " + ", ".join(
                f"{u:.4g} (z = {'/'.join(map(str, z))}, K = {k})" for u, z, k in self.nearest)
        else:
            msg += "; no valid set found near it either"
        msg += " (expected a ratio this scheme can give, a larger tolerance or another scheme)"
        super().__init__(msg)


# ------------------------------------------------------------------------------ not bad input
# Everything below is exit status 1 (a stage failed); ``build`` keeps ``OUT.failed/`` for it.

class InternalError(ReportgenError, RuntimeError):
    """A check of reportgen's own consistency failed (a bug, not the task's fault).

    ``what`` names the check, ``detail`` what was found. The message asks for a report.
    """

    def __init__(self, what: str, detail: str = "") -> None:
        self.what = what
        self.detail = detail
        msg = f"{what}: {detail}" if detail else what
        super().__init__(msg + " (an internal error of reportgen; please report it with the task file)")


class ParameterError(InternalError, ValueError):
    """A function got a parameter outside its range: ``name``, ``value`` and the ``expected`` range.

    The loader validates the task first, so this is reached only by a caller's mistake.
    """

    def __init__(self, name: str, value: object, expected: str) -> None:
        self.name = name
        self.value = value
        self.expected = expected
        super().__init__(f"{name} = {value!r}", f"expected {expected}")


class NameLookupError(InternalError, KeyError):
    """A name (a link id, a point, a force, a gear quantity) that a result does not hold.

    ``kind`` says what was looked up, ``name`` the name asked for, ``known`` the names there are.
    """

    def __init__(self, kind: str, name: object, known: tuple = ()) -> None:
        self.kind = kind
        self.name = name
        self.known = tuple(known)
        shown = ", ".join(map(str, self.known[:20])) + (" …" if len(self.known) > 20 else "")
        super().__init__(f"no {kind} {name!r}", f"known: {shown}" if self.known else "")


class ComputationError(ReportgenError, ArithmeticError):
    """A numerical method failed: ``method`` names it, ``detail`` says how."""

    def __init__(self, method: str, detail: str) -> None:
        self.method = method
        self.detail = detail
        super().__init__(f"{method}: {detail}")


class GeometryError(ReportgenError, ValueError):
    """A geometric construction has no solution (a line that misses a circle …): ``what`` and ``detail``."""

    def __init__(self, what: str, detail: str = "") -> None:
        self.what = what
        self.detail = detail
        super().__init__(f"{what}: {detail}" if detail else what)
