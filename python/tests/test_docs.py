"""The docstring examples are run (doctest) so they stay true."""

import doctest

import pytest

import exactlti
from exactlti import _convert, _exact, _study, _system

pytest.importorskip("sympy")
pytest.importorskip("numpy")


@pytest.mark.parametrize("module", [exactlti, _exact, _system, _convert, _study])
def test_docstring_examples(module):
    flags = doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE
    res = doctest.testmod(module, optionflags=flags, verbose=False)
    assert res.failed == 0
