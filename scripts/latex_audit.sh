#!/usr/bin/env bash
# The LaTeX audit of issue 27: every data file x every `--steps` command, rendered with
# `--steps --format latex --standalone`, compiled with pdflatex (nonstopmode, under a
# timeout), and the `Overfull \hbox` lines of each log counted, with the widest overflow.
#
# Usage: scripts/latex_audit.sh [OUTDIR] [SECONDS]
#   OUTDIR   default target/latex-audit (one .tex/.pdf/.log per document, summary.tsv)
#   SECONDS  per-command time limit of the CLI (default 300; pdflatex gets 120 s)
#   EXACTLTI=path/to/exactlti to use a given binary (default: builds the release binary)
#   ONLY=regex   only the documents whose name matches (e.g. ONLY='yaw.*ho_kalman')
#   SKIP=regex   skip the documents whose name matches
# Needs pdflatex (apt: texlive-latex-base texlive-latex-recommended).
# Output: one line per document (status, overfull count, widest in pt, CLI seconds), then a
# total line; summary.tsv holds the same. Status: ok, refused (exit 2: the command does not
# apply to the file), timeout (the CLI), texfail (pdflatex error), fails (exit 1: an identity).
set -uo pipefail
cd "$(dirname "$0")/.."
out="${1:-target/latex-audit}"
limit="${2:-300}"
mkdir -p "$out"
command -v pdflatex >/dev/null || { echo "latex_audit: pdflatex not installed"; exit 2; }
if [ -z "${EXACTLTI:-}" ]; then
  cargo build --quiet --release --bin exactlti || exit 2
  EXACTLTI="$PWD/target/release/exactlti"
fi
files=(data/*.json data/scb/*.json data/models/*.toml)
cmds=(
  "jordan"
  "jordan --real"
  "scb"
  "zeros"
  "minreal --method kalman"
  "minreal --method jordan"
  "minreal --method rosenbrock"
  "minreal --method ho-kalman"
  "minreal --descriptor"
  "standard"
  "mnf"
  "tf"
)
summary="$out/summary.tsv"
printf 'document\tstatus\toverfull\twidest_pt\tcli_s\n' > "$summary"
docs=0; bad=0; boxes=0; big=0
for f in "${files[@]}"; do
  for c in "${cmds[@]}"; do
    name="$(basename "$f" | sed 's/\.[a-z]*$//')__$(echo "$c" | sed 's/--method //; s/--//g; s/ /_/g; s/-/_/g')"
    if [ -n "${ONLY:-}" ] && ! [[ $name =~ $ONLY ]]; then continue; fi
    if [ -n "${SKIP:-}" ] && [[ $name =~ $SKIP ]]; then continue; fi
    t0=$(date +%s.%N)
    # shellcheck disable=SC2086
    timeout "$limit" "$EXACTLTI" $c "$f" --steps --format latex --standalone \
      > "$out/$name.tex" 2> "$out/$name.err"
    rc=$?
    secs=$(echo "$(date +%s.%N) - $t0" | bc)
    status=ok; n=0; widest=0
    case $rc in
      0) ;;
      1) status=fails ;;
      2) status=refused ;;
      124) status=timeout ;;
      *) status="exit$rc" ;;
    esac
    if [ "$status" = ok ] || [ "$status" = fails ]; then
      if (cd "$out" && timeout 120 pdflatex -interaction=nonstopmode "$name.tex" > /dev/null 2>&1) \
         && [ -f "$out/$name.pdf" ]; then
        n=$(grep -c '^Overfull \\hbox' "$out/$name.log")
        widest=$(grep -o '^Overfull \\hbox ([0-9.]*pt' "$out/$name.log" \
          | grep -o '[0-9.]*' | sort -g | tail -1)
        widest=${widest:-0}
        docs=$((docs + 1)); boxes=$((boxes + n))
        [ "$n" -gt 0 ] && bad=$((bad + 1))
        if [ "$(echo "$widest > 10" | bc)" = 1 ]; then big=$((big + 1)); fi
      else
        status=texfail
      fi
    fi
    printf '%-60s %-8s %4s %8s %7.1f\n' "$name" "$status" "$n" "$widest" "$secs"
    printf '%s\t%s\t%s\t%s\t%.1f\n' "$name" "$status" "$n" "$widest" "$secs" >> "$summary"
  done
done
echo "documents compiled: $docs; with overfull boxes: $bad ($boxes lines); with a box > 10pt: $big"
