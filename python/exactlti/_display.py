"""Jupyter display of results: ``_repr_latex_`` and ``_repr_html_`` made by the library's
report layer (Rust, ``exactlti::report``) from the result's values, never by re-reading
text here.

A result carries its rendering (``{"json", "latex", "html"}`` from the core) when the
computation made a report; otherwise it knows the command of the command line that
reports it (``("tf",)`` on its system) and runs it through the library's front door the
first time it is shown (symbolic results: the command's report carries the field and the
conditions).
"""

import json


def report_parts(d):
    """``(report dict, rendering)`` from a core result's ``report`` entry (or ``None``)."""
    r = d.get("report") if isinstance(d, dict) else None
    if r is None:
        return None, None
    return json.loads(r["json"]), {"latex": r["latex"], "html": r["html"]}


class Rendered:
    """Mixin: ``_repr_latex_`` / ``_repr_html_`` from the report layer.

    Set ``_rendered`` (a dict with ``latex`` and ``html``), or ``_source`` = ``(system,
    op, *args)`` for a rendering computed when first shown."""

    _rendered = None
    _source = None

    def _render(self):
        if self._rendered is None and self._source is not None:
            from ._api import run

            system, op, *args = self._source
            self._rendered = run(system, op, *args)._rendered
        return self._rendered

    def _repr_latex_(self):
        r = self._render()
        return None if r is None else r["latex"]

    def _repr_html_(self):
        r = self._render()
        return None if r is None else r["html"]

    def to_latex(self):
        """The result as a LaTeX fragment (an ``amsmath`` document's body)."""
        return self._repr_latex_()

    def to_html(self):
        """The result as HTML with TeX math for MathJax (what a notebook shows)."""
        return self._repr_html_()
