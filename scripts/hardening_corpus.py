#!/usr/bin/env python3
"""Writes the slow-exact-path corpus (issue 17 item 1) to tests/data/hardening/*.json.

Deterministic (SplitMix64, fixed seeds); re-running rewrites the same files. Read by
benches/hardening.rs and tests/hardening.rs. Every case has a planted answer:
- nilpotent_20: Jordan blocks 5,4,4,3,2,1,1 at 0 scrambled by a unimodular integer T;
- planted_N: integer eigenvalues -1..-4 in blocks (sizes 1..3), dense integer T (entries
  -9..9), random B, C; `zeros` and `scb` on n = 12..20;
- bigq_N: the complex pair roots of x^2 + 1 and x^2 + 2x + 5 plus rational eigenvalues, in
  blocks, scrambled by a dense rational T with 20-30 digit entries (complex `jordan`);
- rosen_N: planted uncontrollable/unobservable parts (n = 30, 40) with 20-digit entries;
- dense_7: dense 7x7 integer system (entries -9..9), SISO (Jordan-method `minreal`).
"""
import json
import os
from fractions import Fraction

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
OUT = os.path.join(ROOT, "tests", "data", "hardening")
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

    def digits(self, d):
        v = 0
        for _ in range(d):
            v = v * 10 + self.int(0, 9)
        return max(v, 1)


def s(x):
    return str(Fraction(x))


def mat(rows):
    return [[s(x) for x in r] for r in rows]


def mul(a, b):
    n, k, m = len(a), len(b), len(b[0])
    return [[sum(a[i][t] * b[t][j] for t in range(k)) for j in range(m)] for i in range(n)]


def inverse(a):
    n = len(a)
    m = [[Fraction(x) for x in r] + [Fraction(int(i == j)) for j in range(n)] for i, r in enumerate(a)]
    for c in range(n):
        p = next(r for r in range(c, n) if m[r][c] != 0)
        m[c], m[p] = m[p], m[c]
        pv = m[c][c]
        m[c] = [x / pv for x in m[c]]
        for r in range(n):
            if r != c and m[r][c] != 0:
                f = m[r][c]
                m[r] = [x - f * y for x, y in zip(m[r], m[c])]
    return [r[n:] for r in m]


def jordan_matrix(blocks):
    """blocks: list of (companion or scalar block as square list, size k): block-diag of
    C (x) I + N (x) I-chain, i.e. the block Jordan matrix of an eigenvalue block."""
    n = sum(len(b) * k for b, k in blocks)
    j = [[0] * n for _ in range(n)]
    o = 0
    for b, k in blocks:
        d = len(b)
        for t in range(k):
            for r in range(d):
                for c in range(d):
                    j[o + t * d + r][o + t * d + c] = b[r][c]
            if t + 1 < k:
                for r in range(d):
                    j[o + t * d + r][o + (t + 1) * d + r] = 1
        o += d * k
    return j


def unimodular(rng, n, steps):
    t = [[int(i == j) for j in range(n)] for i in range(n)]
    for _ in range(steps):
        i, j = rng.int(0, n - 1), rng.int(0, n - 1)
        if i == j:
            continue
        f = rng.int(-2, 2)
        t[i] = [x + f * y for x, y in zip(t[i], t[j])]
    return t


def dense_int(rng, n, m, lo=-9, hi=9):
    return [[rng.int(lo, hi) for _ in range(m)] for _ in range(n)]


def write(name, obj):
    with open(os.path.join(OUT, name + ".json"), "w") as f:
        json.dump(obj, f, indent=None)
        f.write("\n")


def system(name, a, b, c):
    return {"name": name, "A": mat(a), "B": mat(b), "C": mat(c)}


