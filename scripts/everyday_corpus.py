#!/usr/bin/env python3
"""Writes the everyday-models corpus (issue 11) to tests/data/everyday/*.json.

Deterministic (SplitMix64 with fixed seeds); re-running rewrites the same files. The Rust
tests, benches/everyday.rs and scripts/anchors/everyday.py all read these files.
"""
import json
import os

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
OUT = os.path.join(ROOT, "tests", "data", "everyday")
M64 = (1 << 64) - 1


class Rng:
    def __init__(self, seed):
        self.s = seed & M64

    def next(self):
        self.s = (self.s + 0x9E3779B97F4A7C15) & M64
        z = self.s
        z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & M64
        z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & M64
        return z ^ (z >> 31)

    def int(self, lo, hi):
        return lo + self.next() % (hi - lo + 1)


def write(name, obj):
    with open(os.path.join(OUT, name + ".json"), "w") as f:
        json.dump(obj, f, indent=None)
        f.write("\n")


def chain(masses, springs, dashpots):
    """Fixed-free chain: spring/dashpot i joins mass i-1 (ground for i = 0) and mass i."""
    n = len(masses)
    K = [["0"] * n for _ in range(n)]
    L = [["0"] * n for _ in range(n)]
    for i in range(n):
        for (mat, v) in ((K, springs[i]), (L, dashpots[i])):
            mat[i][i] = v if mat[i][i] == "0" else f"{mat[i][i]} + {v}"
            if i > 0:
                mat[i - 1][i - 1] = f"{mat[i - 1][i - 1]} + {v}" if mat[i - 1][i - 1] != "0" else v
                mat[i - 1][i] = f"-{v}"
                mat[i][i - 1] = f"-{v}"
    M = [[masses[i] if i == j else "0" for j in range(n)] for i in range(n)]
    return M, L, K


def main():
    os.makedirs(OUT, exist_ok=True)
    # quarter car: body zs, wheel zu; road input zr through the tyre; output body position
    write("quarter_car", {
        "name": "quarter car (ms 250 kg, mu 40 kg, ks 16000 N/m, cs 1000 Ns/m, kt 190000 N/m); input road height, output body height",
        "parameters": {"ms": "250", "mu": "40", "ks": "16000", "cs": "1000", "kt": "190000"},
        "M": [["ms", "0"], ["0", "mu"]],
        "L": [["cs", "-cs"], ["-cs", "cs"]],
        "K": [["ks", "-ks"], ["-ks", "ks + kt"]],
        "F": [["0"], ["kt"]],
        "C": [["1", "0", "0", "0"]],
    })
    # 3-mass damped chain (fixed-free), exact decimals
    M, L, K = chain(["1", "1.5", "2"], ["100", "80", "60"], ["0.8", "0.6", "0.4"])
    write("damped_chain_3", {
        "name": "3-mass damped chain, fixed-free (m 1, 1.5, 2; k 100, 80, 60; c 0.8, 0.6, 0.4); force on mass 1, output mass 3",
        "M": M, "L": L, "K": K,
        "F": [["1"], ["0"], ["0"]],
        "C": [["0", "0", "1", "0", "0", "0"]],
    })
    # 5-mass damped chain, MIMO
    M, L, K = chain(["1"] * 5, ["2", "3", "2", "3", "2"], ["0.1", "0.2", "0.1", "0.2", "0.1"])
    write("damped_chain_5_mimo", {
        "name": "5-mass damped chain, fixed-free, forces on masses 1 and 5, outputs masses 2 and 4",
        "M": M, "L": L, "K": K,
        "F": [["1", "0"], ["0", "0"], ["0", "0"], ["0", "0"], ["0", "1"]],
        "C": [["0", "1", "0", "0", "0"] + ["0"] * 5, ["0", "0", "0", "1", "0"] + ["0"] * 5],
    })
    # sliding masses with a dashpot (c = 0.1) beside every spring: L = K / 10
    with open(os.path.join(ROOT, "data", "sliding-masses.json")) as f:
        sm = json.load(f)
    sm["name"] = ("10-DOF sliding masses with a dashpot (c = 0.1) beside every spring: "
                  "L = K/10; actuator pushes sliders 4 and 7 apart; output x9 - x2")
    sm["L"] = [[("0" if v == 0 else f"{v}/10") for v in row] for row in sm["K"]]
    write("sliding_masses_damped", sm)
    # dense random integer systems, entries -9..9
    for n, m, p, seed in [(8, 1, 1, 8), (8, 2, 2, 82), (12, 1, 1, 12), (12, 2, 2, 122),
                          (16, 1, 1, 16), (16, 2, 2, 162), (6, 1, 1, 6)]:
        rng = Rng(seed)
        mat = lambda r, c: [[rng.int(-9, 9) for _ in range(c)] for _ in range(r)]
        A, B, C = mat(n, n), mat(n, m), mat(p, n)
        kind = "siso" if m == 1 and p == 1 else "mimo"
        write(f"random_{n}_{kind}", {
            "name": f"dense random integer system n = {n}, {m} in, {p} out, entries -9..9 (SplitMix64 seed {seed})",
            "A": A, "B": B, "C": C,
        })


if __name__ == "__main__":
    main()
