#!/bin/bash
# The old-GL matrix as a user would measure it: every combination of the four fallbacks
# (--caps), the default scene, each image compared with the all-capabilities one
# (oiiotool --diff), and the median frame time of 20 frames from --stats.
# Usage: tests/legacy_matrix.sh [WxH]   (DSR=path/to/dsr, default build/dsr)
set -euo pipefail
D=${DSR:-build/dsr}
SIZE=${1:-512x512}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
names=(no-mrt no-depth-texture no-fbo no-npot)
"$D" render --size "$SIZE" --frames 20 -o "$tmp/full.png" >/dev/null
printf "%-44s %-8s %-10s %-5s %-5s %8s %10s %9s\n" "forced off" depth gbuffer rt tex "max LSB" "mean LSB" "frame ms"
for mask in $(seq 0 15); do
  off=""
  for b in 0 1 2 3; do if (( mask & (1 << b) )); then off="$off${off:+,}${names[$b]}"; fi; done
  "$D" render --size "$SIZE" --frames 20 --caps "$off" -o "$tmp/m.png" --stats "$tmp/m.json" >/dev/null
  diff=$(oiiotool "$tmp/m.png" "$tmp/full.png" --diff 2>&1 || true)
  python3 - "$off" "$tmp/m.json" "$diff" <<'PY'
import json, sys
off, stats, diff = sys.argv[1], sys.argv[2], sys.argv[3]
j = json.load(open(stats))
def field(key):  # oiiotool prints nothing for identical images
    lines = [l for l in diff.splitlines() if key in l]
    return float(lines[0].split('=')[1].split('@')[0]) if lines else 0.0
mean = field('Mean error') * 255 * 4 / 3  # oiiotool averages RGBA; alpha is always equal
p = j['paths']
print("%-44s %-8s %-10s %-5s %-5s %8.1f %10.4f %9.2f" % (off or '(none)', p['depth'], p['gbuffer'],
      p['render_target'], p['textures'], field('Max error') * 255, mean, j['ms']['frame']))
PY
done
