// `dsr figures`: the tutorial's raster figures (4, 6, 8, 9, 10, 11) from the default scene,
// each a plain PNG; docs/figures.md sets them beside the captions.
#include <stdlib.h>

#include <sys/stat.h>

#include <cstdio>
#include <filesystem>
#include <functional>

#include "app/command_table.h"
#include "app/commands.h"
#include "dsr_error.h"
#include "app/files.h"
#include "app/stage.h"
#include "deferred/deferred_shader.h"
#include "gl/caps.h"
#include "gl/readback.h"
#include "platform/context.h"
#include "platform/resources.h"
#include "scene/generated_model.h"
#include "scene/scene.h"
#include "scene/user_file.h"

namespace dsr {

namespace {

// A square close-up, magnified with nearest neighbour so single pixels (and aliasing)
// stay visible. (x0, y0) is the top-left corner in top-down pixel coordinates.
Image closeup(const Image& src, int x0, int y0, int size, int zoom) {
    Image out;
    out.width = out.height = size * zoom;
    out.rgba.resize(size_t(out.width) * out.height * 4);
    for (int y = 0; y < out.height; ++y)
        for (int x = 0; x < out.width; ++x) {
            int sx = x0 + x / zoom;
            int sy = src.height - 1 - (y0 + (out.height - 1 - y) / zoom);  // rows are bottom-first
            const float* p = src.at(sx, sy);
            float* q = out.at(x, y);
            for (int c = 0; c < 4; ++c) q[c] = p[c];
        }
    return out;
}

// What every figure group shares: the GL, the size, the outputs written together at the end.
struct FigureRun {
    const Caps& caps;
    int n;
    std::string shaders, dir;
    OutputSet& outputs;

