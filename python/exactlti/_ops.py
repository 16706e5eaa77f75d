"""Operators and python-control's system functions on exact systems.

``G * H`` is the series connection H then G (transfer matrix ``G(s) H(s)``, as in
python-control), ``G + H`` the parallel one, ``-G`` and ``G - H`` follow, and a number or a
matrix stands for a static gain. ``series``, ``parallel``, ``feedback`` return systems
(python-control's functions); the methods ``G.series(H)`` ... keep returning their reports.
Every result is exact, checked against its parts, and keeps the signal names and the
sample time ``dt`` by python-control's rules; a continuous and a discrete system, or two
sample times, do not connect (``ValueError``).
"""

from fractions import Fraction

from . import _core


def _gain(value, like, rows=None, cols=None):
    """A static gain ``y = K u`` as a system (``value``: a number or a matrix)."""
    from ._system import StateSpace, ss

    if isinstance(value, StateSpace):
        return value
    try:
        rows_v = [list(r) for r in value]
    except TypeError:
        n = rows if rows is not None else 1
        k = value
        rows_v = [[k if i == j else 0 for j in range(n)] for i in range(n)]
    p, m = len(rows_v), len(rows_v[0]) if rows_v else 0
    return ss(_empty(0, 0), _empty(0, m), _empty(p, 0), rows_v, name="gain")


def _empty(r, c):
    import numpy as np

    return np.zeros((r, c), dtype=int)


def _connect(op, systems, *args):
    first, rest = systems[0], systems[1:]
    names = ["s%d" % i for i in range(len(systems))]
    core = first._core.connect_system([op] + names + list(args), [s._core for s in rest])
    from ._system import StateSpace

    return StateSpace(core)


def series(*systems):
    """``series(G1, G2, ...)``: G1 first, then G2 (transfer matrix ``... G2 G1``), exact."""
    out = systems[0]
    for s in systems[1:]:
        out = _connect("series", [out, s])
    return out


def parallel(*systems):
    """``parallel(G1, G2, ...)``: the sum of the transfer matrices, exact."""
    out = systems[0]
    for s in systems[1:]:
        out = _connect("parallel", [out, s])
    return out


def feedback(sys1, sys2=1, sign=-1):
    """python-control's ``feedback(sys1, sys2, sign=-1)``: ``sys1`` with ``sys2`` (a system
    or a gain) in the feedback path, negative feedback unless ``sign=1``; exact."""
    k = _gain(sys2, sys1, rows=sys1.noutputs)
    args = ["--positive"] if sign == 1 else []
    if sign not in (1, -1):
        raise ValueError("sign must be 1 or -1, found %r" % (sign,))
    return _connect("feedback", [sys1, k], *args)


class SystemOps:
    """``*``, ``+``, ``-`` (binary and unary) on exact systems and gains."""

    def __mul__(self, other):
        h = _gain(other, self, rows=self.ninputs)
        return _connect("series", [h, self])

    def __rmul__(self, other):
        k = _gain(other, self, rows=self.noutputs)
        return _connect("series", [self, k])

    def __add__(self, other):
        return _connect("parallel", [self, _gain(other, self, rows=self.noutputs)])

    def __radd__(self, other):
        return _connect("parallel", [_gain(other, self, rows=self.noutputs), self])

    def __neg__(self):
        return _connect("series", [self, _gain(-1, self, rows=self.noutputs)])

    def __sub__(self, other):
        return self + (-_gain(other, self, rows=self.noutputs))

    def __rsub__(self, other):
        return _gain(other, self, rows=self.noutputs) + (-self)

    @property
    def dt(self):
        """The sample time (a ``Fraction``) of a discrete-time system; ``0`` for continuous
        time (python-control's convention)."""
        t = self._core.dt
        return Fraction(t) if t is not None else 0

    def isdtime(self):
        """True for a discrete-time system."""
        return self._core.dt is not None

    def isctime(self):
        """True for a continuous-time system."""
        return self._core.dt is None

    @property
    def input_labels(self):
        """The input names (``u[0]``, ... when the system has none, as python-control)."""
        ins, _ = self._core.signal_names
        return list(ins) if ins else ["u[%d]" % i for i in range(self.ninputs)]

    @property
    def output_labels(self):
        """The output names (``y[0]``, ... when the system has none)."""
        _, outs = self._core.signal_names
        return list(outs) if outs else ["y[%d]" % i for i in range(self.noutputs)]

    def _from_report(self, r, dt):
        from ._system import ss

        ins, outs = self._core.signal_names
        return ss(r["A"], r["B"], r["C"], r["D"], dt=dt, inputs=ins, outputs=outs)

    def c2d(self, dt, method="tustin", max_seconds=None):
        """python-control's ``c2d``: ``"tustin"`` exact (bilinear map, checked by
        ``d2c(c2d(G)) == G``), ``"zoh"`` by the float matrix exponential (the entries are
        the binary floats, exactly)."""
        dt = Fraction(str(dt)) if isinstance(dt, float) else Fraction(dt)
        r = self.run("c2d", "--dt", str(dt), "--method", method, max_seconds=max_seconds)
        return self._from_report(r, dt)

    def d2c(self, max_seconds=None):
        """The continuous system whose Tustin discretization is this one (exact)."""
        r = self.run("d2c", max_seconds=max_seconds)
        return self._from_report(r, None)

    def is_stable(self, max_seconds=None):
        """Exact asymptotic stability over Q (``|z| < 1`` for a discrete-time system,
        ``Re s < 0`` otherwise), decided without floats (Schur-Cohn / Jury)."""
        r = self.run("stability", max_seconds=max_seconds)
        return r["asymptotically_stable"]

    def with_signals(self, inputs=None, outputs=None, dt=None):
        """The same system with input/output names and a sample time (``dt``: a number,
        exact; ``0`` or ``None``: continuous)."""
        from ._system import StateSpace

        t = None if dt is None else str(Fraction(str(dt)) if isinstance(dt, float) else Fraction(dt))
        ins, outs = self._core.signal_names
        return StateSpace(
            self._core.with_signals(
                list(inputs) if inputs is not None else ins,
                list(outputs) if outputs is not None else outs,
                t,
            )
        )


def interconnect(syslist, connections=(), inplist=(), outlist=(), max_seconds=None):
    """python-control's ``interconnect`` by signal names, exact: the systems side by side;
    each connection ``[input, output, "-output", ...]`` feeds the sum of the named outputs
    (a leading ``-`` subtracts) into every subsystem input of that name; ``inplist`` names
    the external inputs (each drives the subsystem inputs of its name), ``outlist`` the
    external outputs. Unknown or repeated names raise ``ValueError`` naming them.

    >>> import exactlti
    >>> P = exactlti.ss([[-1]], [[1]], [[1]], [[0]], inputs=["u"], outputs=["y"])
    >>> C = exactlti.ss([[0]], [[1]], [[2]], [[3]], inputs=["e"], outputs=["u"])
    >>> T = exactlti.interconnect([P, C], [["u", "u"], ["e", "-y"]], inplist=["e"], outlist=["y"])
    >>> T.input_labels, T.output_labels, T.nstates
    (['e'], ['y'], 2)
    >>> T.dcgain()["dc_gain"]  # (2/s + 3)/(s + 1) closed by -1: 1 at s = 0
    [['1']]
    """
    from ._system import StateSpace

    conns = [[str(x) for x in c] for c in connections]
    core = _core.connect_names(
        [s._core for s in syslist], conns, [str(x) for x in inplist],
        [str(x) for x in outlist], max_seconds,
    )
    return StateSpace(core)
