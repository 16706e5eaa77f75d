"""Derivations step by step (the command line's ``--steps``) from Python.

``G.steps("jordan")``, ``G.steps("scb")``, ``G.steps("minreal", method="jordan")`` or
``exactlti.steps(G, "tf")`` run the library's derivation through its front door
(``exactlti::api::steps::steps_on``) and return a :class:`Derivation`: a list of
:class:`Step` (what was computed, the exact objects, the identity it establishes and
whether it held, what it assumes over Q(p)), shown in Jupyter as the worked example the
library typesets (``_repr_latex_``, ``_repr_html_``).
"""

import json

from ._display import Rendered
from ._exact import Matrix

#: commands with a derivation (``minreal`` takes ``method``; ``jordan`` takes ``real``)
COMMANDS = ("jordan", "minreal", "scb", "zeros", "tf", "standard", "mnf")

_META = ("step", "sentence", "part", "identity", "holds", "assumes")


class Step:
    """One step: ``kind`` (``"charpoly"``, ``"chain"``, ...), ``sentence``, ``objects``
    (name -> exact value: :class:`Matrix` for matrices, exact text for polynomials and
    scalars, ints and lists of ints for ranks and counts), ``identity`` (plain text, or
    None when the step computes without checking), ``holds`` (the identity held exactly),
    ``assumes`` (polynomials assumed nonzero over Q(p)) and ``part`` (the eigenvalue or
    block it belongs to, 1-based, or None)."""

    def __init__(self, d):
        self.kind = d["step"]
        self.sentence = d["sentence"]
        self.part = d.get("part")
        self.identity = d.get("identity")
        self.holds = d.get("holds")
        self.assumes = list(d.get("assumes", []))
        self.objects = {}
        for k, v in d.items():
            if k in _META or k.endswith("_approx"):
                continue
            if k + "_approx" in d and isinstance(v, list):
                v = Matrix._from_strings(v)
            self.objects[k] = v

    def __getitem__(self, key):
        return self.objects[key]

    def __repr__(self):
        held = "" if self.holds is None else (", holds" if self.holds else ", FAILS")
        return "Step(%s: %s%s)" % (self.kind, ", ".join(self.objects), held)


class Derivation(list, Rendered):
    """A derivation: a list of :class:`Step` with ``title``, ``field``, ``verified`` (every
    identity held exactly), ``conditions`` (over Q(p): polynomials assumed nonzero) and
    ``report`` (the steps as the command line's JSON)."""

    def __init__(self, text, verified, latex, html):
        self.report = json.loads(text)
        super().__init__(Step(s) for s in self.report["steps"])
        self.verified = bool(verified)
        self.field = self.report.get("field")
        self.conditions = list(self.report.get("conditions", []))
        self._rendered = {"latex": latex, "html": html}

    def kinds(self):
        """The kinds of the steps, in order."""
        return [s.kind for s in self]

    def find(self, kind):
        """The steps of one kind."""
        return [s for s in self if s.kind == kind]

    def __repr__(self):
        return "Derivation(%d steps over %s, verified=%s)" % (len(self), self.field, self.verified)


def steps(system, command, method=None, real=False, expand=False, max_seconds=None,
          normalize=None, descriptor=False):
    """The derivation of ``command`` on ``system`` step by step (the command line's
    ``exactlti COMMAND FILE --steps``): ``command`` is one of :data:`COMMANDS`;
    ``method`` for ``minreal`` (``"kalman"``, ``"rosenbrock"``, ``"ho-kalman"``,
    ``"jordan"``), ``descriptor=True`` for ``minreal --descriptor``, ``real`` (and
    ``expand``) for ``jordan``, ``normalize`` for ``jordan`` (``"orth"``: generalized
    eigenvectors orthogonal to the eigenvector, eq. 31; ``"entry"``, ``"entry:<row>"``,
    ``"unit"``; ``"paper"`` = ``"orth,unit"``).

    >>> import exactlti
    >>> G = exactlti.ss([[1, 1], [0, 1]], [[0], [1]], [[1, 0]])
    >>> d = G.steps("jordan")
    >>> d.verified, d.kinds()[:2]
    (True, ['charpoly', 'factorization'])
    """
    if command not in COMMANDS:
        raise ValueError(
            "steps: no derivation for '%s' (one of %s)" % (command, ", ".join(COMMANDS))
        )
    source, _ = system._core.source
    argv = [command, source]
    if method is not None:
        if command != "minreal":
            raise ValueError("steps: method is an option of minreal")
        argv += ["--method", str(method)]
    if descriptor:
        if command != "minreal":
            raise ValueError("steps: descriptor is an option of minreal")
        argv.append("--descriptor")
    if normalize is not None:
        if command != "jordan":
            raise ValueError("steps: normalize is an option of jordan")
        argv += ["--normalize", str(normalize)]
    if real:
        argv.append("--real")
    if expand:
        argv.append("--expand")
    return Derivation(*system._core.steps(argv, max_seconds))