    void save(const std::string& name, const Image& img) { outputs.put_image("-o", dir + "/" + name, opaque(img)); }
    Image view(DeferredShader& ds, const Scene& scene, View v) {
        ds.draw_view(v, scene.camera, n, n);
        return read_pixels(n, n);
    }
    // One shader per configuration, one frame of the scene; `then` reads what it needs after it.
    void frame(const ShaderOptions& o, const Scene& scene, const std::function<void(DeferredShader&)>& then) {
        DeferredShader ds(caps, n, n, o, shaders);
        ds.set_scene(scene);
        ds.render(scene, n, n);
        then(ds);
    }
    // One frame, its final image saved.
    void final_image(const ShaderOptions& o, const Scene& scene, const std::string& name) {
        frame(o, scene, [&](DeferredShader& ds) { save(name, view(ds, scene, View::final)); });
    }
};

// The tutorial's figures with the tutorial's light pass: one scissored quad per light (§3.4.2).
ShaderOptions tutorial_options() {
    ShaderOptions plain;
    plain.light_geometry = LightGeometry::quad;
    return plain;
}

// Figures 4, 6, 8, 9, 10 and 11, and the SSAO and shadow figures' image without them.
void tutorial_figures(FigureRun& run, const Scene& scene, bool default_scene) {
    const int n = run.n;
    const int cx = n * 300 / 512, cy = n * 220 / 512, cs = n / 4;  // close-up: the red ball's rim on the floor
    const auto view = [&](DeferredShader& ds, View v) { return run.view(ds, scene, v); };
    const ShaderOptions plain = tutorial_options();
    ShaderOptions packed = plain;
    packed.depth = DepthPath::packed;
    run.frame(packed, scene, [&](DeferredShader& ds) {  // Figure 4: the G-buffer of the packed path
        run.save("fig4a_normal.png", view(ds, View::normal));
        run.save("fig4b_diffuse.png", view(ds, View::diffuse));
        run.save("fig4c_specular.png", view(ds, View::specular));
        run.save("fig4d_depth.png", view(ds, View::depth));
    });
    ShaderOptions full = plain;
    full.post.bloom = full.post.aa = true;
    run.final_image(full, scene, "fig6_final.png");
    ShaderOptions aa = plain;
    aa.post.aa = true;
    run.frame(aa, scene, [&](DeferredShader& ds) {
        Image f = view(ds, View::final);
        Image b = view(ds, View::blur_factor);
        run.save("fig8_blur_factor.png", b);
        run.save("fig8_blur_factor_closeup.png", closeup(b, cx, cy, cs, 4));
        run.save("fig9_closeup_with_aa.png", closeup(f, cx, cy, cs, 4));
    });
    run.frame(plain, scene, [&](DeferredShader& ds) {
        Image f = view(ds, View::final);
        run.save("fig9_closeup_without_aa.png", closeup(f, cx, cy, cs, 4));
        run.save("fig11_without_bloom.png", f);
        run.save("ssao_without.png", f);
        if (default_scene) run.save("shadows_without.png", f);
    });
    ShaderOptions bloom = plain;
    bloom.post.bloom = true;
    run.frame(bloom, scene, [&](DeferredShader& ds) {
        run.save("fig11_with_bloom.png", view(ds, View::final));
        // Figure 10 step by step on the un-bloomed lighting result.
        FrameStats st;
        ds.geometry_stage(scene);
        ds.draw_lights(scene, true, st);
        ds.blur(0, 2, {1, 0}, true);
        run.save("fig10a_horizontal_blur.png", ds.read_pbuffer(2));
        ds.blur(0, 3, {0, 1}, true);
        run.save("fig10b_vertical_blur.png", ds.read_pbuffer(3));
        ds.blur(2, 3, {0, 1}, false);
        run.save("fig10c_composed_blur.png", ds.read_pbuffer(3));
    });
    // SSAO (docs/ssao.md, Vasilovici §5): the default options, the image with and without and the
    // blurred AO buffer the ambient pass (Listing 15, Eq. 6) is multiplied by; without it the
    // image is fig11_without_bloom, saved again as ssao_without beside them.
    ShaderOptions ssao = plain;
    ssao.ssao.on = true;
    run.frame(ssao, scene, [&](DeferredShader& ds) {
        run.save("ssao_with.png", view(ds, View::final));
        run.save("ssao_buffer.png", view(ds, View::ssao));
    });
}

// Shadows (docs/shadows.md): the default scene with `shadow` on each of its three point lights
// (six faces each, the default map size, bias, slope and filter), beside the scene as it is
// (shadows_without, saved with the tutorial's figures), and the first light's map as
// --view shadow-map shows it.
void shadow_figures(FigureRun& run, const Scene& scene) {
    Scene shadowed = scene;
    for (Light& l : shadowed.lights) l.shadow.on = true;
    ShaderOptions o = tutorial_options();
    o.shadow_lights = true;  // as RenderOptions::resolved sets it for a scene with `shadow`
    run.frame(o, shadowed, [&](DeferredShader& ds) {
        run.save("shadows_with.png", run.view(ds, shadowed, View::final));
        run.save("shadows_map.png", run.view(ds, shadowed, View::shadow_map));
    });
}

// Transparency (docs/forward.md, the tutorial's §4 answer to its "major limitation"): the panes and
// the glass ball are left out of the G-buffer (its diffuse view shows the wall through them)
// and blended after the lights by the forward stage, with --show-lights markers that bloom
// makes glow (its own scene file is fixed).
void transparency_figures(FigureRun& run) {
    const Scene ts = load_scene(resource_dir("data") + "/transparency.scene");
    add_scene_inputs(run.outputs, ts.inputs);
    ShaderOptions o = tutorial_options();
    o.post.bloom = o.post.aa = true;  // the scene's `post bloom aa`
    o.show_lights = true;
    run.frame(o, ts, [&](DeferredShader& ds) {
        run.save("transparency_final.png", run.view(ds, ts, View::final));
        run.save("transparency_diffuse.png", run.view(ds, ts, View::diffuse));
    });
}

// Beside Figure 6, a real model through the OBJ loader: the windmill `dsr gen-model` writes
// (scene/generated_model.h: OBJ + MTL, map_Kd, tangent-space normal maps, map_Ks and map_Ns
// specular maps), generated into a temporary folder and framed as `dsr render windmill.obj`
// frames it (scene/framing.h).
void windmill_figures(FigureRun& run) {
    std::string tmpl = (std::filesystem::temp_directory_path() / "dsr-figures-XXXXXX").string();
    if (!mkdtemp(tmpl.data())) throw Error("figures: cannot make a temporary folder " + tmpl);
    Scene wm;
    try {
        wm = load_scene(write_model(windmill_model(), tmpl));
    } catch (...) {
        std::filesystem::remove_all(tmpl);
        throw;
    }
    std::filesystem::remove_all(tmpl);  // the maps are in memory now
    ShaderOptions o = tutorial_options();
    o.post.aa = true;
    run.frame(o, wm, [&](DeferredShader& ds) {
        run.save("windmill_final.png", run.view(ds, wm, View::final));
        run.save("windmill_normal.png", run.view(ds, wm, View::normal));
        run.save("windmill_specular.png", run.view(ds, wm, View::specular));
    });
}

// Models nobody here wrote (docs/models.md): a glTF and a textured OBJ of Debian's
// assimp-testmodels, framed and lit as `dsr render FILE` shows them (the key light's shadow
// on). Read in place from the package.
void model_figures(FigureRun& run) {
    const std::string corpus = "/usr/share/assimp/models";
    const struct {
        const char* file;
        const char* out;
    } models[] = {{"glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb", "model_engine.png"},
                  {"OBJ/spider.obj", "model_spider.png"}};
    for (const auto& m : models) {
        const std::string path = corpus + "/" + m.file;
        if (!std::filesystem::is_regular_file(path)) {
            std::printf("figures: %s left out: %s is absent (make deps installs assimp-testmodels)\n", m.out, path.c_str());
            continue;
        }
        const Scene ms = load_scene(path);
        add_scene_inputs(run.outputs, ms.inputs);
        RenderOptions ro;
        ShaderOptions o = ro.resolved(ms);  // the model's shadow light on
        o.light_geometry = tutorial_options().light_geometry;
        o.post.aa = true;
        run.final_image(o, ms, m.out);
    }
}

// Light beyond 1.0 (docs/hdr.md): the default scene with its lights x4, with the tutorial's RGBA8
// P-buffer 0 (sums clip at 1) and in half floats with each operator of the final stage; last, the
// linear pipeline whole (sRGB colour maps decoded, ACES, sRGB output).
void hdr_figures(FigureRun& run, const Scene& scene) {
    Scene bright = scene;
    for (Light& l : bright.lights) l.color *= 4.0f;
    struct HdrFigure {
        const char* file;
        AccumFormat accum;
        ToneMap tonemap;
        bool srgb;
    };
    const HdrFigure figures[] = {{"hdr_rgba8.png", AccumFormat::rgba8, ToneMap::none, false},
                                 {"hdr_half_none.png", AccumFormat::half, ToneMap::none, false},
                                 {"hdr_half_reinhard.png", AccumFormat::half, ToneMap::reinhard, false},
                                 {"hdr_half_aces.png", AccumFormat::half, ToneMap::aces, false},
                                 {"hdr_half_aces_srgb.png", AccumFormat::half, ToneMap::aces, true}};
    for (const HdrFigure& h : figures) {
        if (!accum_format_ok(run.caps, run.caps.fbo, h.accum)) continue;  // a GL without float targets: left out
        ShaderOptions o = tutorial_options();
        o.hdr.accum = h.accum;
        o.hdr.tonemap = h.tonemap;
        o.hdr.output_srgb = o.hdr.textures_srgb = h.srgb;
        run.final_image(o, bright, h.file);
    }
}

// glTF's metallic-roughness BRDF (docs/metal_rough.md): data/metal_rough.scene's grid of spheres,
// metallic 0 to 1 across and roughness 0 to 1 down, in half floats, ACES and sRGB output (the
// linear pipeline, docs/hdr.md); where a GL has float targets.
void metal_rough_figures(FigureRun& run) {
    if (!accum_format_ok(run.caps, run.caps.fbo, AccumFormat::half)) return;
    const Scene mr = load_scene(resource_dir("data") + "/metal_rough.scene");
    add_scene_inputs(run.outputs, mr.inputs);
    RenderOptions ro;
    ShaderOptions o = ro.resolved(mr);  // the light programs' material model flag
    o.light_geometry = tutorial_options().light_geometry;
    o.hdr.accum = AccumFormat::half;
    o.hdr.tonemap = ToneMap::aces;
    o.hdr.output_srgb = true;
    run.final_image(o, mr, "metal_rough_grid.png");
}

}  // namespace

int cmd_figures(const std::vector<std::string>& argv) {
    FiguresSettings flags;  // the figures command's table (app/command_table.h)
    parse_command_line(figures_command(flags), argv);
    const std::string dir = flags.dir;
    std::string scene_path = flags.scene;
    const int n = flags.size;
    const bool default_scene = scene_path.empty();
    if (default_scene) scene_path = resource_dir("data") + "/default.scene";
    Scene scene = load_scene(scene_path);
    // Every figure to a temporary file, renamed together at the end (scene/output_set.h).
    OutputSet outputs("dsr figures");
    add_scene_inputs(outputs, scene.inputs);
    if (dir == FiguresSettings{}.dir) outputs.make_dir("-o", kOutDir);  // the default's parent
    require_folder("dsr figures", "-o", dir);
    outputs.make_dir("-o", dir);
    const Stage stage("rendering the figures of " + scene_path);
    auto ctx = create_context(context_desc(flags.context, n, n));
    const Caps caps = probe_caps();
    FigureRun run{caps, n, resource_dir("glsl120"), dir, outputs};
    tutorial_figures(run, scene, default_scene);
    // The figures beyond the tutorial's: only with the default scene (their pages show it).
    if (default_scene) {
        shadow_figures(run, scene);
        transparency_figures(run);
        windmill_figures(run);
        model_figures(run);
        hdr_figures(run, scene);
        metal_rough_figures(run);
    }
    outputs.commit();
    for (auto& w : outputs.written()) std::printf("wrote %s\n", w.c_str());
    return 0;
}

}  // namespace dsr
