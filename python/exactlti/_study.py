"""Parameter studies of a system file: ``sweep`` and ``critical`` (the command line's
``exactlti sweep`` and ``exactlti critical``). The file is read by the library's one loader
(the api's ``System``), as for every other method: over Q, Q(sqrt d) and Q(i) alike."""

import json

from . import _core
from ._api import Report


def sweep(path, param, values):
    """Eigenvalues of the file's system at each value of the parameter ``param``.

    Where ``E(v)`` (or ``M(v)``) is singular the list holds the finite eigenvalues of the
    pencil (``det(sE - A) = 0``; their number exact) and ``infinite_eigenvalues`` counts the
    others; at a pole or a singular pencil the list is empty and ``status`` says why. A
    parameter the file does not name raises ``ValueError`` naming the ones it has.

    >>> import exactlti, json, os, tempfile
    >>> p = os.path.join(tempfile.mkdtemp(), "v.json")
    >>> _ = open(p, "w").write(json.dumps({"parameters": {"v": 1}, "A": [["-v", 1], [0, -2]]}))
    >>> r = exactlti.sweep(p, "v", [1.0, 3.0])
    >>> r["eigenvalues"][0], r["status"]
    ([(-2+0j), (-1+0j)], ['regular', 'regular'])
    """
    r = _core.sweep(str(path), str(param), [float(v) for v in values])
    r["eigenvalues"] = [[complex(re, im) for re, im in ev] for ev in r["eigenvalues"]]
    return r


def critical(path, param, lo, hi, max_seconds=None):
    """Exact critical values of the parameter ``param`` on ``[lo, hi]`` (bounds exact:
    ints, ``Fraction`` or text such as ``"1/3"``): zero eigenvalues, imaginary pairs,
    double eigenvalues, each ``certified``; the intervals between them with stability; the
    points where the family is undefined (``singular_values`` with a ``reason``). The
    command line's report (a :class:`Report`; ``omega`` is ``None`` where no pair crosses).

    >>> import exactlti, json, os, tempfile
    >>> p = os.path.join(tempfile.mkdtemp(), "c.json")
    >>> _ = open(p, "w").write(json.dumps({"parameters": {"c": 1}, "M": [[1]], "L": [["c"]], "K": [[1]]}))
    >>> r = exactlti.critical(p, "c", -1, 3)
    >>> [(x["value"], x["kind"]) for x in r["critical_values"]], r["verified"]
    ([('0', 'imaginary_pair'), ('2', 'double_eigenvalue')], True)
    """
    argv = ["critical", str(path), "--param", str(param), "--from", str(lo), "--to", str(hi)]
    text, verified, agree = _core.execute(argv, max_seconds)
    r = Report(json.loads(text), verified, agree, op=" ".join(argv[:1] + argv[2:]))
    for c in r["critical_values"]:
        c.setdefault("omega", None)
    return r
