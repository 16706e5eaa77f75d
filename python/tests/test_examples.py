"""The example script reproducing the papers runs and asserts its numbers."""

import os
import runpy

import pytest

EXAMPLE = os.path.join(os.path.dirname(__file__), "..", "examples", "papers.py")


def test_papers_example_runs(capsys):
    pytest.importorskip("sympy")
    runpy.run_path(EXAMPLE, run_name="__main__")
    out = capsys.readouterr().out
    assert "20 -> 16 -> 8" in out
    assert "-16003/27" in out
    assert "DC motor over QQ(" in out
