#!/bin/bash
# Diagnostic (docs/gpu.md, "How to run it"; its output: docs/gpu/run6/): the tiles shader's variants on the GPU, speed only (some
# give wrong images, to price a part): base; noquant (QUANTIZE_8BIT off); constidx (slots 0 and 1
# in place of the decoded ones; beware: those two lights reach few pixels, so it skips lighting
# rather than pricing the fetch); notests (the in-shader light tests
# off). Each variant is a copy of the binary beside an edited glsl120/. Run on the device after
# `tests/gpu_bench.sh run` built .gpu/build/dsr:  tests/gpu_tiles_variants.sh OUTDIR
# (VARIANTS, SCENES pick; DSR0, SIZE, CTX=osmesa, SRC=. run it here on llvmpipe). Writes --stats JSONs.
set -u
out=$1; mkdir -p $out
dsr0=${DSR0:-$PWD/.gpu/build/dsr}; size=${SIZE:-1920x1080}; ctx=${CTX:-egl}; src=${SRC:-.gpu/src}
mk() {  # mk NAME SED-EXPR: a copy of the binary beside a variant glsl120
    local d=/tmp/var_$1; rm -rf $d; mkdir -p $d/build; cp $dsr0 $d/build/dsr
    cp -r $src/glsl120 $d/glsl120; ln -s $PWD/$src/data $d/data
    [ -n "$2" ] && sed -i "$2" $d/glsl120/light_tiles.frag
    echo $d/build/dsr
}
declare -A V
V[base]=$(mk base "")
V[noquant]=$(mk noquant 's/^#ifdef QUANTIZE_8BIT$/#if 0/')
V[constidx]=$(mk constidx 's/shade(int(hi),/shade(0,/; s/shade(int(lo),/shade(1,/')
V[notests]=$(mk notests 's/^#ifdef LIGHT_SPHERE_TEST$/#if 0/; s/^#ifdef LIGHT_DEPTH_TEST$/#if 0/')
for rep in 1 2; do
for v in ${VARIANTS:-base noquant constidx notests}; do
  for l in ${SCENES:-1024-overlap 32-large}; do
    for opt in "d:" "t32l8:--tile-size 32 --tile-lights 8"; do
      ${V[$v]} render --context $ctx --size $size --no-bloom --no-aa --lights $l --light-geometry tiles ${opt#*:} \
        --frames 30 --stats $out/s.json -o $out/i.png > /dev/null 2>&1 || echo "FAIL $v $l $opt"
      cp $out/s.json $out/s_${rep}_${v}_${l}_${opt%%:*}.json
    done
  done
done
for l in 1024-overlap 32-large; do
  $dsr0 render --context $ctx --size $size --no-bloom --no-aa --lights $l --frames 30 --stats $out/q.json -o $out/q.png > /dev/null 2>&1
  cp $out/q.json $out/q_${rep}_${l}.json
done
done
