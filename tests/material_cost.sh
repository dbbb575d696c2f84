#!/bin/bash
# The metallic-roughness light shader against Phong's on the same spheres, lights and pixels:
# data/metal_rough.scene as it is and with every material made Phong, rendered alternately with
# the tutorial's quad loop, printing the light stage's ms per light-pixel pair (--stats: ms.lights
# over light_fragments, the pairs that passed the light's tests).
#   tests/material_cost.sh DSR WxH ROUNDS [render flags, e.g. --context egl]
set -euo pipefail
cd "$(dirname "$0")/.."
dsr=$1 size=$2 rounds=$3
shift 3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
sed -E 's/base ([0-9. ]+) metallic [0-9.]+ roughness [0-9.]+/diffuse \1 specular 0.5 0.5 0.5 shininess 32/' \
    data/metal_rough.scene > "$tmp/phong_grid.scene"
for i in $(seq 1 "$rounds"); do
    for s in data/metal_rough.scene "$tmp/phong_grid.scene"; do
        "$dsr" render "$s" "$@" --size "$size" --frames 40 --light-geometry quad --no-bloom --no-aa \
            --stats "$tmp/s.json" -o "$tmp/i.png" >/dev/null
        python3 -c "
import json, sys
j = json.load(open(sys.argv[2])); ms = j['ms']['lights']; f = j['light_fragments']
print('%-20s lights %.3f ms  pairs %d  ns/pair %.3f' % (sys.argv[1], ms, f, 1e6 * ms / f))" "$(basename "$s")" "$tmp/s.json"
    done
done
