#!/usr/bin/env bash
# Renders the seeds' examples through `--format latex --standalone` to PDF and PNG, to look
# at: pdflatex + pdftoppm (apt: texlive-latex-base texlive-latex-recommended poppler-utils).
# Usage: scripts/latex_check.sh [OUTDIR]   (default target/latex-check; builds the debug binary)
set -euo pipefail
cd "$(dirname "$0")/.."
out="${1:-target/latex-check}"
mkdir -p "$out"
for t in pdflatex pdftoppm; do
  command -v "$t" >/dev/null || { echo "latex_check: $t not installed (apt-get install texlive-latex-base texlive-latex-recommended poppler-utils)"; exit 2; }
done
cargo build --quiet --bin exactlti
bin="$PWD/target/debug/exactlti"
cases=(
  "jordan:data/sliding-masses.json"
  "jordan --real:data/sliding-masses.json"
  "minreal:data/sliding-masses.json"
  "modes:data/sliding-masses.json"
  "tf:data/sliding-masses.json"
  "scb:data/yaw-plane-single-wheel.json"
  "mnf:data/yaw-plane-single-wheel.json"
  "zeros:data/yaw-plane-single-wheel.json"
  "linalg charpoly:tests/data/gaussian.json"
  "analyze:tests/data/everyday/quarter_car.json"
)
fails=0
for c in "${cases[@]}"; do
  cmd="${c%%:*}"; file="${c#*:}"
  name="$(echo "$cmd $(basename "$file" | sed 's/\.[a-z]*$//')" | tr ' -' '__')"
  # shellcheck disable=SC2086
  "$bin" $cmd "$file" --format latex --standalone > "$out/$name.tex"
  if (cd "$out" && pdflatex -interaction=nonstopmode -halt-on-error "$name.tex" > "$name.log.txt" 2>&1); then
    pdftoppm -png -r 70 "$out/$name.pdf" "$out/$name"
    echo "ok    $name: $(ls "$out/$name"*.png | wc -l) page(s)"
  else
    echo "FAIL  $name (see $out/$name.log.txt)"; fails=$((fails + 1))
  fi
done
echo "PNG pages in $out; $fails failed"
[ "$fails" -eq 0 ]
