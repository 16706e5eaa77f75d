"""The exception type of a failed command follows the class of its error (issue 23), as the
command line's exit status does: an unsupported case raises ``UnsupportedError`` (a
``NotImplementedError``), a size bound of the library ``TimeoutError``, bad input
``ValueError`` -- also when the failure comes from a command of the front door
(``exactlti::api``), not only from the library's own errors."""

import json
import os
import tempfile

import pytest

import exactlti


def _file(name, data):
    p = os.path.join(tempfile.mkdtemp(), name)
    with open(p, "w") as f:
        json.dump(data, f)
    return p


def _diag(n, d):
    return [[d if i == j else 0 for j in range(n)] for i in range(n)]


def test_unsupported_command_raises_unsupported_error():
    # the real Jordan form of a symbolic system whose chi_A = x^3 - k is irreducible over Q(k):
    # its roots are not a +- i w with a, w^2 in Q(k), refused by the front door (not bad input)
    p = _file("k.json", {"symbols": ["k"], "A": [[0, 1, 0], [0, 0, 1], ["k", 0, 0]],
                         "B": [[0], [0], [1]], "C": [[1, 0, 0]], "D": [[0]]})
    G = exactlti.load(p)
    with pytest.raises(exactlti.UnsupportedError, match="degree 3") as e:
        G.run("jordan", "--real")
    assert isinstance(e.value, NotImplementedError)
    assert not isinstance(e.value, ValueError)


@pytest.mark.parametrize("n, points, over", [(4, 100000, True), (4, 1000, False), (1, 2000, False)])
def test_a_size_bound_raises_timeout_error(n, points, over):
    G = exactlti.ss(_diag(n, -1), _diag(n, 1), _diag(n, 1), _diag(n, 0))
    if over:
        with pytest.raises(TimeoutError, match="at most 1000000"):
            G.run("freqresp", "--points", points)
    else:
        assert G.run("freqresp", "--points", points) is not None


def test_bad_input_stays_a_value_error():
    G = exactlti.ss([[-1]], [[1]], [[1]], [[0]])
    with pytest.raises(ValueError):
        G.run("freqresp", "--points", 1)
