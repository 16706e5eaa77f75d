"""The control engineer's toolbox as methods of :class:`StateSpace` (python-control's
names): ``margin``, ``stability_margins``, ``step_info``, ``damp``, ``gram``, ``dcgain``,
and ``print(G)`` showing the matrices. Each runs the command line's operation through the
library's front door (the same code and answers as ``exactlti margin FILE`` ...)."""

import math

from ._api import run


def _num(x):
    """A report value as a float (``"inf"`` is infinity, ``None`` is NaN)."""
    if x is None:
        return math.nan
    if x == "inf":
        return math.inf
    return float(x)


class ControlOps:
    """Mixin of :class:`StateSpace`: python-control's toolbox functions, exact where exact."""

    def stability_margins(self, max_seconds=None):
        """Gain and phase margins of a SISO loop over Q (the command line's ``margin``): a
        :class:`Report` with the exact crossover frequencies (algebraic numbers:
        ``phase_crossover_frequency``, ``..._minpoly``, ``..._decimal``), the exact gain
        margin, ``phase_margin_deg`` and the exact ``phase_margin_cos``, every crossing, and
        ``verified``; ``"inf"`` where there is no crossover."""
        return run(self, "margin", max_seconds=max_seconds)

    def margin(self, max_seconds=None):
        """``(gm, pm, wcg, wcp)`` as python-control's ``margin``: gain margin, phase margin
        in degrees, and the phase and gain crossover frequencies in rad/s, as floats
        (``inf`` / ``nan`` when there is no crossover). The exact values:
        :meth:`stability_margins`."""
        r = self.stability_margins(max_seconds=max_seconds)
        gm = r.get("gain_margin_approx", r["gain_margin"])
        return (
            _num(gm),
            _num(r["phase_margin_deg"]),
            _num(r.get("phase_crossover_frequency_approx")),
            _num(r.get("gain_crossover_frequency_approx")),
        )

    def step_info(self, to=None, points=None, max_seconds=None):
        """python-control's ``step_info`` on the float step response (final value: the exact
        DC gain; a channel with a pole outside the open left half-plane has none): a list
        of rows (outputs) of dicts (inputs) with ``RiseTime``, ``SettlingTime``, ``Overshoot``,
        ``Undershoot``, ``Peak``, ``PeakTime``, ``SteadyStateValue`` (or ``reason``). For a
        SISO system the one dict."""
        a = []
        if to is not None:
            a += ["--to", to]
        if points is not None:
            a += ["--points", points]
        r = run(self, "stepinfo", *a, max_seconds=max_seconds)
        chans = r["channels"]
        rows = [chans[i * self.ninputs:(i + 1) * self.ninputs] for i in range(self.noutputs)]
        if self.ninputs == 1 and self.noutputs == 1:
            return rows[0][0]
        return rows

    def damp(self, max_seconds=None):
        """The damping table: a :class:`Report` whose ``poles`` list gives per pole
        ``natural_frequency_rad_s``, ``natural_frequency_hz``, ``damping_ratio``,
        ``time_constant_s`` and the exact ``wn_squared``, ``two_zeta_wn`` where rational."""
        return run(self, "damp", max_seconds=max_seconds)

    def gram(self, type="c", max_seconds=None):
        """The controllability (``"c"``) or observability (``"o"``) Gramian of a stable
        system by an exact Lyapunov solve over its field (Q, Q(sqrt d), Q(i)): a
        :class:`Report` with ``W`` (exact strings; ``to_sympy("W")``,
        ``to_numpy("W")``) and ``verified``."""
        if type not in ("c", "o"):
            raise ValueError("gram: type must be 'c' or 'o' (got %r)" % (type,))
        return run(self, "gram", "--type", type, max_seconds=max_seconds)

    def dcgain(self, max_seconds=None):
        """The exact DC gain ``G(0) = D - C A^-1 B`` per channel (``"inf"`` at a pole at 0):
        a :class:`Report` with ``dc_gain``."""
        return run(self, "dcgain", max_seconds=max_seconds)

    def __str__(self):
        """The matrices, as python-control prints a system."""
        parts = ["%s over %s: %d states, %d inputs, %d outputs" % (
            type(self).__name__, self.field, self.nstates, self.ninputs, self.noutputs)]
        for name in ("A", "B", "C", "D"):
            m = getattr(self, name)
            body = str(m).replace("\n", "\n    ")
            parts.append("%s = %s" % (name, body))
        return "\n\n".join(parts)
