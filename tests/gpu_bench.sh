#!/bin/bash
# dsr on a real GPU (docs/gpu.md). Two steps, because the GPU machine has no network, no GL
# headers and no OpenImageIO:
#
#   tests/gpu_bench.sh fetch [REV [DIR]]  here: the Debian .debs the build needs into .gpu/debs and
#                                    a clean copy of REV (default HEAD) into DIR (default .gpu/src;
#                                    .gpu/ is git-ignored; about 7 MB in all)
#   tests/gpu_bench.sh run OUTDIR    there (carry .gpu): unpack the GL loaders into / and the
#                                    headers into .gpu/root, build dsr with the EGL backend only
#                                    and the libpng image backend, then run info, renders and the
#                                    GPU bench, writing every result into OUTDIR
#                                    (GPU_BENCH_SMOKE=1: build, info and one small render only;
#                                    GPU_BENCH_SRC, GPU_BENCH_BUILD: the source copy and the build
#                                    folder, default .gpu/src and .gpu/build;
#                                    GPU_BENCH_SIZES, _FRAMES, _LIGHTS: the bench's sweep;
#                                    GPU_BENCH_PARTS: some of renders geometry targets ssao
#                                    forward tiles auto goals groups fold shadows hdr material skips bench, default
#                                    all; GPU_BENCH_ROUNDS: goals' alternations)
#
# The build links the system's libEGL/libOpenGL (glvnd, the NVIDIA driver behind them), never
# libOSMesa; it is the same renderer objects as the headless build.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
step=${1:-}

case "$step" in
fetch)
    rev=${2:-HEAD}
    dest=${3:-.gpu/src}
    mkdir -p .gpu/debs
    (cd .gpu/debs && apt-get download libgl-dev libegl-dev libglx-dev libpng-dev libglm-dev nlohmann-json3-dev \
        libtinyobjloader-dev libtinyobjloader2rc10 libtinygltf-dev zlib1g-dev libegl1 libglvnd0 libopengl0 libgl1 libglx0)
    rm -rf "$dest" && mkdir -p "$dest"
    git archive "$rev" | tar -x -C "$dest"
    rm -rf "$dest/docs"  # the run needs src, glsl120, data and tests only; docs/gpu's logs are large
    git rev-parse "$rev" > "$dest/REVISION"
    du -sh .gpu
    ;;
