"""exactlti: exact structure of linear time-invariant systems, in python-control's idiom.

Quick start::

    import exactlti
    G = exactlti.ss([[0, 1], ["-0.08", "-1/3"]], [[0], [1]], [[1, 0]], [[0]])
    G.minreal(), G.poles(), G.jordan().J.to_sympy()

Everything is exact (``"0.08"`` is 2/25; eigenvalues are algebraic numbers); every exact
result carries ``verified``. Approximations come from ``to_numpy()`` / ``approx()``.
Transfer functions: ``exactlti.tf([1, 1], [1, 3, 2])`` or ``exactlti.tf("(s+1)/(s^2+3s+2)")``.
Symbolic parameters: ``exactlti.ss([[0, 1], ["-k/m", "-c/m"]], ..., params={"m": None, ...})``
or SymPy symbols; results then carry ``conditions`` (polynomials assumed nonzero).
"""

from ._core import UnsupportedError, VerificationError
from ._convert import ExactnessWarning
from ._exact import AlgebraicNumber, Conditions, Matrix, Polynomial, RationalFunction
from ._api import Report
from ._steps import Derivation, Step, steps
from ._study import critical, sweep
from ._ops import feedback, interconnect, parallel, series
from ._system import (
    CheckResult,
    Factor,
    Factorization,
    JordanResult,
    MinrealResult,
    MinrealSystem,
    MnfResult,
    ModalTable,
    Roots,
    ScbResult,
    StateSpace,
    SymbolicEigenvalue,
    SymbolicJordanResult,
    TransferMatrix,
    from_control,
    jordan,
    load,
    ss,
    tf,
)

__version__ = "0.1.0"

__all__ = [
    "ss",
    "tf",
    "jordan",
    "load",
    "from_control",
    "sweep",
    "critical",
    "StateSpace",
    "Report",
    "steps",
    "Derivation",
    "Step",
    "Matrix",
    "AlgebraicNumber",
    "Polynomial",
    "RationalFunction",
    "JordanResult",
    "MinrealResult",
    "MinrealSystem",
    "series",
    "parallel",
    "feedback",
    "interconnect",
    "ScbResult",
    "MnfResult",
    "ModalTable",
    "Roots",
    "TransferMatrix",
    "CheckResult",
    "Conditions",
    "Factor",
    "Factorization",
    "SymbolicEigenvalue",
    "SymbolicJordanResult",
    "ExactnessWarning",
    "UnsupportedError",
    "VerificationError",
]
