"""exactlti: exact structure of linear time-invariant systems, in python-control's idiom.

Quick start::

    import exactlti
    G = exactlti.ss([[0, 1], ["-0.08", "-1/3"]], [[0], [1]], [[1, 0]], [[0]])
    G.minreal(), G.poles(), G.jordan().J.to_sympy()

Everything is exact (``"0.08"`` is 2/25; eigenvalues are algebraic numbers); every exact
result carries ``verified``. Approximations come from ``to_numpy()`` / ``approx()``.
"""

from ._core import UnsupportedError, VerificationError
from ._convert import ExactnessWarning
from ._exact import AlgebraicNumber, Matrix, Polynomial, RationalFunction
from ._system import (
    CheckResult,
    JordanResult,
    MinrealResult,
    MnfResult,
    ModalTable,
    Roots,
    ScbResult,
    StateSpace,
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
    "StateSpace",
    "Matrix",
    "AlgebraicNumber",
    "Polynomial",
    "RationalFunction",
    "JordanResult",
    "MinrealResult",
    "ScbResult",
    "MnfResult",
    "ModalTable",
    "Roots",
    "TransferMatrix",
    "CheckResult",
    "ExactnessWarning",
    "UnsupportedError",
    "VerificationError",
]
