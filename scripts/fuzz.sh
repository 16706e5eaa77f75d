#!/usr/bin/env bash
# Longer mutation-fuzz run through the CLI binary (issue 17, item 7).
#   scripts/fuzz.sh [CASES] [SEED]      (EXACTLTI_BIN=path: use that binary, no build)
# Mutants of data/*.json and tests/data/* are written to target/fuzz/, every command runs on
# each with --max-seconds 10; a run fails on a panic (exit 101/134 or "panicked"), on a
# process still alive past the bound (each run under `ulimit -v` 4 GB), on exit 1 (internal failure), or on a multi-line error.
# Failing mutants are kept in target/fuzz/failures/ (add them to tests/data with a test).
set -u
cases=${1:-300}
seed=${2:-1}
cd "$(dirname "$0")/.."
# EXACTLTI_BIN=path runs an already built binary (no build)
if [ -n "${EXACTLTI_BIN:-}" ]; then
  bin=$EXACTLTI_BIN
else
  cargo build --release --quiet || exit 1
  bin=target/release/exactlti
fi
out=target/fuzz
mkdir -p "$out/failures"
python3 - "$cases" "$seed" "$out" <<'PY'
import glob, os, random, re, sys
cases, seed, out = int(sys.argv[1]), int(sys.argv[2]), sys.argv[3]
rng = random.Random(seed)
corpus = sorted(glob.glob("data/*.json") + glob.glob("tests/data/*.json") + glob.glob("tests/data/*.toml"))
nums = ["0", "-1", "1e300", "-1e-300", "1/3", '"1/0"', "123456789012345678901234567890", '"i"', '"sqrt(2)"', "null", "[]", "[[]]"]
for k in range(cases):
    src = rng.choice(corpus)
    t = open(src).read()
    for _ in range(rng.randint(1, 2)):
        op = rng.randrange(4)
        toks = [m.span() for m in re.finditer(r'"[^"]*"|[-\w./+]+', t)]
        if op == 0 and t:
            i = rng.randrange(len(t)); t = t[:i] + rng.choice('0123456789-+./*^()[]{},:"ei ') + t[i + 1:]
        elif op == 1 and toks:
            s, e = rng.choice(toks); t = t[:s] + rng.choice(nums) + t[e:]
        elif op == 2 and len(toks) > 1:
            (a, b), (c, d) = sorted(rng.sample(toks, 2))
            if b <= c: t = t[:a] + t[c:d] + t[b:c] + t[a:b] + t[d:]
        elif op == 3:
            rows = [m.span() for m in re.finditer(r'\[[^\[\]]*\]', t)]
            if rows:
                s, e = rng.choice(rows); t = t[:s] + t[s:e] + ", " + t[s:e] + t[e:]
    ext = os.path.splitext(src)[1]
    open(f"{out}/case{k}{ext}", "w").write(t)
PY
cmds=("jordan" "jordan --real" "minreal" "minreal --method rosenbrock" "minreal --method ho-kalman"
      "minreal --method jordan" "minreal --method era" "standard" "scb" "mnf" "zeros" "modes"
      "freqresp --points 20" "check" "analyze" "linalg det" "linalg rank" "linalg charpoly"
      "linalg minpoly" "linalg inverse" "linalg nullspace" "linalg rref" "pencil" "ctrb" "obsv" "tf"
      "critical --param v --from 0 --to 10" "sweep --param v --from 0 --to 10 --points 20"
      "jordan --symbolic" "scb --symbolic" "mnf --symbolic" "zeros --symbolic" "tf --symbolic"
      "minreal --symbolic" "bifurcations --symbolic")
fail=0
for f in "$out"/case*; do
  for c in "${cmds[@]}"; do
    # shellcheck disable=SC2086
    # under a 4 GB address-space limit (issue 22): past it, one line and exit 2, never 134
    (ulimit -v 4194304; exec timeout 30 "$bin" $c "$f" --max-seconds 10) >/dev/null 2>"$out/err"
    code=$?
    lines=$(wc -l <"$out/err")
    if [ $code -eq 124 ] || [ $code -ge 100 ] || [ $code -eq 1 ] || grep -q panicked "$out/err" \
       || { [ $code -eq 2 ] && [ "$lines" -ne 1 ]; }; then
      echo "FAIL exit $code: $c $f: $(head -c 300 "$out/err")"
      cp "$f" "$out/failures/"
      fail=$((fail + 1))
    fi
  done
done
echo "fuzz.sh: $cases cases, seed $seed, $fail failures"
[ $fail -eq 0 ]
