#!/bin/bash
# A/B of shader folders on the GPU (docs/gpu.md, "Other stages on a GPU"; docs/gpu/run10/): one dsr binary, several glsl120/ folders.
#   here:  tests/gpu_bench.sh fetch; mkdir -p .gpu/var; cp -r glsl120 .gpu/var/NAME (one per variant,
#          edited as the experiment needs; `git archive REV glsl120` gives an older one)
#   there: GPU_BENCH_PARTS=none tests/gpu_bench.sh run /tmp/b   (builds .gpu/build/dsr)
#          tests/gpu_shader_ab.sh OUTDIR   (carry .gpu)
# Each variant runs `dsr bench` at 1920x1080 (LIGHTS, FRAMES) with quad and tiles, the variants
# alternating, REPS rounds; the rows' text beside the JSON in OUTDIR, a summary on stdout.
set -u
out=$(realpath -m "${1:?usage: tests/gpu_shader_ab.sh OUTDIR}")
mkdir -p "$out"
cd "$(dirname "$0")/.."
dsr0=$PWD/.gpu/build/dsr; src=.gpu/src
for j in /usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json /usr/share/glvnd/egl_vendor.d/10_nvidia.json; do
  if [ -f "$j" ] && [ -z "${__EGL_VENDOR_LIBRARY_FILENAMES:-}" ]; then export __EGL_VENDOR_LIBRARY_FILENAMES=$j; fi
done
# The binary takes glsl120/ from beside its parent folder (platform/resources.cpp).
for v in $(ls .gpu/var); do
  d=/tmp/var_$v; rm -rf $d; mkdir -p $d/build; cp $dsr0 $d/build/dsr; cp -r .gpu/var/$v $d/glsl120; ln -s $PWD/$src/data $d/data
done
for rep in ${REPS:-1 2}; do
  for v in ${VARS:-$(ls .gpu/var)}; do
    /tmp/var_$v/build/dsr bench $src/data/default.scene --context egl --size 1920x1080 --frames ${FRAMES:-20} \
      --lights ${LIGHTS:-1024-overlap,32-large} --light-geometry quad,tiles --json $out/ab_${v}_$rep.json > $out/ab_${v}_$rep.txt 2>&1
    echo "== $v rep $rep"
    grep -E "^(default|large) .*(forward-single|deferred texture sc +[0-9]|deferred texture sc tiles)" $out/ab_${v}_$rep.txt | cut -c1-80
  done
done