run)
    out=${2:?usage: tests/gpu_bench.sh run OUTDIR}
    mkdir -p "$out"
    log="$out/gpu_log.txt"
    exec > >(tee "$log") 2>&1
    # GL loaders (glvnd) into /, as the device notes say; headers and link-time files apart.
    for f in .gpu/debs/libegl1_*.deb .gpu/debs/libglvnd0_*.deb .gpu/debs/libopengl0_*.deb \
             .gpu/debs/libgl1_*.deb .gpu/debs/libglx0_*.deb; do dpkg -x "$f" /; done
    ldconfig
    sys=.gpu/root
    rm -rf $sys && mkdir -p $sys
    for f in .gpu/debs/*.deb; do dpkg -x "$f" $sys; done
    src=${GPU_BENCH_SRC:-.gpu/src}  # another fetched copy (e.g. a baseline revision) to build and run
    echo "gpu_bench: source $(cat $src/REVISION 2>/dev/null || echo 'working tree')"
    nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv,noheader || true
    lib=/usr/lib/x86_64-linux-gnu
    # EGL vendor file of the NVIDIA driver where the loader does not find it by itself.
    for j in /usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json /usr/share/glvnd/egl_vendor.d/10_nvidia.json; do
        if [ -f "$j" ] && [ -z "${__EGL_VENDOR_LIBRARY_FILENAMES:-}" ]; then export __EGL_VENDOR_LIBRARY_FILENAMES=$j; fi
    done
    build=$root/${GPU_BENCH_BUILD:-.gpu/build}
    mkdir -p $build/obj
    # A response file, so the quoted DSR_SOURCE_DIR survives xargs and sh.
    flags=$build/flags
    printf '%s\n' -std=c++17 -O2 -g -Wall -Wno-unused-parameter "-I$root/$src/src" "-isystem" "$root/$sys/usr/include" \
        -DDSR_NO_OSMESA "-DDSR_SOURCE_DIR=\\\"$root/$src\\\"" > $flags
    sources=$(cd $src && ls src/gl/*.cpp src/scene/*.cpp src/deferred/*.cpp src/forward/*.cpp src/analysis/*.cpp \
              src/platform/*.cpp src/app/*.cpp | grep -v -e osmesa_context -e 'image_io\.cpp' -e glfw_ -e 'app/viewer_')
    t0=$(date +%s)
    echo "$sources" | xargs -P "$(nproc)" -I{} sh -c \
        'mkdir -p "$(dirname '"$build"'/obj/{})" && g++ @'"$flags"' -c '"$root/$src"'/{} -o '"$build"'/obj/{}.o'
    objs=$(echo "$sources" | sed "s|^|$build/obj/|; s|\$|.o|")
    tol=$root/$sys/usr/lib/x86_64-linux-gnu
    g++ -o $build/dsr $objs -L$tol -Wl,-rpath,$tol -ltinyobjloader $lib/libEGL.so.1 $lib/libOpenGL.so.0 \
        -l:libpng16.so.16 -pthread
    echo "gpu_bench: built in $(( $(date +%s) - t0 )) s: $(ls -la $build/dsr)"
    dsr=$build/dsr
    # The binary finds glsl120/ and data/ beside its parent folder or in DSR_SOURCE_DIR.
    $dsr info --context egl | tee "$out/info.txt"
    # GPU_BENCH_PARTS picks sections (the device time is short): part NAME is true for each.
    part() { [[ " ${GPU_BENCH_PARTS:-all} " == *" all "* || " ${GPU_BENCH_PARTS:-all} " == *" $1 "* ]]; }
    if [ -n "${GPU_BENCH_SMOKE:-}" ]; then  # a check of the build on a machine without a GPU
        $dsr render --context egl --size 160x120 -o "$out/smoke.png"
        exit 0
    fi
    if part renders; then
    for s in 1920x1080 3840x2160; do
        $dsr render --context egl --size $s --no-bloom --no-aa --frames 60 --stats "$out/render_$s.json" \
            -o "$out/default_$s.png"
    done
    $dsr render --context egl --size 1920x1080 --frames 60 --stats "$out/render_post_1920x1080.json" \
        -o "$out/default_post_1920x1080.png"
    $dsr render --context egl --size 512x512 --no-bloom --no-aa -o "$out/default_512.png"
    fi
    if part geometry; then
    [ -f "$out/default_1920x1080.png" ] || $dsr render --context egl --size 1920x1080 --no-bloom --no-aa \
        -o "$out/default_1920x1080.png"
    # Light geometries (docs/light_geometry.md) and the depth-bounds test on the default scene at 1080p, each
    # image against quad's (the 1920x1080 render above).
    for g in volume stencil tiles; do
        $dsr render --context egl --size 1920x1080 --no-bloom --no-aa --light-geometry $g --frames 60 \
            --stats "$out/geometry_$g.json" -o "$out/geometry_$g.png"
        echo "geometry $g vs quad: $($dsr compare "$out/default_1920x1080.png" "$out/geometry_$g.png" 2>&1 | tail -1)" \
            | tee -a "$out/geometry_compare.txt"
    done
    # tiles at one light per pass and the general (any light type) shader is what quad's light_any
    # program computes: where it differs from quad the blending differs, not the shading.
    $dsr render --context egl --size 1920x1080 --no-bloom --no-aa --light-geometry tiles --tile-lights 1 \
        --frames 20 --stats "$out/geometry_tiles1.json" -o "$out/geometry_tiles1.png"
    echo "geometry tiles (1 light a pass) vs quad: $($dsr compare "$out/default_1920x1080.png" "$out/geometry_tiles1.png" 2>&1 | tail -1)" \
        | tee -a "$out/geometry_compare.txt"
    fi
    # The tutorial's P-buffers as EGL pbuffer surfaces, and the copy path, against fbo.
    if part targets; then
    for rt in pbuffer copy; do
        for extra in "--no-bloom --no-aa" ""; do
            tag=$rt${extra:+_nopost}
            $dsr render --context egl --size 1920x1080 $extra --render-target $rt --frames 30 \
                --stats "$out/target_$tag.json" -o "$out/target_$tag.png"
            ref="$out/default_post_1920x1080.png"; [ -n "$extra" ] && ref="$out/default_1920x1080.png"
            echo "render-target $tag vs fbo: $($dsr compare "$ref" "$out/target_$tag.png" 2>&1 | tail -1)" \
                | tee -a "$out/geometry_compare.txt"
        done
    done
    if $dsr render --context egl --size 1920x1080 --no-bloom --no-aa --depth-bounds on --frames 60 \
        --stats "$out/depth_bounds.json" -o "$out/depth_bounds.png"; then
        echo "depth-bounds on vs off: $($dsr compare "$out/default_1920x1080.png" "$out/depth_bounds.png" 2>&1 | tail -1)" \
            | tee -a "$out/geometry_compare.txt"
    fi
    fi
    # The ambient pass folded into a full-screen light's pass (docs/guide.md), in each of its
    # three forms, against the ambient pass drawn (same bytes on llvmpipe; the brief allows 1 LSB):
    # a directional light; point lights of the linear law with the scissors off; LearnOpenGL's
    # lights (the attenuation law) with the scissors off. The material pass's ambient target is off
    # in both renders, else nothing folds. ambient_folded in each stats file says which did.
    if part fold; then
    for v in "directional:$src/data/lights.scene" "linear:$src/data/default.scene --scissor off" \
             "attenuation:$src/data/default.scene --lights 32-large --scissor off"; do
        for s in "fold:ambient-target" "pass:ambient-target,ambient"; do
            $dsr render ${v#*:} --context egl --size 1920x1080 --no-bloom --no-aa --light-geometry quad \
                --no-skip ${s#*:} --frames 30 --stats "$out/fold_${v%%:*}_${s%%:*}.json" -o "$out/fold_${v%%:*}_${s%%:*}.png"
        done
        echo "fold ${v%%:*}, folded vs ambient pass: $($dsr compare "$out/fold_${v%%:*}_pass.png" \
            "$out/fold_${v%%:*}_fold.png" 2>&1 | tail -1)" | tee -a "$out/fold_compare.txt"
    done
    fi
    # SSAO's cost on the GPU (docs/ssao.md), full and half resolution.
    if part ssao; then
    for sc in 1 2; do
        $dsr render --context egl --size 1920x1080 --ssao --ssao-scale $sc --frames 30 \
            --stats "$out/ssao_scale$sc.json" -o "$out/ssao_scale$sc.png"
    done
    fi
    # The forward stage: the depth hand-off by blit and by pass on both depth paths,
    # markers and the transparency figure's scene (docs/forward.md).
    if part forward; then
    FORWARD_FLAGS="--context egl" FORWARD_SIZES="1920x1080 3840x2160" FORWARD_FRAMES=30 \
        $src/tests/forward_measure.sh $dsr "$out/forward" | tee "$out/forward.md"
    fi
    # tiles against quad alone (GPU_BENCH_TILES_LIGHTS), the image difference in the bench's
    # max_lsb_vs_quad column: is the in-shader sum of several lights the blend's sum here?
    if part tiles; then
        $dsr bench $src/data/default.scene --context egl --size 1920x1080 --frames ${GPU_BENCH_FRAMES:-30} \
            --lights ${GPU_BENCH_TILES_LIGHTS:-own,1024,1024-overlap,32-large} --light-geometry quad,volume,stencil,tiles,screen \
            --json "$out/gpu_bench_tiles_1920x1080.json" --report "$out/gpu_bench_tiles_1920x1080.md" \
            | tee "$out/gpu_bench_tiles_1920x1080.txt"
        # Per stage, and where the tiles' CPU time goes: the depth spans' read-back (a pipeline
        # drain) and the plan (--stats tiles.depth_ms, plan_ms on the wall clock; tiles.cpu_ms:
        # spans, wait, cull, plan, upload; tiles.wait_ms).
        for l in own 1024-overlap 32-large; do
            for g in quad volume tiles; do
                $dsr render --context egl --size 1920x1080 --no-bloom --no-aa --lights $l --light-geometry $g \
                    --frames 30 --stats "$out/stats_${l}_$g.json" -o "$out/render_${l}_$g.png"
            done
        done
        # The spans' wait: slept through while an occlusion query's result is polled (as built),
        # against glFinish (--caps no-occlusion-query), alternated, tiles.cpu_ms.wait and ms.cpu.
        for r in $(seq ${GPU_BENCH_ROUNDS:-3}); do
            for l in 32-large 1024-overlap 4096; do
                for v in "poll:" "finish:--caps no-occlusion-query"; do
                    $dsr render --context egl --size 1920x1080 --no-bloom --no-aa --lights $l --light-geometry tiles \
                        ${v#*:} --frames 30 --stats "$out/wait_${l}_${v%%:*}_$r.json" -o "$out/wait_${l}_${v%%:*}.png"
                done
            done
        done
        # The tiles' depth culling reads each tile's depth span back to the CPU: what that stall
        # costs a GPU, against the same bench without it; and 32-pixel tiles with 8 lights a pass.
        # GPU_BENCH_TILES_VARIANTS: some of nodepth t32l8 t32l8nodepth (default all), or none.
        for v in "nodepth:--tile-depth off" "t32l8:--tile-size 32 --tile-lights 8" \
                 "t32l8nodepth:--tile-size 32 --tile-lights 8 --tile-depth off"; do
            [[ " ${GPU_BENCH_TILES_VARIANTS:-nodepth t32l8 t32l8nodepth} " == *" ${v%%:*} "* ]] || continue
            $dsr bench $src/data/default.scene --context egl --size 1920x1080 --frames ${GPU_BENCH_FRAMES:-30} \
                --lights 1024-overlap,32-large --light-geometry quad,tiles ${v#*:} \
                --json "$out/gpu_bench_tiles_${v%%:*}_1920x1080.json" \
                --report "$out/gpu_bench_tiles_${v%%:*}_1920x1080.md" > "$out/gpu_bench_tiles_${v%%:*}_1920x1080.txt"
        done
    fi
    # auto (the default) against every fixed geometry and LearnOpenGL's algorithm (screen) in one
    # run, with each path's share and the model's prediction per frame (--stats auto), and the
    # demo's own 800x600 for the goal measured on it.
    if part auto; then
        $dsr bench $src/data/default.scene --context egl --size 1920x1080 --frames ${GPU_BENCH_FRAMES:-30} \
            --lights ${GPU_BENCH_AUTO_LIGHTS:-own,256,1024,4096,1024-overlap,32-large} \
            --light-geometry auto,quad,volume,tiles,screen \
            --json "$out/gpu_bench_auto_1920x1080.json" --report "$out/gpu_bench_auto_1920x1080.md" \
            | tee "$out/gpu_bench_auto_1920x1080.txt"
        $dsr bench $src/data/default.scene --context egl --frames ${GPU_BENCH_FRAMES:-30} --lights 32-large \
            --light-geometry auto,quad,volume,tiles,screen --json "$out/gpu_bench_auto_large.json" \
            --report "$out/gpu_bench_auto_large.md" | tee "$out/gpu_bench_auto_large.txt"
        for l in own 1024 4096 1024-overlap 32-large; do
            for sc in "1,1,1" "1,1000,1000" "1000,1,1000" "1000,1000,1"; do
                $dsr render --light-cost-scale $sc --context egl --size 1920x1080 --no-bloom --no-aa --lights $l \
                    --frames 30 --stats "$out/auto_${l}_${sc//,/_}.json" -o "$out/auto_${l}.png"
            done
        done
    fi
    # The goals of docs/gpu.md in one place: LearnOpenGL's demo with its light boxes (--show-lights)
    # as a user times it, dsr's default against `--light-geometry screen`, plain renders alternated
    # (GPU_BENCH_ROUNDS times each, 30 frames, ms.frame in each --stats file), at 1920x1080 and the
    # demo's 800x600; then the CPU of every bench scene by geometry (ms.cpu, tiles' steps).
    if part goals; then
        mkdir -p "$out/goals"
        for s in 1920x1080 800x600; do
            for r in $(seq ${GPU_BENCH_ROUNDS:-3}); do
                for g in auto screen; do
                    $dsr render $src/data/default.scene --context egl --size $s --no-bloom --no-aa --lights 32-large \
                        --show-lights --light-geometry $g --frames 30 --stats "$out/goals/demo_${s}_${g}_$r.json" \
                        -o "$out/goals/demo_${s}_$g.png"
                done
            done
            echo "demo $s, auto vs screen: $($dsr compare "$out/goals/demo_${s}_screen.png" "$out/goals/demo_${s}_auto.png" 2>&1 | tail -1)" \
                | tee -a "$out/goals/compare.txt"
        done
        for l in own 256 1024 4096 1024-overlap 32-large; do
            for g in auto quad volume tiles; do
                $dsr render $src/data/default.scene --context egl --size 1920x1080 --no-bloom --no-aa --lights $l \
                    --light-geometry $g --frames 30 --stats "$out/goals/cpu_${l}_$g.json" -o "$out/goals/cpu_${l}_$g.png"
            done
        done
    fi
    # The tiles geometry's other plan (groups), against quad in the same run.
    if part groups; then
        $dsr bench $src/data/default.scene --context egl --size 1920x1080 --frames ${GPU_BENCH_FRAMES:-50} \
            --lights ${GPU_BENCH_GROUP_LIGHTS:-own,1024,4096,1024-overlap,32-large} --light-geometry quad,tiles \
            --tile-plan groups --json "$out/gpu_bench_groups_1920x1080.json" \
            --report "$out/gpu_bench_groups_1920x1080.md" > "$out/gpu_bench_groups_1920x1080.txt"
    fi
    # Shadow maps (docs/shadows.md): 1, 8 and 32 shadowed spot lights and the default scene's
    # lights as shadowed point lights, each against the same lights unshadowed (--shadows off),
    # with every map drawn every frame (--shadow-reuse off: the stage's cost) and kept (on: a still
    # frame); both map formats on the 8 spots; and the bench's rows with their error columns.
    if part shadows; then
        for l in 1-shadow 8-shadow 32-shadow own-shadow; do
            for v in "on:--shadows on --shadow-reuse off" "reuse:--shadows on" "off:--shadows off"; do
                $dsr render $src/data/default.scene --context egl --size 1920x1080 --no-bloom --no-aa --lights $l \
                    ${v#*:} --frames 30 --stats "$out/shadows_${l}_${v%%:*}.json" -o "$out/shadows_${l}_${v%%:*}.png"
            done
        done
        $dsr render $src/data/default.scene --context egl --size 1920x1080 --no-bloom --no-aa --lights 8-shadow \
            --shadow-reuse off --caps no-depth-texture --frames 30 --stats "$out/shadows_8-shadow_packed.json" \
            -o "$out/shadows_8-shadow_packed.png"
        echo "8-shadow, depth texture vs packed maps: $($dsr compare "$out/shadows_8-shadow_on.png" \
            "$out/shadows_8-shadow_packed.png" 2>&1 | tail -1)" | tee "$out/shadows_compare.txt"
        $dsr bench $src/data/default.scene --context egl --size 1920x1080 --frames ${GPU_BENCH_FRAMES:-30} \
            --lights 1-shadow,8-shadow,32-shadow,own-shadow --light-geometry auto,quad \
            --json "$out/gpu_bench_shadows_1920x1080.json" --report "$out/gpu_bench_shadows_1920x1080.md" \
            | tee "$out/gpu_bench_shadows_1920x1080.txt"
    fi
    # Light beyond 1.0 (docs/hdr.md): clipped pixels and frame ms per accumulation format and
    # operator; the default scene x4 in each format at 1920x1080; `info`'s float blending lines.
    if part hdr; then
    $dsr info --context egl | grep -E "blending|--accum|sRGB" | tee "$out/hdr_info.txt"
    $dsr hdr --context egl --size 1024 --frames ${GPU_BENCH_FRAMES:-50} | tee "$out/hdr.md"
    for a in rgba8 half float; do
        $dsr render --context egl --size 1920x1080 --no-bloom --no-aa --accum $a --frames 60 \
            --stats "$out/hdr_accum_$a.json" -o "$out/hdr_accum_$a.png"
    done
    fi
    # The metallic-roughness light shader against Phong's (docs/metal_rough.md, "Measured"): the
    # bench's metal-rough rows beside the default quad rows, on the same pixel-light pairs in the
    # same rounds; the ratio in the "Material model" line and the report's section of that name.
    if part material; then
        $dsr bench $src/data/default.scene --context egl --size 1920x1080 --frames ${GPU_BENCH_FRAMES:-30} \
            --lights ${GPU_BENCH_MATERIAL_LIGHTS:-own,256,1024} --light-geometry quad \
            --json "$out/gpu_bench_material_1920x1080.json" --report "$out/gpu_bench_material_1920x1080.md" \
            | tee "$out/gpu_bench_material_1920x1080.txt"
    fi
    # Each skip of the fixed passes (docs/gpu_frame.md, "The fixed passes"): the bench's skip rows
    # (the default configuration with quads, each skip turned off alone) on 1024 and 32-large, and
    # dsr's default frame with every skip against --no-skip gbuffer-clears, alternated
    # GPU_BENCH_ROUNDS times (ms.frame, ms.geometry in each --stats file), each pair's images
    # compared: LearnOpenGL's demo with its light boxes (32-large --show-lights) as the goals time
    # it, and 1024 lights with the boxes (a forward stage: every frame hands off) and without.
    if part skips; then
        mkdir -p "$out/skips"
        for s in 1920x1080 800x600; do
            $dsr bench $src/data/default.scene --context egl --size $s --frames ${GPU_BENCH_FRAMES:-30} \
                --lights 1024,32-large --light-geometry quad --json "$out/skips/bench_$s.json" \
                --report "$out/skips/bench_$s.md" | tee "$out/skips/bench_$s.txt"
            for v in 32-large:--show-lights 1024:--show-lights 1024:; do
                l=${v%%:*}; tag=${l}${v#*:}; tag=${tag/--show-lights/_markers}
                for r in $(seq ${GPU_BENCH_ROUNDS:-3}); do
                    for k in on off; do
                        flag=""; [ $k = off ] && flag="--no-skip gbuffer-clears"
                        $dsr render $src/data/default.scene --context egl --size $s --no-bloom --no-aa --lights $l \
                            ${v#*:} $flag --frames 30 --stats "$out/skips/render_${s}_${tag}_${k}_$r.json" \
                            -o "$out/skips/render_${s}_${tag}_$k.png"
                    done
                done
                echo "$s $l ${v#*:}: gbuffer-clears skipped vs not: $($dsr compare \
                    "$out/skips/render_${s}_${tag}_off.png" "$out/skips/render_${s}_${tag}_on.png" 2>&1 | tail -1)" \
                    | tee -a "$out/skips/compare.txt"
            done
        done
    fi
    if part bench; then
    for s in ${GPU_BENCH_SIZES:-1920x1080}; do
        $dsr bench $src/data/default.scene --context egl --size $s --frames ${GPU_BENCH_FRAMES:-50} \
            --lights ${GPU_BENCH_LIGHTS:-own,256,1024,4096} --json "$out/gpu_bench_$s.json" \
            --report "$out/gpu_bench_$s.md" | tee "$out/gpu_bench_$s.txt"
    done
    fi
    ;;
*)
    sed -n '2,16p' "$0"
    exit 2
    ;;
esac
