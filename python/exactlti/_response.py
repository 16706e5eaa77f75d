"""The papers' remaining computations as methods of :class:`StateSpace`: the free response
``x(t) = e^(At) x0`` in closed form (exact over Q, in symbols over Q(p); the Jordan paper's
eq. 36-37) and the modes ranked by contribution with truncation (the minimal-realizations
paper's eq. 33). Each runs the command line's operation through the library's front door
(``exactlti response FILE --x0 ...``, ``exactlti contributions FILE --keep K``)."""

from fractions import Fraction

from ._api import run


def _entry(x):
    """One entry of ``x0`` as the command line reads it: exact numbers as fractions, text
    (symbols, ``"1/3"``, ``"0.1"``) and SymPy expressions as written."""
    if isinstance(x, bool):
        raise TypeError("x0: a bool is not a number")
    if isinstance(x, (int, Fraction)):
        return str(x)
    if isinstance(x, float):
        return repr(x)
    text = str(x).replace("**", "^")
    if "," in text:
        raise ValueError("x0: an entry may not contain a comma (%r)" % (text,))
    return text


class ResponseOps:
    """Mixin of :class:`StateSpace`: ``free_response`` and ``contributions``."""

    def free_response(self, x0, times=None, max_seconds=None):
        """``x(t) = e^(At) x0 = sum_k t^k e^(s t) g`` in closed form: a :class:`Report`
        whose ``terms`` give per eigenvalue ``s`` and power ``k`` the exact vector ``g``,
        checked exactly (``x' = A x`` term by term and ``x(0) = x0``: ``verified``).
        ``x0``: one entry per state (int, Fraction, exact text; symbols such as
        ``"psi0"`` give the response in symbols over Q(p)). ``times``: also the float
        values ``x(t)`` (``values``)."""
        args = ["--x0", ",".join(_entry(x) for x in x0)]
        if times is not None:
            args += ["--times", ",".join(repr(float(t)) for t in times)]
        return run(self, "response", *args, max_seconds=max_seconds)

    def contributions(self, keep=None, max_seconds=None):
        """The modes ranked by contribution (eq. 33): per mode (an irreducible factor of
        ``det(sI - A)``) its exact squared H2 norm ``h2_squared`` (``"0"`` when it does not
        reach the output, ``"inf"`` when it contributes and is not asymptotically stable)
        and its residues ``H = C G_k B``. With ``keep``: ``truncation``, the realization of
        the ``keep`` heaviest modes over Q and its exact error (``error_h2_squared``,
        ``error_dc_gain``, ``error_markov0``)."""
        args = [] if keep is None else ["--keep", str(int(keep))]
        return run(self, "contributions", *args, max_seconds=max_seconds)