def main():
    os.makedirs(OUT, exist_ok=True)
    # 1. nilpotent 20x20 scrambled by a unimodular integer similarity
    rng = Rng(1701)
    j = jordan_matrix([([[0]], k) for k in (5, 4, 4, 3, 2, 1, 1)])
    t = unimodular(rng, 20, 60)
    a = mul(mul(t, j), inverse(t))
    write("nilpotent_20", system("nilpotent 20x20 (blocks 5,4,4,3,2,1,1) scrambled by a unimodular integer T",
                                 a, dense_int(rng, 20, 1, -3, 3), dense_int(rng, 1, 20, -3, 3)))
    # 2. planted integer structures, dense integer T, for zeros/scb on n = 12..20
    for n in (12, 16, 20):
        rng = Rng(4200 + n)
        blocks, size = [], 0
        while size < n:
            k = min(rng.int(1, 3), n - size)
            blocks.append(([[-rng.int(1, 4)]], k))
            size += k
        j = jordan_matrix(blocks)
        while True:
            t = dense_int(rng, n, n)
            try:
                ti = inverse(t)
                break
            except StopIteration:
                continue
        a = mul(mul(t, j), ti)
        write(f"planted_{n}", system(f"planted integer Jordan structure n = {n}, dense integer T (-9..9)",
                                     a, dense_int(rng, n, 2, -3, 3), dense_int(rng, 2, n, -3, 3)))
    # 3. complex pairs and rational eigenvalues under a dense 20-30 digit rational T
    for n in (18, 36):
        rng = Rng(9000 + n)
        pool = [([[0, -1], [1, 0]], 1), ([[0, -5], [1, -2]], 2), ([[-3]], 2), ([[2]], 1), ([[0, -1], [1, 0]], 2)]
        blocks, size, i = [], 0, 0
        while size < n:
            b, k = pool[i % len(pool)]
            if size + len(b) * k > n:
                b, k = [[-1]], n - size
            blocks.append((b, k))
            size += len(b) * k
            i += 1
        j = jordan_matrix(blocks)
        # T = U diag(d): U unimodular (dense after 4n steps), d_i rationals of 20-30 digits,
        # so T is dense with big entries while the file stays small (A = U (D J D^-1) U^-1)
        u = unimodular(rng, n, 2 * n)
        d = [Fraction(rng.digits(rng.int(20, 30)) * (1 if rng.int(0, 1) else -1), rng.digits(rng.int(1, 5)))
             for _ in range(n)]
        t = [[u[i][k] * d[k] for k in range(n)] for i in range(n)]
        ti = inverse(t)
        a = mul(mul(t, j), ti)
        write(f"bigq_{n}", system(f"planted complex Jordan structure n = {n}, rational T with 20-30 digit entries",
                                  a, dense_int(rng, n, 1, -3, 3), dense_int(rng, 1, n, -3, 3)))
    # 4. Rosenbrock: a minimal part of order n/2 plus uncontrollable and unobservable states,
    #    block-triangular (Kalman form), then scrambled by a unimodular T times a 20-digit scale
    for n in (30, 40):
        rng = Rng(3000 + n)
        r = n // 2
        a = [[0] * n for _ in range(n)]
        blk = [0 if i < r else 1 if i < 3 * n // 4 else 2 for i in range(n)]
        # co (0..r), c-not-o (r..3n/4), not-c (3n/4..n): not-c rows see only not-c states,
        # co rows see co and not-c states (the c-not-o states stay invisible), B is zero on
        # the not-c rows and C zero on the c-not-o columns: minimal order r = n/2
        for i in range(n):
            for k in range(n):
                if (blk[i] == 2 and blk[k] == 2) or (blk[i] == 0 and blk[k] != 1) or blk[i] == 1:
                    a[i][k] = rng.int(-5, 5)
        b = [[rng.int(-3, 3) if blk[i] != 2 else 0] for i in range(n)]
        c = [[rng.int(-3, 3) if blk[k] != 1 else 0 for k in range(n)]]
        big = 10**20 + 39
        t = unimodular(rng, n, 3 * n)
        t = [[x * big if i == 0 else x for x in row] for i, row in enumerate(t)]
        ti = inverse(t)
        write(f"rosen_{n}", system(f"Rosenbrock case n = {n}: Kalman-structured, scrambled by a T with 20-digit entries",
                                   mul(mul(ti, a), t), mul(ti, b), mul(c, t)))
    # 5. dense 7x7 integer SISO
    rng = Rng(77)
    write("dense_7", system("dense 7x7 integer system (entries -9..9), SISO",
                            dense_int(rng, 7, 7), dense_int(rng, 7, 1), dense_int(rng, 1, 7)))


if __name__ == "__main__":
    main()
