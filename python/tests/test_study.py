"""Parameter studies (issue 22 items 3, 4, 8): a parameter the file lacks is refused, a
singular E gives the finite eigenvalues of the pencil, coincident pairs are certified."""

import json
import os
import random
import tempfile

import pytest

import exactlti


def _write(doc, name):
    p = os.path.join(tempfile.mkdtemp(), name)
    with open(p, "w") as f:
        json.dump(doc, f)
    return p


@pytest.mark.parametrize("seed", range(8))
def test_a_parameter_the_file_lacks_raises_naming_the_ones_it_has(seed):
    rnd = random.Random(seed)
    names = rnd.sample(["a", "b", "m", "k", "zeta"], rnd.randint(0, 3))
    params = {n: rnd.randint(1, 9) for n in names}
    entry = names[0] if names else "1"
    p = _write({"parameters": params, "A": [[entry, 1], [-2, -3]]}, "f.json")
    for call in (
        lambda: exactlti.sweep(p, "v", [0.0, 1.0]),
        lambda: exactlti.critical(p, "v", 0, 1),
    ):
        with pytest.raises(ValueError) as e:
            call()
        msg = str(e.value)
        assert "key parameters" in msg and "'v'" in msg and p in msg
        for n in names:
            assert " " + n in msg
        if not names:
            assert "no parameters" in msg


def test_singular_e_sweep_gives_finite_eigenvalues_and_notes():
    # E = diag(1, 1, 0), A: x3 = x2, so s^2 + 2 s + v; a pole at v = 1/2 (row 3 scaled)
    doc = {
        "parameters": {"v": 1},
        "E": [[1, 0, 0], [0, 1, 0], [0, 0, 0]],
        "A": [[0, 1, 0], ["-v", -3, 1], [0, "1/(2*v - 1)", "-1/(2*v - 1)"]],
    }
    r = exactlti.sweep(_write(doc, "e.json"), "v", [0.0, 0.5, 1.0])
    assert r["status"] == ["descriptor", "pole", "descriptor"]
    assert r["infinite_eigenvalues"] == [1, 0, 1]
    assert r["eigenvalues"][1] == []
    ev = sorted(z.real for z in r["eigenvalues"][0])
    assert abs(ev[0] + 2) < 1e-12 and abs(ev[1]) < 1e-12


def test_coincident_imaginary_and_real_pairs_are_certified():
    # M q'' + v L1 q' + K q: at v = 0 the pairs +-1.0589 and +-1.7667i
    doc = {
        "parameters": {"v": 1},
        "M": [[1, 0], [0, 2]],
        "L": [["v", "2*v"], ["-v", "v"]],
        "K": [[3, 1], [1, -2]],
    }
    r = exactlti.critical(_write(doc, "m.json"), "v", 0, 2)
    assert r["verified"]
    first = r["critical_values"][0]
    assert (first["value"], first["kind"], first["certified"]) == ("0", "imaginary_pair", True)
    assert abs(first["omega"] - 1.7667258824049763) < 1e-9
