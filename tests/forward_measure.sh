#!/bin/bash
# The forward stage's costs (docs/forward.md): the depth hand-off by each method
# (EXT_framebuffer_blit, the gl_FragDepth pass) on each depth path, and the forward stage on the
# transparency figure's scene. Medians of FRAMES frames from `render --stats`; one markdown table
# on stdout.
#   tests/forward_measure.sh [DSR] [OUTDIR]     DSR default build/dsr; extra render flags in
#                                               FORWARD_FLAGS (e.g. "--context egl"), sizes in
#                                               FORWARD_SIZES (default 512x512 1024x1024)
set -euo pipefail
cd "$(dirname "$0")/.."
dsr=${1:-build/dsr}
out=${2:-$(mktemp -d)}
frames=${FORWARD_FRAMES:-9}
flags=${FORWARD_FLAGS:-}
mkdir -p "$out"
field() { grep -o "\"$2\": [-0-9.e]*" "$1" | head -1 | sed 's/.*: //'; }
ms() { printf '%.3f' "$(field "$1" "$2")"; }
echo "| scene | size | depth | hand-off | ms.depth_copy | ms.forward | ms.lights | ms.frame | image vs first row |"
echo "| --- | --- | --- | --- | ---: | ---: | ---: | ---: | --- |"
for size in ${FORWARD_SIZES:-512x512 1024x1024}; do
    for scene in default transparency; do
        for depth in texture packed; do
            ref=""
            for h in blit pass; do
                tag=${scene}_${size}_${depth}_$h
                # The default scene has nothing to draw forward: --show-lights makes the stage run.
                $dsr render data/$scene.scene $flags --size $size --no-bloom --no-aa --show-lights --depth $depth \
                    --depth-handoff $h --frames $frames --stats "$out/$tag.json" -o "$out/$tag.png" > /dev/null
                cmp=-
                if [ -n "$ref" ]; then cmp=$($dsr compare "$ref" "$out/$tag.png" 2>&1 | tail -1 | sed 's/|/\\|/g'); fi
                [ -z "$ref" ] && ref="$out/$tag.png"
                echo "| $scene | $size | $depth | $h | $(ms "$out/$tag.json" depth_copy) | $(ms "$out/$tag.json" forward) |" \
                     "$(ms "$out/$tag.json" lights) | $(ms "$out/$tag.json" frame) | $cmp |"
            done
        done
    done
done
