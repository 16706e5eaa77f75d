"""Runs the paper notebooks (``*.ipynb`` here) the way Jupyter would, without Jupyter:
every code cell in order in one namespace, the value of a cell's last expression shown
through its ``_repr_html_`` / ``_repr_latex_`` (made by the library's report layer).
Fails (exit 1, the cell and the traceback printed) on the first error or failed
``assert``, or when a displayed exactlti result has no HTML or LaTeX rendering.

    python run.py                 # execute every notebook (CI: python/ci.sh)
    python run.py --write         # ... and store the outputs in the notebooks
    python run.py NAME.ipynb ...  # only these

Run it with the working directory anywhere: each notebook runs in its own directory.
"""

import ast
import json
import os
import sys
import time
import traceback

HERE = os.path.dirname(os.path.abspath(__file__))


def _display(value):
    """Jupyter's output bundle of a value (text/plain always; HTML and LaTeX when the
    value renders itself)."""
    data = {"text/plain": repr(value)}
    for mime, name in (("text/html", "_repr_html_"), ("text/latex", "_repr_latex_")):
        f = getattr(value, name, None)
        if f is None:
            continue
        out = f()
        if type(value).__module__.startswith("exactlti") and not isinstance(out, str):
            raise AssertionError("%s.%s() gave no rendering" % (type(value).__name__, name))
        if isinstance(out, str):
            data[mime] = out
    if type(value).__module__.startswith("exactlti") and "text/html" not in data:
        raise AssertionError("%s has no HTML rendering" % type(value).__name__)
    return data


def run_cell(source, ns, name):
    """Executes one cell; returns the display bundle of its last expression (or None)."""
    tree = ast.parse(source, filename=name)
    last = None
    if tree.body and isinstance(tree.body[-1], ast.Expr):
        last = ast.Expression(tree.body.pop().value)
    exec(compile(tree, name, "exec"), ns)
    if last is None:
        return None
    value = eval(compile(last, name, "eval"), ns)
    return None if value is None else _display(value)


def run_notebook(path, write):
    nb = json.load(open(path))
    ns = {"__name__": "__main__"}
    cwd = os.getcwd()
    os.chdir(os.path.dirname(os.path.abspath(path)))
    count = 0
    try:
        for i, cell in enumerate(nb["cells"]):
            if cell["cell_type"] != "code":
                continue
            count += 1
            source = "".join(cell["source"])
            try:
                bundle = run_cell(source, ns, "%s[cell %d]" % (os.path.basename(path), i))
            except Exception:
                print("FAILED: %s, cell %d:\n%s" % (path, i, source), file=sys.stderr)
                traceback.print_exc()
                return False
            cell["execution_count"] = count
            cell["outputs"] = []
            if bundle is not None:
                cell["outputs"] = [{
                    "output_type": "execute_result",
                    "execution_count": count,
                    "metadata": {},
                    "data": {k: v.splitlines(keepends=True) for k, v in bundle.items()},
                }]
    finally:
        os.chdir(cwd)
    if write:
        with open(path, "w") as f:
            json.dump(nb, f, indent=1, ensure_ascii=False)
            f.write("\n")
    return True


def main(argv):
    write = "--write" in argv
    names = [a for a in argv if not a.startswith("--")]
    paths = [os.path.join(HERE, n) for n in names] or sorted(
        os.path.join(HERE, n) for n in os.listdir(HERE) if n.endswith(".ipynb")
    )
    ok = True
    for p in paths:
        t = time.time()
        good = run_notebook(p, write)
        print("%s: %s in %.1f s" % (os.path.basename(p), "ok" if good else "FAILED", time.time() - t))
        ok = ok and good
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
