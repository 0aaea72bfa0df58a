"""The note's matplotlib plots keyed by their data, as the scene figures are by their scene
(:func:`latex_templates.figures.scene.figure_key`), so that the build cache keeps their PDF.

``@keyed_plot()`` on a function that makes a plot from plain data: its key is the content digest
(:func:`reportgen.cache.content_digest`) of the function's name, its arguments and the note's
language (catalogue, decimal mark); the build cache adds the code's fingerprint (every source
file, the libraries' versions, the fonts installed). Inside a build whose cache keeps a plot
with that key, the function is not called: a :class:`.saving.KeptFigure` stands in and the kept
PDF is copied. A plot whose arguments have no canonical form is made and saved as before (no
key), as is every plot of a build without a cache (``content_keys_read``); one that gets artists
after it is made loses its key (:func:`.saving.content_key`).

The function must draw nothing but its arguments in the active language: no other global state,
no stage of the project read on the side. ``skip``: dataclass fields of the arguments that the
plot does not draw, left out of the key (the structural schemes draw no masses).
"""
from __future__ import annotations

import functools
from typing import Any, Callable, TypeVar

from reportgen.errors import InternalError

from ..parts import active, active_strings
from .saving import content_keys_read, kept_figure, mark_content

F = TypeVar("F", bound=Callable[..., Any])


def plot_key(fn: Callable[..., Any], args: tuple, kwargs: dict[str, Any],
             skip: frozenset[tuple[str, str]] = frozenset()) -> str | None:
    """The content key of the plot ``fn(*args, **kwargs)`` in the active language, or None when an
    argument has no canonical form."""
    from reportgen.cache import content_digest

    strings = active()
    try:
        return content_digest(("plot", fn.__module__, fn.__qualname__, args, sorted(kwargs.items()),
                               strings.language, getattr(strings, "_overlay", None)), skip=skip)
    except InternalError:
        return None


def keyed_plot(skip: frozenset[tuple[str, str]] = frozenset()) -> Callable[[F], F]:
    """Key the plots ``fn`` makes by their data (see the module's docstring)."""
    def wrap(fn: F) -> F:
        @functools.wraps(fn)
        def keyed(*args: Any, **kwargs: Any) -> Any:
            key = plot_key(fn, args, kwargs, skip) if content_keys_read() else None
            if key is None:
                return fn(*args, **kwargs)

            strings = active()

            def make() -> Any:          # perhaps later (a kept PDF gone): in the language of now
                with active_strings(strings):
                    fig = fn(*args, **kwargs)
                fig.reportgen_key = key
                mark_content(fig)
                return fig

            kept = kept_figure(key, make)
            return kept if kept is not None else make()
        return keyed  # type: ignore[return-value]
    return wrap
