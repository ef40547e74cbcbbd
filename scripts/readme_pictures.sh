#!/usr/bin/env bash
# Makes the small pictures README.md and docs/ show (docs/pictures/): seed 000's part.png and its front
# and section views, four frames of its cut.mp4, its report.html as Chromium shows it, and
# check's deviation.png for seed 001's wrong taper. Each is lathesim's own output, scaled down
# and reduced to a palette so that it stays a few tens of KB. Needs build/lathesim
# (scripts/setup.sh), ffmpeg and chromium.
set -euo pipefail
cd "$(dirname "$0")/.."
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
docs=docs/pictures
mkdir -p "$docs"

# A PNG of at most WIDTH pixels across in at most 96 colours.
small() {  # small INPUT WIDTH OUTPUT [filters before scaling]
  ffmpeg -v error -y -i "$1" -frames:v 1 -vf "${4:+$4,}scale='min($2,iw)':-2:flags=lanczos,split[a][b];[a]palettegen=max_colors=96:stats_mode=full[p];[b][p]paletteuse=dither=none" "$3"
}

seed=parts/seed000-face-taper
build/lathesim run "$seed/program.nc" --setup "$seed/setup.toml" --out "$work/seed000" --views front,section \
  --animate >/dev/null 2>&1
for view in part part-front part-section; do small "$work/seed000/$view.png" 480 "$docs/$view.png"; done
# Four frames of the video's 120: at the start, a third and two thirds of the machine time, and the end.
small "$work/seed000/cut.mp4" 640 "$docs/cut-frames.png" \
  "select='eq(n\,0)+eq(n\,40)+eq(n\,80)+eq(n\,119)',scale=400:-2,tile=2x2"
chromium --headless --no-sandbox --disable-gpu --enable-unsafe-swiftshader --hide-scrollbars \
  --user-data-dir="$work/chromium" --window-size=1200,900 --virtual-time-budget=15000 \
  --screenshot="$work/report.png" "file://$work/seed000/report.html" >/dev/null 2>&1
small "$work/report.png" 600 "$docs/report-html.png"

wrong=parts/seed001-taper-r20
build/lathesim check "$wrong/program.nc" --setup "$wrong/setup.toml" --target "$wrong/drawing.toml" --tol 0.5 \
  --out "$work/seed001" >/dev/null 2>&1 || [ $? -eq 3 ]  # 3: out of tolerance, as this part is
small "$work/seed001/deviation.png" 480 "$docs/deviation.png"
ls -l "$docs"
